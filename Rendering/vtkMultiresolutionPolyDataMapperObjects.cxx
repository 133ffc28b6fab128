// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper: reading the input's leaves into objects
// (TOM copies shared between leaves, non-TOM triangles, merge trees, the
// skeleton the superclass draws from) and the per-object settings and queries.
#include "vtkMultiresolutionPolyDataMapperInternals.h"

#include "MergeTree.h"
#include "TOMMesh.h"
#include "vtkMergeTreeFieldData.h"
#include "vtkTOMFieldData.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSetAttributes.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataValidator.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::UpdateObjects()
{
  Internals& in = *this->Internal;
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    if (in.Input)
    {
      this->ReadObjects(nullptr);
    }
    return;
  }
  if (!this->Static)
  {
    int port = 0;
    if (vtkAlgorithm* producer = this->GetInputAlgorithm(0, 0, port))
    {
      producer->Update(port);
    }
  }
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  bool changed = input != in.Input || (input && input->GetMTime() != in.InputTime);
  for (size_t i = 0; !changed && i < in.Watched.size(); ++i)
  {
    changed = in.Watched[i].first->GetMTime() != in.Watched[i].second;
  }
  // Finished background builds are swapped in by reading the objects again.
  changed = this->TakeBuiltHierarchies() || changed || in.ForceRead;
  if (changed)
  {
    const auto start = std::chrono::steady_clock::now();
    this->ReadObjects(input);
    this->LastObjectReadEnd = std::chrono::steady_clock::now();
    this->UntakenObjectReadTime +=
      std::chrono::duration<double>(this->LastObjectReadEnd - start).count();
    ++this->NumberOfObjectReads;
  }
  this->UpdateBlockAttributes();
}

double vtkMultiresolutionPolyDataMapper::TakeObjectReadTime(
  std::chrono::steady_clock::time_point frameStart)
{
  const double seconds = this->LastObjectReadEnd < frameStart ? 0.0 : this->UntakenObjectReadTime;
  this->UntakenObjectReadTime = 0.0;
  return seconds;
}

//------------------------------------------------------------------------------
void vtkMultiresolutionPolyDataMapper::ReadObjects(vtkDataObject* input)
{
  Internals& in = *this->Internal;
  std::vector<double> previous(in.Objects.size());
  for (size_t i = 0; i < in.Objects.size(); ++i)
  {
    previous[i] = in.Objects[i].Resolution;
  }
  in.ReleaseObjects(input);
  in.PreviousFacts.swap(in.Facts);
  in.Facts.clear();
  in.Reader->StartReadingPass();
  Internals::Leaves leaves = in.CollectLeaves(this, input);
  std::vector<char> explained(leaves.size(), 0); // drawn without a hierarchy for a known reason
  if (in.BackgroundReset || !this->BackgroundBuilds)
  {
    in.ForgetBuilds();
  }
  if (this->BackgroundBuilds)
  {
    in.SubstituteBuiltLeaves(this, leaves, explained);
  }

  vtkTOMFieldData* reader = in.Reader;
  vtkNew<vtkMergeTreeFieldData> treeReader; // a local: it keeps a copy of the last tree read
  Internals::TOMCopies copies;
  in.ReserveTOMCopies(leaves);

  Internals::Offsets offsets;
  in.MaxObjectTriangles = 0;
  in.MaxSurfaceIndices = in.MaxWireIndices = in.MaxPointIndices = 0;
  for (size_t k = 0; k < leaves.size(); ++k)
  {
    const auto& leaf = leaves[k];
    vtkPolyData* poly = leaf.first;
    if (poly->GetNumberOfPoints() < 1)
    {
      continue; // empty leaf: not an object
    }
    if (poly->GetNumberOfPoints() > static_cast<vtkIdType>(UINT32_MAX) - offsets.Vertex)
    {
      vtkErrorMacro("More than 2^32 points in all leaves; the rest are not drawn.");
      break;
    }
    // Bad point ids would make VTK's bounds, the index buffers and the vertex
    // buffer builder read out of bounds; NaN coordinates would poison bounds and culling.
    const Internals::LeafFacts& facts = in.FactsOf(poly);
    if (!facts.Problem.empty())
    {
      vtkErrorMacro("Block " << leaf.second << " is not drawn: " << facts.Problem << ".");
      continue;
    }
    Internals::Object object = Internals::StartObject(poly, leaf.second, offsets);
    std::copy(facts.Bounds, facts.Bounds + 6, object.Bounds);
    object.IsTOM = reader->Read(poly);
    if (object.IsTOM)
    {
      in.ReadTOM(object, reader, copies);
    }
    else
    {
      in.ReadNonTOM(object, this, reader, explained[k] != 0);
    }
    if (object.IsTOM && vtkMergeTreeFieldData::HasMergeTreeArrays(poly))
    {
      in.ReadMergeTree(object, this, treeReader);
    }
    in.AddObject(std::move(object), previous, offsets);
  }
  in.FinishObjects(offsets);
  in.BuildSkeleton();
  in.ResolutionColors = nullptr;
  reader->ReleaseMesh(); // copied into the objects' arrays
  in.PreviousFacts.clear();
}

