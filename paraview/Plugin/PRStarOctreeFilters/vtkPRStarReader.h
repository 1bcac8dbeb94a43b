// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarReader
 * @brief Reads tetrahedral meshes with the PR-star octree package's readers.
 *
 * For the formats ParaView lacks or reads without their labels: Medit `.mesh` and `.meshb` (with
 * their references), gmsh `.msh` (physical tags and their names), TetGen `.node`/`.ele` (region
 * attributes).  The output holds the tetrahedra, the cell array `label`, the field data `label_ids`
 * and `label_names` when the file names its labels, and the file's point and cell data.  The
 * readers refuse a file announcing more than the available memory before allocating it.  Under MPI
 * the first process reads the file and the others output nothing (redistribute the mesh with
 * RedistributeDataSet).
 */
#ifndef vtkPRStarReader_h
#define vtkPRStarReader_h

#include "PRStarOctreeFiltersModule.h"
#include <vtkUnstructuredGridAlgorithm.h>

#include <string>

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarReader : public vtkUnstructuredGridAlgorithm {
public:
  static vtkPRStarReader* New();
  vtkTypeMacro(vtkPRStarReader, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /// Whether the extension of `name` is one this reader takes (1) or not (0).
  int CanReadFile(const char* name);

protected:
  vtkPRStarReader();
  ~vtkPRStarReader() override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;

private:
  vtkPRStarReader(const vtkPRStarReader&) = delete;
  void operator=(const vtkPRStarReader&) = delete;
};

#endif
