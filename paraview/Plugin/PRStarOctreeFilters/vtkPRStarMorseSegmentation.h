// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarMorseSegmentation
 * @brief The Morse segmentation of a scalar point array, from a discrete (Forman) gradient.
 *
 * The output is the input with the point arrays `ascending_cell` (the vertex of the minimum whose
 * ascending cell holds the vertex) and `critical_type`, the cell array `descending_cell` (the vertex of
 * its maximum, -1 for a path out through the boundary) and the counts as field data, after the cancellation
 * of the pairs of persistence under PersistenceThreshold (a fraction of the field's range), as `prstar
 * morse`. One process only: under MPI each process segments its piece.
 */
#ifndef vtkPRStarMorseSegmentation_h
#define vtkPRStarMorseSegmentation_h

#include "vtkPRStarFilter.h"

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarMorseSegmentation : public vtkPRStarFilter {
public:
  static vtkPRStarMorseSegmentation* New();
  vtkTypeMacro(vtkPRStarMorseSegmentation, vtkPRStarFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The scalar point array (empty: the z coordinate).
  vtkSetStdStringFromCharMacro(FieldArrayName);
  vtkGetCharFromStdStringMacro(FieldArrayName);
  ///@}
  ///@{
  /// Pairs of persistence under this fraction of the field's range are cancelled (default 0).
  vtkSetClampMacro(PersistenceThreshold, double, 0.0, 1.0);
  vtkGetMacro(PersistenceThreshold, double);
  ///@}

protected:
  vtkPRStarMorseSegmentation();
  ~vtkPRStarMorseSegmentation() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FieldArrayName;
  double PersistenceThreshold = 0;

private:
  vtkPRStarMorseSegmentation(const vtkPRStarMorseSegmentation&) = delete;
  void operator=(const vtkPRStarMorseSegmentation&) = delete;
};

#endif