vtkMultiresolutionPolyDataMapper::Internals::LeafFacts&
vtkMultiresolutionPolyDataMapper::Internals::FactsOf(vtkPolyData* leaf)
{
  auto current = this->Facts.find(leaf);
  if (current != this->Facts.end() && current->second.Time == leaf->GetMTime())
  {
    return current->second;
  }
  LeafFacts& facts = this->Facts[leaf];
  auto previous = this->PreviousFacts.find(leaf);
  if (previous != this->PreviousFacts.end() && previous->second.Time == leaf->GetMTime())
  {
    facts = std::move(previous->second);
    return facts;
  }
  facts = LeafFacts(); // a stale entry of this read keeps nothing
  facts.Leaf = leaf;
  facts.Time = leaf->GetMTime();
  facts.Problem = vtkPolyDataValidator::Check(leaf);
  if (facts.Problem.empty() && leaf->GetNumberOfCells() > 0)
  {
    leaf->GetCellsBounds(facts.Bounds);
  }
  else if (facts.Problem.empty())
  {
    leaf->GetBounds(facts.Bounds);
  }
  return facts;
}

void vtkMultiresolutionPolyDataMapper::Internals::ReleaseObjects(vtkDataObject* input)
{
  this->Objects.clear();
  this->Watched.clear();
  // Released, not cleared: they are sized for this input below.
  std::vector<uint32_t>().swap(this->Substitution);
  std::vector<uint32_t>().swap(this->Triangles);
  std::vector<uint32_t>().swap(this->StaticTriangles);
  std::vector<uint32_t>().swap(this->StaticTriangleCells);
  this->Skeleton = nullptr;
  this->LayoutValid = false; // other objects: the next render lays the index buffer out
  this->CompactValid = false;
  this->Input = input;
  this->InputTime = input ? input->GetMTime() : 0;
  this->ForceRead = false;
  ++this->ResolutionVersion;
}

vtkMultiresolutionPolyDataMapper::Internals::Leaves
vtkMultiresolutionPolyDataMapper::Internals::CollectLeaves(
  vtkMultiresolutionPolyDataMapper* self, vtkDataObject* input)
{
  // Leaves in composite iteration order, the order vtkCellPicker reports.
  Leaves leaves;
  if (auto poly = vtkPolyData::SafeDownCast(input))
  {
    leaves.emplace_back(poly, 0u);
    return leaves;
  }
  auto composite = vtkCompositeDataSet::SafeDownCast(input);
  if (!composite)
  {
    return leaves;
  }
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(composite->NewIterator());
  it->SkipEmptyNodesOn();
  // Inner nodes are watched too: setting a block of a nested multiblock
  // modifies that node only, not the root.
  if (auto tree = vtkDataObjectTreeIterator::SafeDownCast(it))
  {
    tree->VisitOnlyLeavesOff();
  }
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    vtkDataObject* leaf = it->GetCurrentDataObject();
    this->Watched.emplace_back(leaf, leaf->GetMTime());
    if (vtkCompositeDataSet::SafeDownCast(leaf))
    {
      continue;
    }
    if (auto leafPoly = vtkPolyData::SafeDownCast(leaf))
    {
      leaves.emplace_back(leafPoly, it->GetCurrentFlatIndex());
    }
    else if (!this->WarnedNonPolyData)
    {
      vtkWarningWithObjectMacro(self, "Block " << it->GetCurrentFlatIndex() << " is a "
                                               << leaf->GetClassName()
                                               << ", not a vtkPolyData: it is not drawn.");
      this->WarnedNonPolyData = true;
    }
  }
  return leaves;
}

