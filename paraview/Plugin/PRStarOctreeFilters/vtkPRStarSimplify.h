// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarSimplify
 * @brief Simplifies the tetrahedra of a mesh by edge collapses, leaf by leaf (paper Section 9).
 *
 * The options of `prstar simplify`: the fraction of tetrahedra to remove, the quality floors and
 * ceiling, the feature angle, the error bound (a percentage of the bounding box diagonal), the
 * collapse priority and placement, the optimisation rounds.  The labels (any integer cell array)
 * keep their interfaces; every point and cell array is carried along.  The output holds the
 * tetrahedra only.
 *
 * Under MPI each process simplifies the cells it owns and keeps the vertices it shares with the
 * other pieces, so that the pieces still meet face to face.
 */
#ifndef vtkPRStarSimplify_h
#define vtkPRStarSimplify_h

#include "vtkPRStarFilter.h"

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarSimplify : public vtkPRStarFilter {
public:
  static vtkPRStarSimplify* New();
  vtkTypeMacro(vtkPRStarSimplify, vtkPRStarFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The fraction of the tetrahedra to remove, in (0, 1) (default 0.5).
  vtkSetClampMacro(TargetReduction, double, 0.0, 1.0);
  vtkGetMacro(TargetReduction, double);
  ///@}
  ///@{
  /// The floor on the smallest dihedral angle, in degrees (default 5; 0: none).
  vtkSetClampMacro(MinimumDihedralAngle, double, 0.0, 70.0);
  vtkGetMacro(MinimumDihedralAngle, double);
  ///@}
  ///@{
  /// The floor on the radius ratio 3r/R (default 0.1; 0: none).
  vtkSetClampMacro(MinimumRadiusRatio, double, 0.0, 1.0);
  vtkGetMacro(MinimumRadiusRatio, double);
  ///@}
  ///@{
  /// The ceiling on the largest dihedral angle, in degrees (default 165; 180: none).
  vtkSetClampMacro(MaximumDihedralAngle, double, 70.0, 180.0);
  vtkGetMacro(MaximumDihedralAngle, double);
  ///@}
  ///@{
  /// Surface edges bending more than this many degrees are sharp features (default 40).
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}
  ///@{
  /// The bound on the distance to the input surface, in percent of the bounding box diagonal
  /// (default 0.2); negative: no bound.
  vtkSetMacro(MaximumError, double);
  vtkGetMacro(MaximumError, double);
  ///@}
  ///@{
  /// Rounds of flips and vertex moves after the collapses (default 2; 0: coarsen only).
  vtkSetClampMacro(OptimizationRounds, int, 0, 100);
  vtkGetMacro(OptimizationRounds, int);
  ///@}
  ///@{
  /// The collapse priority: 0 edge length (shortest first, default), 1 quadric error.
  vtkSetClampMacro(Priority, int, 0, 1);
  vtkGetMacro(Priority, int);
  ///@}
  ///@{
  /// The placement: 0 half-edge (default), 1 optimal.
  vtkSetClampMacro(Placement, int, 0, 1);
  vtkGetMacro(Placement, int);
  ///@}

protected:
  vtkPRStarSimplify();
  ~vtkPRStarSimplify() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double TargetReduction = 0.5;
  double MinimumDihedralAngle = 5;
  double MinimumRadiusRatio = 0.1;
  double MaximumDihedralAngle = 165;
  double FeatureAngle = 40;
  double MaximumError = 0.2;
  int OptimizationRounds = 2;
  int Priority = 0;
  int Placement = 0;

private:
  vtkPRStarSimplify(const vtkPRStarSimplify&) = delete;
  void operator=(const vtkPRStarSimplify&) = delete;
};

#endif
