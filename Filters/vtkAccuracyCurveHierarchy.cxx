// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAccuracyCurveHierarchy.h"

#include "AccuracyCurve.h"
#include "AccuracyCurveComposition.h"
#include "vtkAccuracyCurveFieldData.h"
#include "vtkTOMFieldData.h"

#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDataObjectTree.h"
#include "vtkDataObjectTreeIterator.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedIntArray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

vtkInformationKeyMacro(vtkAccuracyCurveHierarchy, LOD_NODE, Integer);

namespace
{
using timecritical::AccuracyCurve;
using timecritical::AccuracyCurveComposition;
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// What Compose found for one node.
struct Node
{
  AccuracyCurve Curve;
  double Size = 0.0;
  bool LOD = false;
  AccuracyCurveComposition::LODEnvelope Envelope;
  std::vector<int> EnvelopeChildPosition; ///< block position of each envelope child
};

/// A failure of Compose, with the message vtkErrorMacro shows.
struct ComposeError
{
  std::string Message;
};

/// Iterator over every node of a tree, empty ones and composite ones included.
vtkSmartPointer<vtkDataObjectTreeIterator> EveryNode(vtkDataObjectTree* tree, bool subtrees)
{
  vtkSmartPointer<vtkDataObjectTreeIterator> it;
  it.TakeReference(tree->NewTreeIterator());
  it->VisitOnlyLeavesOff();
  it->SkipEmptyNodesOff();
  it->SetTraverseSubTree(subtrees);
  return it;
}

/// The flat indices listed in the root's LODNodes array (throws ComposeError when malformed).
std::set<unsigned int> ListedLODNodes(vtkDataObject* root)
{
  std::set<unsigned int> listed;
  vtkAbstractArray* abstract =
    root->GetFieldData()->GetAbstractArray(vtkAccuracyCurveHierarchy::LODNodesArrayName());
  if (!abstract)
  {
    return listed;
  }
  vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
  if (!array || array->GetNumberOfComponents() != 1)
  {
    throw ComposeError{ "AccuracyCurveLODNodes must be a numeric array of flat indices" };
  }
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const double v = array->GetTuple1(i);
    if (!(v >= 0.0) || v != std::floor(v) || v > std::numeric_limits<unsigned int>::max())
    {
      std::ostringstream msg;
      msg << "AccuracyCurveLODNodes value " << i << " (" << v << ") is not a flat index";
      throw ComposeError{ msg.str() };
    }
    listed.insert(static_cast<unsigned int>(v));
  }
  return listed;
}

/// Triangles a plain polydata draws: polygons fanned, strips split.
double CountTriangles(vtkPolyData* data)
{
  double triangles = 0.0;
  for (vtkCellArray* cells : { data->GetPolys(), data->GetStrips() })
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      it->GetCurrentCell(size, ids);
      triangles += static_cast<double>(std::max<vtkIdType>(size - 2, 0));
    }
  }
  return triangles;
}

/// Composes the curves of one data object tree (the state of one Compose call).
class Composer
{
public:
  Composer(vtkDataObject* root, int kind, const double viewPoint[3], double minimumDistance)
    : Listed(ListedLODNodes(root))
    , Kind(kind)
    , ViewPoint{ viewPoint[0], viewPoint[1], viewPoint[2] }
    , MinimumDistance(minimumDistance)
  {
  }

  /// Composes the node at flatIndex into Nodes; returns the nodes of its subtree (itself included).
  unsigned int Visit(vtkDataObject* object, unsigned int flatIndex, bool markedLOD,
    vtkBoundingBox& bounds)
  {
    if (auto* tree = vtkDataObjectTree::SafeDownCast(object))
    {
      return this->VisitTree(tree, flatIndex, markedLOD || this->Listed.count(flatIndex), bounds);
    }
    this->VisitLeaf(object, flatIndex, bounds);
    return 1;
  }

