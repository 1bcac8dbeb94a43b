// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarReader.h"
#include "PRStarParaViewCore.h"

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cctype>
#include <exception>

vtkStandardNewMacro(vtkPRStarReader);

vtkPRStarReader::vtkPRStarReader() {
  this->SetNumberOfInputPorts(0);
}

vtkPRStarReader::~vtkPRStarReader() = default;

void vtkPRStarReader::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}

int vtkPRStarReader::CanReadFile(const char* name) {
  std::string s = name != nullptr ? name : "";
  const auto dot = s.rfind('.');
  if (dot == std::string::npos) {
    return 0;
  }
  std::string e = s.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e == "mesh" || e == "meshb" || e == "msh" || e == "node" || e == "ele" ? 1 : 0;
}

int vtkPRStarReader::RequestInformation(vtkInformation*, vtkInformationVector**,
                                        vtkInformationVector* outputVector) {
  // every process is asked for its piece; the first one reads the file
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkPRStarReader::RequestData(vtkInformation*, vtkInformationVector**,
                                 vtkInformationVector* outputVector) {
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
      info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0) {
    return 1;
  }
  if (this->FileName.empty()) {
    vtkErrorMacro(<< "no file name");
    return 0;
  }
  this->UpdateProgress(0);
  try {
    const prstar_paraview::Outcome r = prstar_paraview::read(this->FileName, output);
    if (r.other_cells > 0) {
      vtkWarningMacro(<< r.summary);
    }
  } catch (const std::exception& e) {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  this->UpdateProgress(1);
  return 1;
}