vtkMultiresolutionPolyDataMapper::Internals::TOMKey
vtkMultiresolutionPolyDataMapper::Internals::KeyOfTOM(vtkPolyData* poly)
{
  return TOMKey(poly->GetPolys(),
    poly->GetPointData()->GetAbstractArray(vtkTOMFieldData::SubstitutionArrayName()));
}

void vtkMultiresolutionPolyDataMapper::Internals::ReserveTOMCopies(const Leaves& leaves)
{
  // Replicas of a mesh often share their arrays: one copy each, into vectors
  // reserved for the leaves that carry TOM arrays (no growth slack). The
  // leaves hold the arrays while they are read, so their addresses are stable keys.
  std::set<TOMKey> seen;
  size_t substitution = 0;
  size_t triangles = 0;
  for (const auto& leaf : leaves)
  {
    if (vtkTOMFieldData::HasTOMArrays(leaf.first) && seen.insert(KeyOfTOM(leaf.first)).second)
    {
      substitution += static_cast<size_t>(leaf.first->GetNumberOfPoints());
      triangles += 3 * static_cast<size_t>(leaf.first->GetNumberOfPolys());
    }
  }
  this->Substitution.reserve(substitution);
  this->Triangles.reserve(triangles);
}

vtkMultiresolutionPolyDataMapper::Internals::Object
vtkMultiresolutionPolyDataMapper::Internals::StartObject(
  vtkPolyData* poly, unsigned int flatIndex, const Offsets& offsets)
{
  Object object;
  object.FlatIndex = flatIndex;
  object.Leaf = poly;
  object.NumberOfVerts = poly->GetNumberOfVerts();
  object.NumberOfLines = poly->GetNumberOfLines();
  object.NumberOfStrips = poly->GetNumberOfStrips();
  object.VertOffset = offsets.Vert;
  object.LineOffset = offsets.Line;
  object.StripOffset = offsets.Strip;
  object.CellOffset = offsets.Cell;
  object.VertexOffset = offsets.Vertex;
  object.NumberOfVertices = poly->GetNumberOfPoints();
  object.NumberOfPolys = poly->GetNumberOfPolys();
  object.PolyConnectivity = poly->GetPolys()->GetNumberOfConnectivityIds();
  return object;
}

void vtkMultiresolutionPolyDataMapper::Internals::ReadTOM(
  Object& object, vtkTOMFieldData* reader, TOMCopies& copies)
{
  const timecritical::TOMMesh& mesh = reader->GetMesh();
  object.BaseVertexCount = mesh.BaseVertexCount;
  auto found = copies.emplace(
    KeyOfTOM(object.Leaf), std::make_pair(this->Substitution.size(), this->Triangles.size() / 3));
  object.SubstitutionStart = found.first->second.first;
  object.TriangleStart = found.first->second.second;
  if (found.second)
  {
    this->Substitution.insert(
      this->Substitution.end(), mesh.Substitution.begin(), mesh.Substitution.end());
    this->Triangles.insert(this->Triangles.end(), mesh.Triangles.begin(), mesh.Triangles.end());
  }
  object.NumberOfTriangles = mesh.GetNumberOfTriangles();
  object.Coarsest = object.NumberOfTriangles > 0
    ? static_cast<double>(mesh.BaseTriangleCount) / object.NumberOfTriangles
    : 1.0;
}

