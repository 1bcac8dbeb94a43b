// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarOctreeLeaves
 * @brief The leaves of the PR-star octree of a tetrahedral mesh, as voxels.
 *
 * One voxel per leaf with the cell arrays `depth`, `vertices` (the vertices it owns) and
 * `tetrahedra` (those of its vertices' stars), as `prstar stats --octree`; the octree's statistics
 * (nodes, leaves, depth, chi, bytes, ...) as field data.  Under MPI, each process shows the octree of
 * its piece.
 */
#ifndef vtkPRStarOctreeLeaves_h
#define vtkPRStarOctreeLeaves_h

#include "vtkPRStarFilter.h"

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarOctreeLeaves : public vtkPRStarFilter {
public:
  static vtkPRStarOctreeLeaves* New();
  vtkTypeMacro(vtkPRStarOctreeLeaves, vtkPRStarFilter);

protected:
  vtkPRStarOctreeLeaves();
  ~vtkPRStarOctreeLeaves() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPRStarOctreeLeaves(const vtkPRStarOctreeLeaves&) = delete;
  void operator=(const vtkPRStarOctreeLeaves&) = delete;
};

#endif
