// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMultiresolutionHierarchyBuilder.h"

#include "LeafContentHash.h"
#include "LeafHierarchyBuild.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkMultiresolutionHierarchyBuilder);

namespace
{
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
  const bool carries = timecritical::CarriesHierarchy(data,
    this->Hierarchy == MERGE_TREE ? timecritical::LeafHierarchy::MergeTree
                                  : timecritical::LeafHierarchy::TotallyOrderedMesh);
  if (carries || cells == 0.0)
  {
    ++this->NumberOfPassedLeaves;
  }
  else
  {
    const uint64_t hash = timecritical::HashLeafContent(data);
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
  // The leaf's progress, scaled into the whole execution's; an abort of this
  // filter cancels the build.
  auto progress = [this, progressBase, progressSpan](double fraction) {
    this->UpdateProgress(progressBase + progressSpan * fraction);
    return !this->AbortExecute;
  };
  const timecritical::LeafBuildResult built = timecritical::BuildLeafHierarchy(leaf,
    this->Hierarchy == MERGE_TREE ? timecritical::LeafHierarchy::MergeTree
                                  : timecritical::LeafHierarchy::TotallyOrderedMesh,
    progress);
  this->ReportMessages(built, leafIndex);
  if (!built.Hierarchy)
  {
    ++this->NumberOfPassedLeaves; // the messages said why (or the build was aborted)
    return leaf;
  }
  ++this->NumberOfBuiltLeaves;
  ++this->NumberOfBuilds;
  return built.Hierarchy;
}

void vtkMultiresolutionHierarchyBuilder::ReportMessages(
  const timecritical::LeafBuildResult& built, unsigned int leafIndex)
{
  // The builders' messages become this filter's, with the leaf they concern.
  for (const timecritical::LeafBuildMessage& message : built.Messages)
  {
    if (message.IsError)
    {
      vtkErrorMacro("Leaf " << leafIndex << " (composite flat index) passes without a "
                            << "hierarchy: " << message.Text);
    }
    else
    {
      vtkWarningMacro("Leaf " << leafIndex << " (composite flat index): " << message.Text);
    }
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
