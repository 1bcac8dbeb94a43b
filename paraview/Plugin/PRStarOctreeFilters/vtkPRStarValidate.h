// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarValidate
 * @brief Checks a tetrahedral mesh leaf by leaf with exact predicates.
 *
 * The output is the input with the cell array `problem` (bit flags: 1 inverted, 2 flat, 4 in a
 * triangle of three or more tetrahedra), the point array `problem` (1 non-manifold, 2 in no
 * tetrahedron, 4 on a triangle of three or more tetrahedra) and, as field data, the summary of
 * `prstar validate --json`: valid, tetrahedra, inverted, degenerate, nonmanifold_triangles,
 * nonmanifold_vertices, unreferenced_vertices, euler_characteristic, boundary_triangles,
 * boundary_components.
 */
#ifndef vtkPRStarValidate_h
#define vtkPRStarValidate_h

#include "vtkPRStarFilter.h"

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarValidate : public vtkPRStarFilter {
public:
  static vtkPRStarValidate* New();
  vtkTypeMacro(vtkPRStarValidate, vtkPRStarFilter);

protected:
  vtkPRStarValidate();
  ~vtkPRStarValidate() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPRStarValidate(const vtkPRStarValidate&) = delete;
  void operator=(const vtkPRStarValidate&) = delete;
};

#endif