void vtkMultiresolutionPolyDataMapper::Internals::ReadNonTOM(
  Object& object, vtkMultiresolutionPolyDataMapper* self, vtkTOMFieldData* reader, bool explained)
{
  // Leaves whose hierarchy is being built (or failed with an error) are not
  // warned about.
  if (!this->WarnedNonTOM && !explained)
  {
    vtkWarningWithObjectMacro(self, "Block " << object.FlatIndex
                                             << " is not a valid TOM, rendering it at full "
                                                "resolution: "
                                             << reader->GetErrorMessage());
    this->WarnedNonTOM = true;
  }
  // Fan triangles in merged point ids, dropping those with coincident
  // points as VTK's own index buffers do, so that primitive ids (and cell
  // colors) line up with VTK's cell map.
  object.TriangleStart = this->StaticTriangles.size() / 3;
  const auto vertexOffset = object.VertexOffset;
  vtkPoints* points = object.Leaf->GetPoints();
  vtkCellArray* polys = object.Leaf->GetPolys();
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  double p0[3], p1[3], p2[3];
  auto same = [](const double* a, const double* b)
  { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
  for (vtkIdType c = 0; c < object.NumberOfPolys; ++c)
  {
    polys->GetCellAtId(c, npts, ids);
    for (vtkIdType i = 2; i < npts; ++i)
    {
      points->GetPoint(ids[0], p0);
      points->GetPoint(ids[i - 1], p1);
      points->GetPoint(ids[i], p2);
      if (same(p0, p1) || same(p1, p2) || same(p0, p2))
      {
        continue;
      }
      this->StaticTriangles.push_back(static_cast<uint32_t>(ids[0] + vertexOffset));
      this->StaticTriangles.push_back(static_cast<uint32_t>(ids[i - 1] + vertexOffset));
      this->StaticTriangles.push_back(static_cast<uint32_t>(ids[i] + vertexOffset));
      this->StaticTriangleCells.push_back(static_cast<uint32_t>(c));
    }
  }
  object.NumberOfTriangles = static_cast<vtkIdType>(this->StaticTriangles.size() / 3) -
    static_cast<vtkIdType>(object.TriangleStart);
}

void vtkMultiresolutionPolyDataMapper::Internals::ReadMergeTree(
  Object& object, vtkMultiresolutionPolyDataMapper* self, vtkMergeTreeFieldData* treeReader)
{
  vtkPolyData* poly = object.Leaf;
  if (!treeReader->Read(poly))
  {
    if (!this->WarnedBadTree)
    {
      vtkWarningWithObjectMacro(self, "Block " << object.FlatIndex
                                               << " has invalid merge-tree arrays, drawing it "
                                               << "as a TOM: " << treeReader->GetErrorMessage());
      this->WarnedBadTree = true;
    }
    return;
  }
  // The refinement keeps its own copy of the points (float, as drawn).
  const timecritical::MergeTree& tree = treeReader->GetTree();
  const vtkIdType count = poly->GetNumberOfPoints();
  std::vector<float> xyz(3 * static_cast<size_t>(count));
  vtkDataArray* coordinates = poly->GetPoints()->GetData();
  for (vtkIdType p = 0; p < count; ++p)
  {
    for (int k = 0; k < 3; ++k)
    {
      xyz[3 * p + k] = static_cast<float>(coordinates->GetComponent(p, k));
    }
  }
  try
  {
    object.Refinement = std::make_unique<timecritical::ViewDependentRefinement>();
    object.Refinement->Initialize(treeReader->GetMesh(), tree, xyz.data());
    object.Levels = tree.Level;
    object.LevelCount = tree.LevelCount;
  }
  catch (const std::exception& e)
  {
    object.Refinement.reset();
    vtkWarningWithObjectMacro(self, "Block " << object.FlatIndex << ": merge tree not usable ("
                                             << e.what() << "); drawing it as a TOM.");
  }
}

void vtkMultiresolutionPolyDataMapper::Internals::AddObject(
  Object&& object, const std::vector<double>& previous, Offsets& offsets)
{
  const auto triangles = static_cast<size_t>(object.NumberOfTriangles);
  this->MaxObjectTriangles = std::max(this->MaxObjectTriangles, object.NumberOfTriangles);
  this->MaxSurfaceIndices += 3 * triangles;
  this->MaxWireIndices +=
    object.IsTOM ? 6 * triangles : 2 * static_cast<size_t>(object.PolyConnectivity);
  this->MaxPointIndices += object.IsTOM
    ? std::max(3 * triangles, static_cast<size_t>(object.NumberOfVertices))
    : static_cast<size_t>(object.PolyConnectivity);
  const size_t index = this->Objects.size();
  object.Resolution = index < previous.size() ? previous[index] : 1.0;
  offsets.Vertex += object.NumberOfVertices;
  offsets.Vert += object.NumberOfVerts;
  offsets.Line += object.NumberOfLines;
  offsets.Strip += object.NumberOfStrips;
  offsets.Cell += object.Leaf->GetNumberOfCells();
  this->Objects.push_back(std::move(object));
}

void vtkMultiresolutionPolyDataMapper::Internals::FinishObjects(const Offsets& offsets)
{
  this->TotalVertices = offsets.Vertex;
  this->TotalCells = offsets.Cell;
  // No-ops unless a leaf with TOM arrays was not valid; the static ones grew by push_back.
  this->Substitution.shrink_to_fit();
  this->Triangles.shrink_to_fit();
  this->StaticTriangles.shrink_to_fit();
  this->StaticTriangleCells.shrink_to_fit();

  // Views into the TOM arrays, now that they no longer move.
  for (auto& object : this->Objects)
  {
    if (object.IsTOM)
    {
      object.Traversal =
        timecritical::TOMTraversal(this->Substitution.data() + object.SubstitutionStart,
          static_cast<uint32_t>(object.NumberOfVertices),
          this->Triangles.data() + 3 * object.TriangleStart,
          static_cast<uint32_t>(object.NumberOfTriangles), object.BaseVertexCount);
    }
  }
  // The traversal writes batches in place and may use the output as scratch.
  vtkMultiresolutionMapperDetail::Grow(
    this->Scratch, 3 * static_cast<size_t>(this->MaxObjectTriangles));
  // Empty slots until the next render lays the index buffer out for these objects.
  this->Slots.Configure(std::vector<size_t>(this->Objects.size(), 0), this->Slots.GetCanPad());
}

void vtkMultiresolutionPolyDataMapper::Internals::BuildSkeleton()
{
  // The skeleton (see Skeleton): arrays common to all leaves, as
  // vtkAppendPolyData would keep them, without tuples; the leaves' other cells.
  this->HasOtherCells = false;
  if (this->Objects.empty())
  {
    return;
  }
  this->Skeleton = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> none;
  this->Skeleton->SetPoints(none);
  const auto parts = static_cast<int>(this->Objects.size());
  vtkDataSetAttributes::FieldList pointFields(parts);
  vtkDataSetAttributes::FieldList cellFields(parts);
  for (size_t k = 0; k < this->Objects.size(); ++k)
  {
    vtkPolyData* part = this->Objects[k].Leaf;
    if (k == 0)
    {
      pointFields.InitializeFieldList(part->GetPointData());
      cellFields.InitializeFieldList(part->GetCellData());
    }
    else
    {
      pointFields.IntersectFieldList(part->GetPointData());
      cellFields.IntersectFieldList(part->GetCellData());
    }
  }
  // One tuple of room: 0 would reserve the sum of the leaves' tuples.
  this->Skeleton->GetPointData()->CopyAllocate(pointFields, 1);
  this->Skeleton->GetCellData()->CopyAllocate(cellFields, 1);
  // Edge flags are ignored (see the class comment); VTK would read them per point.
  this->Skeleton->GetPointData()->SetActiveAttribute(-1, vtkDataSetAttributes::EDGEFLAG);

  vtkNew<vtkCellArray> verts, lines, strips;
  std::vector<vtkIdType> shifted;
  for (const auto& object : this->Objects)
  {
    vtkCellArray* from[3] = { object.Leaf->GetVerts(), object.Leaf->GetLines(),
      object.Leaf->GetStrips() };
    vtkCellArray* to[3] = { verts, lines, strips };
    for (int type = 0; type < 3; ++type)
    {
      vtkIdType npts = 0;
      const vtkIdType* ids = nullptr;
      for (vtkIdType c = 0; c < from[type]->GetNumberOfCells(); ++c)
      {
        from[type]->GetCellAtId(c, npts, ids);
        shifted.assign(ids, ids + npts);
        for (vtkIdType& id : shifted)
        {
          id += object.VertexOffset;
        }
        to[type]->InsertNextCell(npts, shifted.data());
      }
    }
  }
  this->HasOtherCells =
    verts->GetNumberOfCells() || lines->GetNumberOfCells() || strips->GetNumberOfCells();
  if (this->HasOtherCells)
  {
    this->Skeleton->SetVerts(verts);
    this->Skeleton->SetLines(lines);
    this->Skeleton->SetStrips(strips);
  }
}

//------------------------------------------------------------------------------
vtkIdType vtkMultiresolutionPolyDataMapper::GetNumberOfObjects() const
{
  return static_cast<vtkIdType>(this->Internal->Objects.size());
}

void vtkMultiresolutionPolyDataMapper::SetObjectResolution(vtkIdType i, double r)
{
  if (!this->IsValidObject(i))
  {
    return;
  }
  if (std::isnan(r))
  {
    vtkErrorMacro("Resolution of object " << i << " is NaN; ignored.");
    return;
  }
  r = std::min(1.0, std::max(0.0, r));
  // Resolutions are per-frame render state: they change the index buffer
  // only, so they do not Modified() the mapper (that would rebuild every
  // buffer and recompile the shaders).
  Internals::Object& object = this->Internal->Objects[i];
  if (object.Resolution != r)
  {
    object.Resolution = r;
    ++this->Internal->ResolutionVersion;
  }
}

double vtkMultiresolutionPolyDataMapper::GetObjectResolution(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].Resolution : 0.0;
}

