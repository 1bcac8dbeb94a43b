// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarValidate.h"
#include "vtkPRStarFilterRun.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkUnstructuredGrid.h>

vtkStandardNewMacro(vtkPRStarValidate);

vtkPRStarValidate::vtkPRStarValidate() = default;
vtkPRStarValidate::~vtkPRStarValidate() = default;

int vtkPRStarValidate::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector) {
  return this->RunOnGhostedInput(
      inputVector, outputVector, false,
      [](vtkUnstructuredGrid* grid, vtkUnstructuredGrid* output, const prstar_paraview::Options& o) {
        return prstar_paraview::validate(grid, output, o);
      });
}
