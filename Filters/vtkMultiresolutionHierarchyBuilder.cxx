// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMultiresolutionHierarchyBuilder.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMergeTreeBuilder.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataValidator.h"
#include "vtkSmartPointer.h"
#include "vtkTOMBuilder.h"
#include "vtkTOMFieldData.h"
#include "vtkVariant.h"

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMultiresolutionHierarchyBuilder);

namespace
{
/// 64-bit hash of a byte range, 8 bytes per step (a multiply-xorshift mix:
/// several GB/s, far below the cost of a build).
uint64_t HashBytes(const void* data, size_t bytes, uint64_t h)
{
  const auto* p = static_cast<const unsigned char*>(data);
  auto mix = [&h](uint64_t word) {
    h ^= word + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 31;
  };
  size_t i = 0;
  for (; i + 8 <= bytes; i += 8)
  {
    uint64_t word;
    std::memcpy(&word, p + i, 8);
    mix(word);
  }
  uint64_t tail = 0;
  if (bytes > i)
  {
    std::memcpy(&tail, p + i, bytes - i);
  }
  mix(tail ^ (static_cast<uint64_t>(bytes) << 56));
  return h;
}

uint64_t HashString(const char* text, uint64_t h)
{
  return text ? HashBytes(text, std::strlen(text), h) : HashBytes("\0null", 5, h);
}

/// Type, shape and values of an array (a non-numeric array by its values' text).
uint64_t HashArray(vtkAbstractArray* array, uint64_t h)
{
  if (!array)
  {
    return HashBytes("none", 4, h);
  }
  h = HashString(array->GetName(), h);
  const int shape[3] = { array->GetDataType(), array->GetNumberOfComponents(),
    static_cast<int>(array->GetNumberOfTuples() & 0x7fffffff) };
  h = HashBytes(shape, sizeof(shape), h);
  auto* data = vtkDataArray::SafeDownCast(array);
  if (data && data->HasStandardMemoryLayout())
  {
    return HashBytes(data->GetVoidPointer(0),
      static_cast<size_t>(data->GetNumberOfValues()) * static_cast<size_t>(data->GetDataTypeSize()),
      h);
  }
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    h = HashString(array->GetVariantValue(i).ToString().c_str(), h);
  }
  return h;
}

uint64_t HashCells(vtkCellArray* cells, uint64_t h)
{
  if (!cells || cells->GetNumberOfCells() == 0)
  {
    return HashBytes("empty", 5, h);
  }
  return HashArray(cells->GetConnectivityArray(), HashArray(cells->GetOffsetsArray(), h));
}

uint64_t HashAttributes(vtkFieldData* attributes, uint64_t h)
{
  for (int i = 0; i < attributes->GetNumberOfArrays(); ++i)
  {
    h = HashArray(attributes->GetAbstractArray(i), h);
  }
  return HashBytes("end", 3, h);
}

/**
 * Everything a build depends on: points, cells, point and cell data. A
 * hash rather than the arrays themselves: ParaView's geometry filter may
 * refill the same array objects at every execution, so holding them would
 * not keep the old content to compare with.
 */
uint64_t HashLeaf(vtkPolyData* leaf)
{
  uint64_t h = 0x84222325CBF29CE4ull;
  h = HashArray(leaf->GetPoints() ? leaf->GetPoints()->GetData() : nullptr, h);
  h = HashCells(leaf->GetVerts(), h);
  h = HashCells(leaf->GetLines(), h);
  h = HashCells(leaf->GetPolys(), h);
  h = HashCells(leaf->GetStrips(), h);
  h = HashAttributes(leaf->GetPointData(), h);
  return HashAttributes(leaf->GetCellData(), h);
}
/// The cells a build simplifies (0 for a leaf that is not polydata).
double SurfaceCells(vtkPolyData* leaf)
{
  return leaf ? static_cast<double>(leaf->GetNumberOfPolys() + leaf->GetNumberOfStrips()) : 0.0;
}
} // namespace

struct vtkMultiresolutionHierarchyBuilder::CacheEntry
{
  uint64_t InputHash = 0;              // HashLeaf() of the leaf Output was built from
  vtkIdType InputCells = 0;            // and its cell count (a second check)
  vtkSmartPointer<vtkPolyData> Output; // the build
  int Hierarchy = 0;
};

