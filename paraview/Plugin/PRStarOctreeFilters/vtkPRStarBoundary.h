// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarBoundary
 * @brief The boundary of a tetrahedral mesh, leaf by leaf (paper Section 7).
 *
 * Output 0: the input with the point array `boundary` (0 interior, 1 boundary, 2 non-manifold,
 * 3 in no tetrahedron) and the counts as field data, as `prstar boundary -o`.
 * Output 1 (when GenerateSurface is on): the boundary surface and the interfaces between labels,
 * outward oriented, with the cell arrays `label_inside`, `label_outside` (-1 on the boundary) and
 * `interface`, and the point arrays `vertex` (the input point) and `boundary_type`, as
 * `prstar boundary --surface`.
 */
#ifndef vtkPRStarBoundary_h
#define vtkPRStarBoundary_h

#include "vtkPRStarFilter.h"

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarBoundary : public vtkPRStarFilter {
public:
  static vtkPRStarBoundary* New();
  vtkTypeMacro(vtkPRStarBoundary, vtkPRStarFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Whether output 1 holds the boundary surface (default on).
  vtkSetMacro(GenerateSurface, bool);
  vtkGetMacro(GenerateSurface, bool);
  vtkBooleanMacro(GenerateSurface, bool);
  ///@}

protected:
  vtkPRStarBoundary();
  ~vtkPRStarBoundary() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool GenerateSurface = true;

private:
  vtkPRStarBoundary(const vtkPRStarBoundary&) = delete;
  void operator=(const vtkPRStarBoundary&) = delete;
};

#endif
