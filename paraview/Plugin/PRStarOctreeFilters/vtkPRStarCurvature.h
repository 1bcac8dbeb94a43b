// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarCurvature
 * @brief Discrete distortion of a point array and concentrated curvature of the domain (paper Section 8).
 *
 * The output is the input with the point arrays `boundary`, `distortion` (of the point array
 * FieldArrayName, the z coordinate when it is empty) and `domain_curvature`, NaN where they are
 * undefined (non-manifold vertices, vertices in no tetrahedron), as `prstar curvature --csv`.
 */
#ifndef vtkPRStarCurvature_h
#define vtkPRStarCurvature_h

#include "vtkPRStarFilter.h"

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarCurvature : public vtkPRStarFilter {
public:
  static vtkPRStarCurvature* New();
  vtkTypeMacro(vtkPRStarCurvature, vtkPRStarFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scalar point array whose distortion is computed (empty: the z coordinate).
  vtkSetStdStringFromCharMacro(FieldArrayName);
  vtkGetCharFromStdStringMacro(FieldArrayName);
  ///@}

protected:
  vtkPRStarCurvature();
  ~vtkPRStarCurvature() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FieldArrayName;

private:
  vtkPRStarCurvature(const vtkPRStarCurvature&) = delete;
  void operator=(const vtkPRStarCurvature&) = delete;
};

#endif