struct vtkMultiresolutionHierarchyBuilder::Internals
{
  std::map<unsigned int, CacheEntry> Cache; // by composite flat index (0 for polydata)
};

//------------------------------------------------------------------------------
vtkMultiresolutionHierarchyBuilder::vtkMultiresolutionHierarchyBuilder()
  : Internal(new Internals)
{
}

vtkMultiresolutionHierarchyBuilder::~vtkMultiresolutionHierarchyBuilder() = default;

void vtkMultiresolutionHierarchyBuilder::ClearCache()
{
  this->Internal->Cache.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkMultiresolutionHierarchyBuilder::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  this->NumberOfBuiltLeaves = this->NumberOfReusedLeaves = this->NumberOfPassedLeaves = 0;
  if (!input || !output)
  {
    return 1;
  }
  std::map<unsigned int, CacheEntry> cache; // this execution's builds
  double totalCells = 0.0, doneCells = 0.0;       // progress follows the surface cells

  auto* compositeInput = vtkCompositeDataSet::SafeDownCast(input);
  auto* compositeOutput = vtkCompositeDataSet::SafeDownCast(output);
  if (compositeInput && compositeOutput)
  {
    compositeOutput->CopyStructure(compositeInput);
    vtkSmartPointer<vtkCompositeDataIterator> iterator;
    iterator.TakeReference(compositeInput->NewIterator());
    iterator->SkipEmptyNodesOn();
    for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
    {
      totalCells += SurfaceCells(vtkPolyData::SafeDownCast(iterator->GetCurrentDataObject()));
    }
    for (iterator->InitTraversal(); !iterator->IsDoneWithTraversal(); iterator->GoToNextItem())
    {
      vtkDataObject* leaf = iterator->GetCurrentDataObject();
      if (auto* poly = vtkPolyData::SafeDownCast(leaf))
      {
        compositeOutput->SetDataSet(iterator,
          this->ProcessLeaf(poly, iterator->GetCurrentFlatIndex(), cache, totalCells, doneCells));
      }
      else
      {
        compositeOutput->SetDataSet(iterator, leaf);
        ++this->NumberOfPassedLeaves;
      }
    }
  }
  else if (auto* poly = vtkPolyData::SafeDownCast(input))
  {
    totalCells = SurfaceCells(poly);
    output->ShallowCopy(this->ProcessLeaf(poly, 0, cache, totalCells, doneCells));
  }
  else
  {
    output->ShallowCopy(input);
    return 1;
  }
  this->Internal->Cache.swap(cache);
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkMultiresolutionHierarchyBuilder::ProcessLeaf(vtkPolyData* data,
  unsigned int index, std::map<unsigned int, CacheEntry>& cache, double totalCells,
  double& doneCells)
{
  const double cells = SurfaceCells(data);
  vtkSmartPointer<vtkPolyData> result = data;
  const bool carries = vtkTOMFieldData::HasTOMArrays(data) &&
    (this->Hierarchy != MERGE_TREE || vtkMergeTreeFieldData::HasMergeTreeArrays(data));
  if (carries || cells == 0.0)
  {
    ++this->NumberOfPassedLeaves;
  }
  else
  {
    const uint64_t hash = HashLeaf(data);
    auto cached = this->Internal->Cache.find(index);
    if (cached != this->Internal->Cache.end() && cached->second.Hierarchy == this->Hierarchy &&
      cached->second.InputHash == hash && cached->second.InputCells == data->GetNumberOfCells())
    {
      result = cached->second.Output;
      ++this->NumberOfReusedLeaves;
    }
    else
    {
      result = this->Build(data, index, totalCells > 0.0 ? doneCells / totalCells : 0.0,
        totalCells > 0.0 ? cells / totalCells : 0.0);
    }
    if (result != data) // builds only: a leaf passed as it came costs nothing again
    {
      CacheEntry& entry = cache[index];
      entry.InputHash = hash;
      entry.InputCells = data->GetNumberOfCells();
      entry.Output = result;
      entry.Hierarchy = this->Hierarchy;
    }
  }
  doneCells += cells;
  this->UpdateProgress(totalCells > 0.0 ? doneCells / totalCells : 1.0);
  return result;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkMultiresolutionHierarchyBuilder::Build(
  vtkPolyData* leaf, unsigned int leafIndex, double progressBase, double progressSpan)
{
  // Checked here rather than by the builder, whose failure would also bring
  // an error of its executive; and vertices or lines, which a TOM cannot
  // hold, would be lost: such leaves pass as they are.
  const std::string problem = vtkPolyDataValidator::CheckBuildInput(leaf);
  if (!problem.empty())
  {
    vtkErrorMacro("Leaf " << leafIndex << " (composite flat index) passes without a hierarchy: "
                          << problem << ".");
    ++this->NumberOfPassedLeaves;
    return leaf;
  }
  if (leaf->GetNumberOfVerts() > 0 || leaf->GetNumberOfLines() > 0)
  {
    vtkWarningMacro("Leaf " << leafIndex << " (composite flat index) has "
                            << leaf->GetNumberOfVerts() + leaf->GetNumberOfLines()
                            << " vertex and line cells besides its surface: drawn in full "
                               "(a hierarchy holds triangles only; extract the surface to make "
                               "it multiresolution).");
    ++this->NumberOfPassedLeaves;
    return leaf;
  }
  vtkSmartPointer<vtkPolyDataAlgorithm> builder;
  if (this->Hierarchy == MERGE_TREE)
  {
    builder = vtkSmartPointer<vtkMergeTreeBuilder>::New();
  }
  else
  {
    builder = vtkSmartPointer<vtkTOMBuilder>::New();
  }
  this->ProgressBase = progressBase;
  this->ProgressSpan = progressSpan;
  this->CurrentLeaf = leafIndex;
  builder->AddObserver(
    vtkCommand::ProgressEvent, this, &vtkMultiresolutionHierarchyBuilder::ForwardProgress);
  builder->AddObserver(
    vtkCommand::ErrorEvent, this, &vtkMultiresolutionHierarchyBuilder::ForwardMessage);
  builder->AddObserver(
    vtkCommand::WarningEvent, this, &vtkMultiresolutionHierarchyBuilder::ForwardMessage);
  builder->SetInputData(leaf);
  builder->Update();
  vtkPolyData* built = builder->GetOutput();
  if (!built || !vtkTOMFieldData::HasTOMArrays(built))
  {
    ++this->NumberOfPassedLeaves; // the builder said why
    return leaf;
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(built);
  ++this->NumberOfBuiltLeaves;
  ++this->NumberOfBuilds;
  return result;
}

void vtkMultiresolutionHierarchyBuilder::ForwardProgress(vtkObject* caller, unsigned long, void*)
{
  // The leaf's progress, scaled into the whole execution's.
  auto* algorithm = static_cast<vtkAlgorithm*>(caller);
  this->UpdateProgress(this->ProgressBase + this->ProgressSpan * algorithm->GetProgress());
  if (this->AbortExecute)
  {
    algorithm->SetAbortExecute(1);
  }
}

void vtkMultiresolutionHierarchyBuilder::ForwardMessage(
  vtkObject*, unsigned long event, void* callData)
{
  // The builder's messages become this filter's, with the leaf they concern
  // (an observer keeps the builder from printing them itself).
  const char* text = callData ? static_cast<const char*>(callData) : "";
  if (event == vtkCommand::ErrorEvent)
  {
    vtkErrorMacro("Leaf " << this->CurrentLeaf << " (composite flat index) passes without a "
                          << "hierarchy: " << text);
  }
  else
  {
    vtkWarningMacro("Leaf " << this->CurrentLeaf << " (composite flat index): " << text);
  }
}

//------------------------------------------------------------------------------
void vtkMultiresolutionHierarchyBuilder::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Hierarchy: "
     << (this->Hierarchy == MERGE_TREE ? "MERGE_TREE" : "TOTALLY_ORDERED_MESH") << "\n";
  os << indent << "NumberOfBuiltLeaves: " << this->NumberOfBuiltLeaves << "\n";
  os << indent << "NumberOfReusedLeaves: " << this->NumberOfReusedLeaves << "\n";
  os << indent << "NumberOfPassedLeaves: " << this->NumberOfPassedLeaves << "\n";
  os << indent << "NumberOfBuilds: " << this->NumberOfBuilds << "\n";
  os << indent << "CachedLeaves: " << this->Internal->Cache.size() << "\n";
}