  std::map<unsigned int, Node> Nodes;

private:
  unsigned int VisitTree(vtkDataObjectTree* tree, unsigned int flatIndex, bool lod,
    vtkBoundingBox& bounds)
  {
    std::vector<AccuracyCurve> curves;
    std::vector<double> sizes;
    std::vector<int> positions;
    vtkBoundingBox own;
    unsigned int next = flatIndex + 1;
    auto it = EveryNode(tree, false);
    int position = 0;
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem(), ++position)
    {
      const bool childMarked = it->HasCurrentMetaData() &&
        it->GetCurrentMetaData()->Get(vtkAccuracyCurveHierarchy::LOD_NODE()) == 1;
      const unsigned int childIndex = next;
      next += this->Visit(it->GetCurrentDataObject(), childIndex, childMarked, own);
      const auto found = this->Nodes.find(childIndex);
      if (found != this->Nodes.end() && !found->second.Curve.IsEmpty())
      {
        curves.push_back(found->second.Curve);
        sizes.push_back(found->second.Size);
        positions.push_back(position);
      }
    }
    Node node;
    node.LOD = lod;
    node.Size = own.IsValid() ? own.GetDiagonalLength() : 0.0;
    if (this->Kind == vtkAccuracyCurveHierarchy::RELATIVE && node.Size > 0.0)
    {
      for (size_t i = 0; i < curves.size(); ++i)
      {
        if (sizes[i] > 0.0)
        {
          curves[i] = curves[i].Rescale(sizes[i], node.Size);
        }
      }
    }
    if (lod)
    {
      node.Envelope = AccuracyCurveComposition::Minimum(curves);
      node.Curve = node.Envelope.Curve;
      node.EnvelopeChildPosition = positions;
    }
    else
    {
      node.Curve = AccuracyCurveComposition::Sum(curves);
    }
    bounds.AddBox(own);
    this->Nodes[flatIndex] = std::move(node);
    return next - flatIndex;
  }

  void VisitLeaf(vtkDataObject* object, unsigned int flatIndex, vtkBoundingBox& bounds)
  {
    auto* data = vtkDataSet::SafeDownCast(object);
    if (!data || data->GetNumberOfPoints() == 0)
    {
      return; // no curve, no extent
    }
    vtkBoundingBox box(data->GetBounds());
    bounds.AddBox(box);
    auto* polydata = vtkPolyData::SafeDownCast(data);
    if (!polydata)
    {
      return;
    }
    Node node;
    node.Size = box.GetDiagonalLength();
    if (vtkAccuracyCurveFieldData::HasAccuracyCurve(polydata) ||
      vtkTOMFieldData::HasTOMArrays(polydata))
    {
      vtkNew<vtkAccuracyCurveFieldData> reader;
      if (!reader->ReadOrDerive(polydata))
      {
        std::ostringstream msg;
        msg << "block " << flatIndex << ": " << reader->GetErrorMessage();
        throw ComposeError{ msg.str() };
      }
      node.Curve = reader->GetCurve();
      node.Size = reader->GetSize(); // the size its relative accuracies refer to
    }
    else
    {
      const double triangles = CountTriangles(polydata);
      if (triangles == 0.0)
      {
        return;
      }
      node.Curve = AccuracyCurve({ { 0.0, triangles, 0.0 } },
        std::numeric_limits<double>::infinity()); // exact: every accuracy
    }
    if (this->Kind == vtkAccuracyCurveHierarchy::ABSOLUTE && node.Size > 0.0)
    {
      double centre[3];
      box.GetCenter(centre);
      const double distance = AccuracyCurve::NearestDistance(
        std::sqrt(vtkMath::Distance2BetweenPoints(centre, this->ViewPoint)),
        box.GetDiagonalLength() / 2.0, this->MinimumDistance);
      node.Curve = node.Curve.ToAbsolute(node.Size, distance);
    }
    this->Nodes[flatIndex] = std::move(node);
  }

  std::set<unsigned int> Listed;
  int Kind;
  double ViewPoint[3];
  double MinimumDistance;
};
}

