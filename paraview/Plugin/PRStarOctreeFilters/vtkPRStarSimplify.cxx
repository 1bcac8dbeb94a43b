// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarSimplify.h"
#include "vtkPRStarFilterRun.h"

#include <vtkCellArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkIdList.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <vector>

vtkStandardNewMacro(vtkPRStarSimplify);

vtkPRStarSimplify::vtkPRStarSimplify() = default;
vtkPRStarSimplify::~vtkPRStarSimplify() = default;

void vtkPRStarSimplify::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "MinimumDihedralAngle: " << this->MinimumDihedralAngle << "\n";
  os << indent << "MinimumRadiusRatio: " << this->MinimumRadiusRatio << "\n";
  os << indent << "MaximumDihedralAngle: " << this->MaximumDihedralAngle << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "OptimizationRounds: " << this->OptimizationRounds << "\n";
  os << indent << "Priority: " << this->Priority << "\n";
  os << indent << "Placement: " << this->Placement << "\n";
}

int vtkPRStarSimplify::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                   vtkInformationVector* outputVector) {
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  prstar_paraview::Simplify_options s;
  s.target = this->TargetReduction;
  s.min_dihedral = this->MinimumDihedralAngle;
  s.min_radius_ratio = this->MinimumRadiusRatio;
  s.max_dihedral = this->MaximumDihedralAngle;
  s.feature_angle = this->FeatureAngle;
  s.max_error = this->MaximumError;
  s.optimize = this->OptimizationRounds;
  s.quadric = this->Priority == 1;
  s.optimal = this->Placement == 1;
  // Under MPI: the cells this piece owns, and the vertices it shares with the ghost layer (the
  // other pieces' cells) kept, so that the simplified pieces still meet face to face.
  auto grid = this->WithGhostCells(input);
  if (grid->GetNumberOfCells() == 0) {
    return this->EmptyPiece(grid, output);
  }
  std::vector<char> owned, shared;
  vtkUnsignedCharArray* ghosts = grid->GetCellGhostArray();
  if (ghosts != nullptr) {
    const vtkIdType nc = grid->GetNumberOfCells();
    owned.assign(static_cast<std::size_t>(nc), 1);
    shared.assign(static_cast<std::size_t>(grid->GetNumberOfPoints()), 0);
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < nc; ++c) {
      if ((ghosts->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL) == 0) {
        continue;
      }
      owned[static_cast<std::size_t>(c)] = 0;
      grid->GetCellPoints(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
        shared[static_cast<std::size_t>(ids->GetId(k))] = 1;
      }
    }
    s.cells = &owned;
    s.constrained = &shared;
  }
  return this->Run(output, [&](const prstar_paraview::Options& base) {
    prstar_paraview::Options o = base;
    o.labels = this->Labels(grid);
    return prstar_paraview::simplify(grid, s, output, o);
  });
}
