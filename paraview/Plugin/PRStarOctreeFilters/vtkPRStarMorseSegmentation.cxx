// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarMorseSegmentation.h"
#include "vtkPRStarFilterRun.h"

#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkUnstructuredGrid.h>

vtkStandardNewMacro(vtkPRStarMorseSegmentation);

vtkPRStarMorseSegmentation::vtkPRStarMorseSegmentation() = default;
vtkPRStarMorseSegmentation::~vtkPRStarMorseSegmentation() = default;

void vtkPRStarMorseSegmentation::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FieldArrayName: " << this->FieldArrayName << "\n";
  os << indent << "PersistenceThreshold: " << this->PersistenceThreshold << "\n";
}

int vtkPRStarMorseSegmentation::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                            vtkInformationVector* outputVector) {
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (input->GetNumberOfCells() == 0) {
    return this->EmptyPiece(input, output);
  }
  return this->Run(output, [&](const prstar_paraview::Options& base) {
    prstar_paraview::Options o = base;
    o.labels = this->Labels(input);
    vtkDataArray* field = FieldArray(input, this->FieldArrayName);
    return prstar_paraview::morse_segmentation(input, field, this->PersistenceThreshold, output, o);
  });
}