struct vtkAccuracyCurveHierarchy::Internals
{
  std::map<unsigned int, Node> Nodes;
  AccuracyCurve Empty;

  const Node* Find(unsigned int flatIndex) const
  {
    const auto it = this->Nodes.find(flatIndex);
    return it == this->Nodes.end() ? nullptr : &it->second;
  }
};

vtkStandardNewMacro(vtkAccuracyCurveHierarchy);

//------------------------------------------------------------------------------
vtkAccuracyCurveHierarchy::vtkAccuracyCurveHierarchy()
  : Internal(new Internals)
{
}

vtkAccuracyCurveHierarchy::~vtkAccuracyCurveHierarchy() = default;

//------------------------------------------------------------------------------
bool vtkAccuracyCurveHierarchy::MarkLODNode(
  vtkDataObjectTree* root, unsigned int flatIndex, bool lod)
{
  if (!root)
  {
    vtkGenericWarningMacro("MarkLODNode: no root given.");
    return false;
  }
  if (flatIndex > 0)
  {
    auto it = EveryNode(root, true);
    for (it->InitTraversal(); !it->IsDoneWithTraversal() && it->GetCurrentFlatIndex() != flatIndex;
         it->GoToNextItem())
    {
    }
    if (it->IsDoneWithTraversal() || !vtkDataObjectTree::SafeDownCast(it->GetCurrentDataObject()))
    {
      vtkErrorWithObjectMacro(root, "MarkLODNode: no composite block at flat index " << flatIndex
                                                                                    << ".");
      return false;
    }
    if (lod)
    {
      it->GetCurrentMetaData()->Set(LOD_NODE(), 1);
    }
    else if (it->HasCurrentMetaData())
    {
      it->GetCurrentMetaData()->Remove(LOD_NODE());
    }
  }
  std::set<unsigned int> listed;
  try
  {
    listed = ListedLODNodes(root);
  }
  catch (const ComposeError&)
  {
    // A malformed array is replaced.
  }
  if (lod)
  {
    listed.insert(flatIndex);
  }
  else
  {
    listed.erase(flatIndex);
  }
  vtkNew<vtkUnsignedIntArray> array;
  array->SetName(LODNodesArrayName());
  for (unsigned int index : listed)
  {
    array->InsertNextValue(index);
  }
  root->GetFieldData()->AddArray(array); // replaces an array of the same name
  return true;
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveHierarchy::IsLODNode(vtkDataObjectTree* root, unsigned int flatIndex)
{
  if (!root)
  {
    return false;
  }
  try
  {
    if (ListedLODNodes(root).count(flatIndex))
    {
      return true;
    }
  }
  catch (const ComposeError&)
  {
    // A malformed list marks nothing.
  }
  auto it = EveryNode(root, true);
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (it->GetCurrentFlatIndex() == flatIndex)
    {
      return it->HasCurrentMetaData() && it->GetCurrentMetaData()->Get(LOD_NODE()) == 1;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveHierarchy::Compose(vtkDataObject* data)
{
  this->Internal->Nodes.clear();
  if (!data)
  {
    vtkErrorMacro("Compose: no input data.");
    return false;
  }
  if (!(this->MinimumDistance > 0.0) || !std::isfinite(this->MinimumDistance) ||
    !vtkMath::IsFinite(this->ViewPoint[0]) || !vtkMath::IsFinite(this->ViewPoint[1]) ||
    !vtkMath::IsFinite(this->ViewPoint[2]))
  {
    vtkErrorMacro("Compose: MinimumDistance must be finite and positive and ViewPoint finite.");
    return false;
  }
  try
  {
    Composer composer(data, this->AccuracyKind, this->ViewPoint, this->MinimumDistance);
    vtkBoundingBox bounds;
    composer.Visit(data, 0, false, bounds);
    this->Internal->Nodes = std::move(composer.Nodes);
    return true;
  }
  catch (const ComposeError& e)
  {
    vtkErrorMacro("Compose: " << e.Message);
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro("Compose: " << e.what());
  }
  return false;
}

//------------------------------------------------------------------------------
const timecritical::AccuracyCurve& vtkAccuracyCurveHierarchy::GetRootCurve() const
{
  const Node* root = this->Internal->Find(0);
  return root ? root->Curve : this->Internal->Empty;
}

//------------------------------------------------------------------------------
const timecritical::AccuracyCurve* vtkAccuracyCurveHierarchy::GetCurve(unsigned int flatIndex) const
{
  const Node* node = this->Internal->Find(flatIndex);
  return node ? &node->Curve : nullptr;
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveHierarchy::HasCurve(unsigned int flatIndex) const
{
  const Node* node = this->Internal->Find(flatIndex);
  return node && !node->Curve.IsEmpty();
}

//------------------------------------------------------------------------------
double vtkAccuracyCurveHierarchy::GetNodeResources(unsigned int flatIndex, double accuracy) const
{
  const Node* node = this->Internal->Find(flatIndex);
  if (!node)
  {
    return NaN;
  }
  try
  {
    return node->Curve.GetResources(accuracy);
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro(<< e.what());
    return NaN;
  }
}

//------------------------------------------------------------------------------
double vtkAccuracyCurveHierarchy::GetNodeAccuracy(unsigned int flatIndex, double quota) const
{
  const Node* node = this->Internal->Find(flatIndex);
  if (!node)
  {
    return NaN;
  }
  try
  {
    return node->Curve.GetAccuracy(quota);
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro(<< e.what());
    return NaN;
  }
}

//------------------------------------------------------------------------------
double vtkAccuracyCurveHierarchy::GetNodeSize(unsigned int flatIndex) const
{
  const Node* node = this->Internal->Find(flatIndex);
  return node ? node->Size : NaN;
}

//------------------------------------------------------------------------------
bool vtkAccuracyCurveHierarchy::GetNodeIsLOD(unsigned int flatIndex) const
{
  const Node* node = this->Internal->Find(flatIndex);
  return node && node->LOD;
}

//------------------------------------------------------------------------------
int vtkAccuracyCurveHierarchy::GetCheapestChild(unsigned int flatIndex, double accuracy) const
{
  const Node* node = this->Internal->Find(flatIndex);
  if (!node || !node->LOD)
  {
    return -1;
  }
  try
  {
    const std::size_t child = node->Envelope.GetCheapestChild(accuracy);
    return child == AccuracyCurve::npos ? -1 : node->EnvelopeChildPosition[child];
  }
  catch (const std::invalid_argument& e)
  {
    vtkErrorMacro(<< e.what());
    return -1;
  }
}

//------------------------------------------------------------------------------
double vtkAccuracyCurveHierarchy::GetResources(double accuracy) const
{
  return this->GetNodeResources(0, accuracy);
}

double vtkAccuracyCurveHierarchy::GetAccuracy(double quota) const
{
  return this->GetNodeAccuracy(0, quota);
}

double vtkAccuracyCurveHierarchy::GetMaximumAccuracy() const
{
  const Node* root = this->Internal->Find(0);
  return root ? root->Curve.GetMaximumAccuracy() : NaN;
}

double vtkAccuracyCurveHierarchy::GetMinimumResources() const
{
  const Node* root = this->Internal->Find(0);
  return root ? root->Curve.GetMinimumResources() : NaN;
}

//------------------------------------------------------------------------------
void vtkAccuracyCurveHierarchy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AccuracyKind: " << (this->AccuracyKind == ABSOLUTE ? "absolute" : "relative")
     << "\n";
  os << indent << "ViewPoint: " << this->ViewPoint[0] << " " << this->ViewPoint[1] << " "
     << this->ViewPoint[2] << "\n";
  os << indent << "MinimumDistance: " << this->MinimumDistance << "\n";
  os << indent << "ComposedNodes: " << this->Internal->Nodes.size() << "\n";
}
