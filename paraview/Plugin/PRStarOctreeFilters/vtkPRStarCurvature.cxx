// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarCurvature.h"
#include "vtkPRStarFilterRun.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkUnstructuredGrid.h>

vtkStandardNewMacro(vtkPRStarCurvature);

vtkPRStarCurvature::vtkPRStarCurvature() = default;
vtkPRStarCurvature::~vtkPRStarCurvature() = default;

void vtkPRStarCurvature::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FieldArrayName: " << this->FieldArrayName << "\n";
}

int vtkPRStarCurvature::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector) {
  return this->RunOnGhostedInput(
      inputVector, outputVector, true,
      [&](vtkUnstructuredGrid* grid, vtkUnstructuredGrid* output, const prstar_paraview::Options& o) {
        vtkDataArray* field = FieldArray(grid, this->FieldArrayName);
        return prstar_paraview::curvature(grid, field, output, o);
      });
}
