// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarCriticalPoints.h"
#include "vtkPRStarFilterRun.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

vtkStandardNewMacro(vtkPRStarCriticalPoints);

vtkPRStarCriticalPoints::vtkPRStarCriticalPoints() {
  this->SetNumberOfOutputPorts(2);
}

vtkPRStarCriticalPoints::~vtkPRStarCriticalPoints() = default;

void vtkPRStarCriticalPoints::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FieldArrayName: " << this->FieldArrayName << "\n";
}

int vtkPRStarCriticalPoints::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                         vtkInformationVector* outputVector) {
  vtkPolyData* points = vtkPolyData::GetData(outputVector, 1);
  return this->RunOnGhostedInput(
      inputVector, outputVector, true,
      [&](vtkUnstructuredGrid* grid, vtkUnstructuredGrid* output, const prstar_paraview::Options& o) {
        vtkDataArray* field = FieldArray(grid, this->FieldArrayName);
        return prstar_paraview::critical_points(grid, field, output, points, o);
      });
}