void vtkMultiresolutionPolyDataMapper::SetResolution(double r)
{
  if (std::isnan(r))
  {
    vtkErrorMacro("Resolution is NaN; ignored.");
    return;
  }
  for (vtkIdType i = 0; i < this->GetNumberOfObjects(); ++i)
  {
    this->SetObjectResolution(i, r);
  }
}

void vtkMultiresolutionPolyDataMapper::SetObjectResolutions(const double* r, vtkIdType n)
{
  if (n != this->GetNumberOfObjects() || (n > 0 && !r))
  {
    vtkErrorMacro("SetObjectResolutions needs " << this->GetNumberOfObjects() << " values, got "
                                                << n << "; ignored.");
    return;
  }
  bool nan = false;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (std::isnan(r[i]))
    {
      nan = true;
      continue;
    }
    this->SetObjectResolution(i, r[i]);
  }
  if (nan)
  {
    vtkErrorMacro("NaN resolutions were ignored.");
  }
}

bool vtkMultiresolutionPolyDataMapper::IsValidObject(vtkIdType i) const
{
  if (i < 0 || i >= this->GetNumberOfObjects())
  {
    vtkErrorMacro(
      "Object index " << i << " out of range [0, " << this->GetNumberOfObjects() << ").");
    return false;
  }
  return true;
}

