// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// vtkPRStarFilter::Run, for the filters' .cxx files only (not wrapped).
#ifndef vtkPRStarFilterRun_h
#define vtkPRStarFilterRun_h

#include "PRStarParaViewCore.h"
#include "vtkPRStarFilter.h"

#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <chrono>
#include <exception>

template <class F>
int vtkPRStarFilter::Run(vtkDataObject* output, F&& work) {
  prstar_paraview::Options o;
  o.bucket_size = this->BucketSize;
  o.threads = this->NumberOfThreads;
  o.progress = [this](double f) { this->UpdateProgress(f); };
  this->UpdateProgress(0);
  try {
    const auto start = std::chrono::steady_clock::now();
    const prstar_paraview::Outcome r = work(o);
    vtkNew<vtkDoubleArray> seconds;
    seconds->SetName("seconds");
    seconds->InsertNextValue(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    vtkNew<vtkStringArray> summary;
    summary->SetName("summary");
    summary->InsertNextValue(r.summary);
    output->GetFieldData()->AddArray(seconds);
    output->GetFieldData()->AddArray(summary);
    if (r.other_cells > 0) {
      vtkWarningMacro(<< r.other_cells
                      << " cells are not tetrahedra: they are passed through, and the octree ignores them");
    }
    vtkDebugMacro(<< r.summary);
    this->SetProgressText(r.summary.c_str());
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  this->UpdateProgress(1);
  return 1;
}

template <class F>
int vtkPRStarFilter::RunOnGhostedInput(vtkInformationVector** inputVector, vtkInformationVector* outputVector,
                                       bool labels, F&& work) {
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkSmartPointer<vtkUnstructuredGrid> grid = this->WithGhostCells(input);
  if (grid->GetNumberOfCells() == 0) {
    return this->EmptyPiece(grid, output);
  }
  return this->Run(output, [&](const prstar_paraview::Options& base) {
    prstar_paraview::Options o = base;
    if (labels) {
      o.labels = this->Labels(grid);
    }
    return work(grid.GetPointer(), output, o);
  });
}

#endif
