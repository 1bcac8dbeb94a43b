// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarBoundary.h"
#include "vtkPRStarFilterRun.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

vtkStandardNewMacro(vtkPRStarBoundary);

vtkPRStarBoundary::vtkPRStarBoundary() {
  this->SetNumberOfOutputPorts(2);
}

vtkPRStarBoundary::~vtkPRStarBoundary() = default;

void vtkPRStarBoundary::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GenerateSurface: " << this->GenerateSurface << "\n";
}

int vtkPRStarBoundary::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector) {
  vtkPolyData* surface = vtkPolyData::GetData(outputVector, 1);
  return this->RunOnGhostedInput(
      inputVector, outputVector, true,
      [&](vtkUnstructuredGrid* grid, vtkUnstructuredGrid* output, const prstar_paraview::Options& o) {
        return prstar_paraview::boundary(grid, output, this->GenerateSurface ? surface : nullptr, o);
      });
}