void vtkMultiresolutionPolyDataMapper::GetObjectBounds(vtkIdType i, double bounds[6]) const
{
  if (!this->IsValidObject(i))
  {
    vtkMath::UninitializeBounds(bounds);
    return;
  }
  std::copy(this->Internal->Objects[i].Bounds, this->Internal->Objects[i].Bounds + 6, bounds);
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectNumberOfTriangles(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].NumberOfTriangles : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectNumberOfVertices(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].NumberOfVertices : 0;
}

double vtkMultiresolutionPolyDataMapper::GetObjectCoarsestResolution(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].Coarsest : 1.0;
}

bool vtkMultiresolutionPolyDataMapper::GetObjectIsTOM(vtkIdType i) const
{
  return this->IsValidObject(i) && this->Internal->Objects[i].IsTOM;
}

unsigned int vtkMultiresolutionPolyDataMapper::GetObjectFlatIndex(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].FlatIndex : 0u;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectRenderedVertices(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].RenderedVertices : 0;
}

bool vtkMultiresolutionPolyDataMapper::GetObjectIsViewDependent(vtkIdType i) const
{
  return this->IsValidObject(i) && this->ViewDependentRefinement &&
    this->Internal->Objects[i].Refinement != nullptr;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectSplits(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].Splits : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectMerges(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].Merges : 0;
}

double vtkMultiresolutionPolyDataMapper::GetObjectRefinementTime(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].RefinementTime : 0.0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectRenderedTriangles(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].RenderedTriangles : 0;
}

vtkIdType vtkMultiresolutionPolyDataMapper::GetObjectVertexOffset(vtkIdType i) const
{
  return this->IsValidObject(i) ? this->Internal->Objects[i].VertexOffset : -1;
}

bool vtkMultiresolutionPolyDataMapper::GetObjectRewritten(vtkIdType i) const
{
  return this->IsValidObject(i) && this->Internal->Objects[i].Rewritten;
}
