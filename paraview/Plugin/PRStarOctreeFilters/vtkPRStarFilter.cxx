// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later
#include "vtkPRStarFilter.h"
#include "vtkPRStarFilterRun.h"

#include <vtkCellData.h>
#include <vtkIdTypeArray.h>
#include <vtkCommunicator.h>
#include <vtkDataSetAttributes.h>
#include <vtkUnsignedCharArray.h>
#include <vtkDataArray.h>
#include <vtkGhostCellsGenerator.h>
#include <vtkInformation.h>
#include <vtkMultiProcessController.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>

vtkPRStarFilter::vtkPRStarFilter() = default;
vtkPRStarFilter::~vtkPRStarFilter() = default;

void vtkPRStarFilter::PrintSelf(ostream& os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BucketSize: " << this->BucketSize << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "LabelArrayName: " << this->LabelArrayName << "\n";
}

bool vtkPRStarFilter::Distributed() {
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  return c != nullptr && c->GetNumberOfProcesses() > 1;
}

vtkSmartPointer<vtkUnstructuredGrid> vtkPRStarFilter::WithGhostCells(vtkUnstructuredGrid* input) {
  if (!Distributed()) {
    return input;
  }
  // Whether this piece has ghost cells already (a vtkGhostType array with DUPLICATECELL set: a
  // redistribution filter may add the array with none); the processes decide together, since the
  // generator is collective.
  int has = 0;
  if (vtkUnsignedCharArray* g = input->GetCellGhostArray()) {
    for (vtkIdType c = 0; c < g->GetNumberOfTuples() && !has; ++c) {
      has = (g->GetValue(c) & vtkDataSetAttributes::DUPLICATECELL) != 0;
    }
  }
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  int all = 0;
  controller->AllReduce(&has, &all, 1, vtkCommunicator::MIN_OP);
  if (all != 0) {
    return input;
  }
  // The generator of VTK 9.2 (ParaView 5.11) finds the neighbouring pieces of an unstructured grid
  // through the point global ids: without them it adds no ghost cell.  Ids made from the bits of
  // the coordinates are the same on every process for the same point (the pieces of one mesh share
  // their interface points exactly).
  vtkSmartPointer<vtkUnstructuredGrid> source = input;
  const bool made_ids = input->GetPointData()->GetGlobalIds() == nullptr;
  if (made_ids) {
    source = vtkSmartPointer<vtkUnstructuredGrid>::New();
    source->ShallowCopy(input);
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("prstar_point_ids");
    ids->SetNumberOfTuples(input->GetNumberOfPoints());
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i) {
      double x[3];
      input->GetPoint(i, x);
      std::uint64_t h = 0x9e3779b97f4a7c15ULL;
      for (double c : x) {
        std::uint64_t bits;
        std::memcpy(&bits, &c, sizeof bits);
        h ^= bits + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL; // the splitmix64 finaliser
        h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
        h ^= h >> 31;
      }
      ids->SetValue(i, static_cast<vtkIdType>(h >> 2)); // non-negative
    }
    source->GetPointData()->SetGlobalIds(ids);
  }
  vtkNew<vtkGhostCellsGenerator> ghosts;
  ghosts->SetController(controller);
  ghosts->SetNumberOfGhostLayers(1);
  ghosts->BuildIfRequiredOff();
  ghosts->SetInputData(source);
  ghosts->Update();
  auto generated = vtkUnstructuredGrid::SafeDownCast(ghosts->GetOutputDataObject(0));
  if (generated == nullptr) {
    return input;
  }
  auto result = vtkSmartPointer<vtkUnstructuredGrid>::New();
  result->ShallowCopy(generated);
  if (made_ids) {
    result->GetPointData()->RemoveArray("prstar_point_ids");
  }
  return result;
}

int vtkPRStarFilter::EmptyPiece(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output) {
  output->ShallowCopy(input);
  return 1;
}

vtkDataArray* vtkPRStarFilter::Labels(vtkUnstructuredGrid* grid) const {
  if (this->LabelArrayName.empty()) {
    return nullptr;
  }
  return grid->GetCellData()->GetArray(this->LabelArrayName.c_str());
}

vtkDataArray* vtkPRStarFilter::FieldArray(vtkUnstructuredGrid* grid, const std::string& name) {
  if (name.empty()) {
    return nullptr;
  }
  vtkDataArray* a = grid->GetPointData()->GetArray(name.c_str());
  if (a == nullptr) {
    throw std::runtime_error("no point array '" + name + "'");
  }
  return a;
}

int vtkPRStarFilter::FillOutputPortInformation(int port, vtkInformation* info) {
  if (port > 0) {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}
