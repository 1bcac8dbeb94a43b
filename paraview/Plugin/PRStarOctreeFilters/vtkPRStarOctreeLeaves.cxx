// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarOctreeLeaves.h"
#include "vtkPRStarFilterRun.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkUnstructuredGrid.h>

vtkStandardNewMacro(vtkPRStarOctreeLeaves);

vtkPRStarOctreeLeaves::vtkPRStarOctreeLeaves() = default;
vtkPRStarOctreeLeaves::~vtkPRStarOctreeLeaves() = default;

int vtkPRStarOctreeLeaves::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                       vtkInformationVector* outputVector) {
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (input->GetNumberOfCells() == 0) {
    return this->EmptyPiece(input, output);
  }
  return this->Run(output, [&](const prstar_paraview::Options& base) {
    prstar_paraview::Options o = base;
    o.labels = this->Labels(input);
    return prstar_paraview::octree_leaves(input, output, o);
  });
}
