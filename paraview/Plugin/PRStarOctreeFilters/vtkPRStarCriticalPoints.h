// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarCriticalPoints
 * @brief The critical points of a scalar point array (minima, saddles, maxima), from the links.
 *
 * Output 0: the input with the point array `critical_type` (TTK's codes: 0 minimum, 1 1-saddle,
 * 2 2-saddle, 3 maximum, 4 degenerate, 5 regular) and the counts as field data.
 * Output 1: the critical points as vertices with the point arrays `vertex`, `critical_type`,
 * `value`, `lower_components`, `upper_components` and `on_boundary`, as `prstar critical`.
 */
#ifndef vtkPRStarCriticalPoints_h
#define vtkPRStarCriticalPoints_h

#include "vtkPRStarFilter.h"

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarCriticalPoints : public vtkPRStarFilter {
public:
  static vtkPRStarCriticalPoints* New();
  vtkTypeMacro(vtkPRStarCriticalPoints, vtkPRStarFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scalar point array (empty: the z coordinate).
  vtkSetStdStringFromCharMacro(FieldArrayName);
  vtkGetCharFromStdStringMacro(FieldArrayName);
  ///@}

protected:
  vtkPRStarCriticalPoints();
  ~vtkPRStarCriticalPoints() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FieldArrayName;

private:
  vtkPRStarCriticalPoints(const vtkPRStarCriticalPoints&) = delete;
  void operator=(const vtkPRStarCriticalPoints&) = delete;
};

#endif
