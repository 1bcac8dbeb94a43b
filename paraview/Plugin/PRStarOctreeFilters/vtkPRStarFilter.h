// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
/**
 * @class vtkPRStarFilter
 * @brief The base of the PR-star octree filters: k_v, threads, labels, ghost cells, errors.
 *
 * Each filter builds the PR-star octree of the tetrahedra of its vtkUnstructuredGrid input (cells
 * of other types are passed through and reported), runs one application of the package on it and
 * throws the octree away.  When ParaView runs on several MPI processes, each process works on its
 * piece with one layer of ghost cells (vtkGhostCellsGenerator), so that the results on the points
 * it owns are those of one process; the ghost cells stay in the output, marked as such.
 */
#ifndef vtkPRStarFilter_h
#define vtkPRStarFilter_h

#include "PRStarOctreeFiltersModule.h"
#include <vtkUnstructuredGridAlgorithm.h>

#include <string>

class vtkDataArray;
class vtkDataObject;
class vtkUnstructuredGrid;

class PRSTAROCTREEFILTERS_EXPORT vtkPRStarFilter : public vtkUnstructuredGridAlgorithm {
public:
  vtkTypeMacro(vtkPRStarFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The bucket threshold k_v of the octree (default 50); 0 for one leaf (k_v = infinity).
  vtkSetClampMacro(BucketSize, int, -1, VTK_INT_MAX);
  vtkGetMacro(BucketSize, int);
  ///@}

  ///@{
  /// The number of threads (default 0: all the cores).
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// The integer cell array of the tetrahedron labels (subdomains); none when empty or not found.
  vtkSetStdStringFromCharMacro(LabelArrayName);
  vtkGetCharFromStdStringMacro(LabelArrayName);
  ///@}

protected:
  vtkPRStarFilter();
  ~vtkPRStarFilter() override;

  /// The grid a filter works on: `input` itself on one process; with one layer of ghost cells
  /// added on several (unless it has ghost cells already).
  vtkSmartPointer<vtkUnstructuredGrid> WithGhostCells(vtkUnstructuredGrid* input);
  /// Whether ParaView runs on several processes.
  static bool Distributed();
  /// `output` = `input` for a piece without cells (under MPI, a process may get none); returns 1.
  static int EmptyPiece(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output);
  /// The label array of `grid` (nullptr: none).
  vtkDataArray* Labels(vtkUnstructuredGrid* grid) const;
  /// The one-component point array `name` of `grid`, the field of an application: nullptr when
  /// `name` is empty (the z coordinate then); throws std::runtime_error when there is no such array.
  static vtkDataArray* FieldArray(vtkUnstructuredGrid* grid, const std::string& name);
  /// Port 0 a vtkUnstructuredGrid, any other port (the boundary surface, the critical points) a
  /// vtkPolyData.
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  /// Runs `work`, reporting its progress to ParaView and its exceptions as errors, and adds to the
  /// field data of `output` its `seconds` (the time of `work`, for scripts and benchmarks) and a
  /// one-line `summary`; returns 1 on success, 0 on failure.
  template <class F>
  int Run(vtkDataObject* output, F&& work);
  /// The RequestData of a filter on its input grid with ghost cells (`WithGhostCells`): an empty
  /// piece is passed through; otherwise `work(grid, output, options)` runs through `Run`, the
  /// options with the label array (`Labels`) when `labels`.
  template <class F>
  int RunOnGhostedInput(vtkInformationVector** inputVector, vtkInformationVector* outputVector, bool labels,
                        F&& work);

  int BucketSize = -1;
  int NumberOfThreads = 0;
  std::string LabelArrayName = "label";

private:
  vtkPRStarFilter(const vtkPRStarFilter&) = delete;
  void operator=(const vtkPRStarFilter&) = delete;
};

#endif
