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
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  auto grid = this->WithGhostCells(input);
  if (grid->GetNumberOfCells() == 0) {
    return this->EmptyPiece(grid, output);
  }
  return this->Run(output, [&](const prstar_paraview::Options& base) {
    prstar_paraview::Options o = base;
    o.labels = this->Labels(grid);
    vtkDataArray* field = FieldArray(grid, this->FieldArrayName);
    return prstar_paraview::curvature(grid, field, output, o);
  });
}
