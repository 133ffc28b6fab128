// SPDX-License-Identifier: BSD-3-Clause
// vtkMultiresolutionPolyDataMapper hardware selection: leaf cells and points
// at any resolution, fronts, non-TOM leaves, id arrays, selection display and
// unpickable blocks.
#include "MultiresolutionMapperTestSupport.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositePolyDataMapper2.h"

//------------------------------------------------------------------------------
// Hardware selection (vtkHardwareSelector on the renderer, as ParaView selects):
// every selected (flat index, cell id) is a leaf cell that the mapper drew, at
// any resolution and for view-dependent fronts, and the cell under a drawn
// triangle's centre is that triangle's own.
namespace
{
// The leaf cells drawn for object i by the last render, each with the drawn
// triangle (its index among the object's drawn triangles) it became: a cell
// is drawn when its corners, moved up the substitution forest to vertices
// that the drawn triangles use, are the corners of a drawn triangle.
struct DrawnCells
{
  std::vector<std::array<uint32_t, 3>> Triangles; // leaf point ids
  std::map<vtkIdType, size_t> CellTriangle;       // drawn cell -> its drawn triangle
  std::set<uint32_t> Vertices;
};

DrawnCells GetDrawnCells(vtkMultiresolutionPolyDataMapper* mapper, vtkIdType object, vtkPolyData* leaf)
{
  DrawnCells drawn;
  const uint32_t* indices = mapper->GetLastIndices();
  size_t start = 0;
  for (vtkIdType i = 0; i < object; ++i)
  {
    start += 3 * static_cast<size_t>(mapper->GetObjectRenderedTriangles(i));
  }
  const auto offset = static_cast<uint32_t>(mapper->GetObjectVertexOffset(object));
  std::map<std::array<uint32_t, 3>, size_t> byCorners;
  for (vtkIdType t = 0; t < mapper->GetObjectRenderedTriangles(object); ++t)
  {
    std::array<uint32_t, 3> corners;
    for (int k = 0; k < 3; ++k)
    {
      corners[k] = indices[start + 3 * t + k] - offset;
      drawn.Vertices.insert(corners[k]);
    }
    drawn.Triangles.push_back(corners);
    std::sort(corners.begin(), corners.end());
    byCorners[corners] = static_cast<size_t>(t);
  }
  vtkDataArray* substitution =
    leaf->GetPointData()->GetArray(vtkTOMFieldData::SubstitutionArrayName());
  auto up = [&](vtkIdType v)
  {
    while (substitution && !drawn.Vertices.count(static_cast<uint32_t>(v)))
    {
      const auto parent = static_cast<vtkIdType>(substitution->GetComponent(v, 0));
      if (parent == v)
      {
        break;
      }
      v = parent;
    }
    return static_cast<uint32_t>(v);
  };
  for (vtkIdType c = 0; c < leaf->GetNumberOfPolys(); ++c)
  {
    vtkIdType npts;
    const vtkIdType* ids;
    leaf->GetPolys()->GetCellAtId(c, npts, ids);
    if (npts != 3)
    {
      continue;
    }
    std::array<uint32_t, 3> corners = { up(ids[0]), up(ids[1]), up(ids[2]) };
    std::sort(corners.begin(), corners.end());
    auto found = byCorners.find(corners);
    if (found != byCorners.end())
    {
      EXPECT_EQ(drawn.CellTriangle.count(c), 0u);
      drawn.CellTriangle[c] = found->second;
    }
  }
  // Every drawn triangle comes from exactly one cell.
  EXPECT_EQ(drawn.CellTriangle.size(), drawn.Triangles.size()) << "object " << object;
  return drawn;
}


// Checks the area selection of cells (and of points) and, for each object, the
// pixel at the centre of its largest drawn triangle facing the camera (+z).
void CheckSelection(vtkMultiresolutionPolyDataMapper* mapper, Scene& scene,
  const std::vector<vtkPolyData*>& leaves, const std::string& what, bool pixels = true)
{
  // What is drawn, from the triangle indices of a surface render.
  vtkProperty* property = scene.Actor->GetProperty();
  const int representation = property->GetRepresentation();
  property->SetRepresentationToSurface();
  scene.Render();
  std::map<unsigned int, vtkIdType> objectOfFlat;
  std::vector<DrawnCells> drawn;
  for (vtkIdType i = 0; i < mapper->GetNumberOfObjects(); ++i)
  {
    objectOfFlat[mapper->GetObjectFlatIndex(i)] = i;
    drawn.push_back(GetDrawnCells(mapper, i, leaves[i]));
  }
  property->SetRepresentation(representation);
  scene.Render();

  // Pairs that are not a drawn cell of an object: counted, the first one shown.
  size_t wrong = 0;
  std::string example;
  auto check = [&](const std::pair<unsigned int, vtkIdType>& pair, bool cell)
  {
    auto object = objectOfFlat.find(pair.first);
    const bool right = object != objectOfFlat.end() &&
      (cell ? drawn[object->second].CellTriangle.count(pair.second)
            : drawn[object->second].Vertices.count(static_cast<uint32_t>(pair.second))) == 1;
    if (!right && wrong++ == 0)
    {
      example = (cell ? "cell " : "point ") + std::to_string(pair.second) + " of flat index " +
        std::to_string(pair.first);
    }
    return right ? object->second : -1;
  };
  const auto cells = SelectArea(scene, vtkDataObject::FIELD_ASSOCIATION_CELLS);
  std::vector<size_t> selected(leaves.size(), 0);
  for (const auto& pair : cells)
  {
    const vtkIdType object = check(pair, true);
    selected[object >= 0 ? object : 0] += object >= 0 ? 1 : 0;
  }
  EXPECT_EQ(wrong, 0u) << what << ": " << wrong << " of " << cells.size()
                       << " selected cells not drawn, e.g. " << example;
  for (size_t i = 0; i < leaves.size(); ++i)
  {
    // Every object shows many of its cells (points: those of its visible vertices).
    EXPECT_GE(selected[i], std::min<size_t>(10, drawn[i].Triangles.size() / 8))
      << what << ": object " << i;
  }

  const auto points = SelectArea(scene, vtkDataObject::FIELD_ASSOCIATION_POINTS);
  EXPECT_GT(points.size(), 20u) << what;
  wrong = 0;
  for (const auto& pair : points)
  {
    check(pair, false);
  }
  EXPECT_EQ(wrong, 0u) << what << ": " << wrong << " of " << points.size()
                       << " selected points not drawn, e.g. " << example;
  if (!pixels)
  {
    return;
  }

  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(scene.Renderer);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  const int* size = scene.Window->GetSize();
  selector->SetArea(0, 0, static_cast<unsigned int>(size[0] - 1), static_cast<unsigned int>(size[1] - 1));
  ASSERT_TRUE(selector->CaptureBuffers());
  for (size_t i = 0; i < leaves.size(); ++i)
  {
    double largest = 0.0, aim[3] = { 0, 0, 0 };
    size_t target = 0;
    for (size_t t = 0; t < drawn[i].Triangles.size(); ++t)
    {
      double p[3][3];
      for (int k = 0; k < 3; ++k)
      {
        leaves[i]->GetPoint(drawn[i].Triangles[t][k], p[k]);
      }
      const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2] };
      const double v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2] };
      double n[3];
      vtkMath::Cross(u, v, n);
      const double area = vtkMath::Norm(n);
      if (area > largest && n[2] > 0.9 * area)
      {
        largest = area;
        target = t;
        for (int k = 0; k < 3; ++k)
        {
          aim[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0;
        }
      }
    }
    ASSERT_GT(largest, 0.0) << what << ": object " << i;
    vtkIdType cell = -1;
    for (const auto& entry : drawn[i].CellTriangle)
    {
      if (entry.second == target)
      {
        cell = entry.first;
      }
    }
    scene.Renderer->SetWorldPoint(aim[0], aim[1], aim[2], 1.0);
    scene.Renderer->WorldToDisplay();
    double display[3];
    scene.Renderer->GetDisplayPoint(display);
    const unsigned int position[2] = { static_cast<unsigned int>(std::lround(display[0])),
      static_cast<unsigned int>(std::lround(display[1])) };
    const vtkHardwareSelector::PixelInformation info = selector->GetPixelInformation(position);
    ASSERT_TRUE(info.Valid) << what << ": object " << i;
    EXPECT_EQ(info.Prop, scene.Actor.GetPointer());
    EXPECT_EQ(info.CompositeID, mapper->GetObjectFlatIndex(static_cast<vtkIdType>(i)))
      << what << ": object " << i;
    EXPECT_EQ(info.AttributeID, cell) << what << ": object " << i;
  }
}
}

TEST(MultiresolutionMapperSelection, AreaSelectionReportsLeafCellsAtAnyResolution)
{
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  Scene scene(mapper, 500);
  scene.SetCamera(0, 0, 7);
  const std::vector<vtkPolyData*> leaves(data.Leaves.begin(), data.Leaves.end());
  CheckSelection(mapper, scene, leaves, "full resolution");

  const double reduced[4] = { 0.3, 0.5, 0.15, 0.6 };
  mapper->SetObjectResolutions(reduced, 4);
  scene.Render();
  CheckSelection(mapper, scene, leaves, "reduced");
  for (vtkIdType i = 0; i < 4; ++i)
  {
    EXPECT_LT(mapper->GetObjectRenderedTriangles(i), mapper->GetObjectNumberOfTriangles(i));
  }

  // Slots moved by growth and shrinking: ids follow the slots, not object order.
  const double moved[4] = { 0.9, 0.1, 0.7, 0.2 };
  mapper->SetObjectResolutions(moved, 4);
  CheckSelection(mapper, scene, leaves, "moved slots");

  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  CheckSelection(mapper, scene, leaves, "wireframe", false);
  scene.Actor->GetProperty()->SetRepresentationToPoints();
  scene.Actor->GetProperty()->SetPointSize(3);
  CheckSelection(mapper, scene, leaves, "points", false);
}

TEST(MultiresolutionMapperSelection, FrontsAndNonTOMLeaves)
{
  // A view-dependent front, a TOM and a plain (non-TOM) surface.
  vtkNew<vtkMergeTreeBuilder> builder;
  builder->SetInputData(tt::MakeBumpySurface(0.5, 40, 30, -1.2, 0, 0, 7.0));
  builder->Update();
  auto tree = vtkSmartPointer<vtkPolyData>::New();
  tree->ShallowCopy(builder->GetOutput());
  auto tom = MakeTOM(0.45, 48, 32, 0, 0, 0);
  vtkNew<vtkSphereSource> plain;
  plain->SetCenter(1.2, 0, 0);
  plain->SetRadius(0.4);
  plain->Update();
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(3);
  blocks->SetBlock(0, tree);
  blocks->SetBlock(1, tom);
  blocks->SetBlock(2, plain->GetOutput());
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  EventCounter warnings(mapper, vtkCommand::WarningEvent); // the non-TOM leaf
  mapper->SetInputDataObject(blocks);
  mapper->UpdateObjects();
  EXPECT_EQ(warnings.Count, 1);
  mapper->SetResolution(0.3);
  Scene scene(mapper, 500);
  scene.SetCamera(0, 0, 7);
  scene.Render();
  ASSERT_TRUE(mapper->GetObjectIsViewDependent(0));
  ASSERT_FALSE(mapper->GetObjectIsTOM(2));
  EXPECT_LT(mapper->GetObjectRenderedTriangles(0), mapper->GetObjectNumberOfTriangles(0));
  const std::vector<vtkPolyData*> leaves = { tree, tom, plain->GetOutput() };
  CheckSelection(mapper, scene, leaves, "front");
  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  CheckSelection(mapper, scene, leaves, "front, wireframe", false);
}

TEST(MultiresolutionMapperSelection, IdArraysOfTheLeaves)
{
  // Cell and point id arrays (as ParaView names its original ids) are read
  // from each leaf at the leaf's own ids.
  NestedScene data;
  for (auto& leaf : data.Leaves)
  {
    vtkNew<vtkIdTypeArray> cellIds, pointIds;
    cellIds->SetName("OriginalCellIds");
    pointIds->SetName("OriginalPointIds");
    for (vtkIdType c = 0; c < leaf->GetNumberOfCells(); ++c)
    {
      cellIds->InsertNextValue(50000 + c);
    }
    for (vtkIdType p = 0; p < leaf->GetNumberOfPoints(); ++p)
    {
      pointIds->InsertNextValue(70000 + p);
    }
    leaf->GetCellData()->AddArray(cellIds);
    leaf->GetPointData()->AddArray(pointIds);
  }
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->SetCellIdArrayName("OriginalCellIds");
  mapper->SetPointIdArrayName("OriginalPointIds");
  mapper->UpdateObjects();
  const double r[4] = { 0.4, 0.6, 0.3, 0.5 };
  mapper->SetObjectResolutions(r, 4);
  Scene scene(mapper, 500);
  scene.SetCamera(0, 0, 7);
  scene.Render();
  std::map<unsigned int, vtkIdType> objectOfFlat;
  for (vtkIdType i = 0; i < 4; ++i)
  {
    objectOfFlat[mapper->GetObjectFlatIndex(i)] = i;
  }
  for (const int association :
    { vtkDataObject::FIELD_ASSOCIATION_CELLS, vtkDataObject::FIELD_ASSOCIATION_POINTS })
  {
    const bool cells = association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
    const auto pairs = SelectArea(scene, association);
    EXPECT_GT(pairs.size(), 100u);
    size_t wrong = 0;
    for (const auto& pair : pairs)
    {
      auto object = objectOfFlat.find(pair.first);
      const vtkIdType id = pair.second - (cells ? 50000 : 70000);
      // A TOM draws cells [0, drawn triangles) and points [0, drawn vertices).
      const bool right = object != objectOfFlat.end() && id >= 0 &&
        id < (cells ? mapper->GetObjectRenderedTriangles(object->second)
                    : mapper->GetObjectRenderedVertices(object->second));
      wrong += right ? 0 : 1;
    }
    EXPECT_EQ(wrong, 0u) << (cells ? "cells" : "points");
  }
}

TEST(MultiresolutionMapperSelection, SelectionDisplayOutlinesTheLeafCells)
{
  // vtkMapper::SetSelection: the cells selected by a node with a leaf's flat
  // index are outlined over that leaf, and only there.
  NestedScene data;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->UpdateObjects();
  mapper->SetResolution(0.5);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 5);
  scene.Actor->GetProperty()->SetSelectionColor(1.0, 0.0, 1.0, 1.0);
  scene.Render();
  auto pixels = [&]()
  {
    std::vector<unsigned char> rgb(3 * ImageSize * ImageSize);
    unsigned char* read = scene.Window->GetPixelData(0, 0, ImageSize - 1, ImageSize - 1, 0);
    std::copy(read, read + rgb.size(), rgb.begin());
    delete[] read;
    return rgb;
  };
  const std::vector<unsigned char> plain = pixels();

  auto select = [&](unsigned int flat)
  {
    vtkNew<vtkIdTypeArray> ids;
    for (vtkIdType c = 0; c < 40; ++c)
    {
      ids->InsertNextValue(c);
    }
    vtkNew<vtkSelectionNode> node;
    node->SetFieldType(vtkSelectionNode::CELL);
    node->SetContentType(vtkSelectionNode::INDICES);
    node->SetSelectionList(ids);
    node->GetProperties()->Set(vtkSelectionNode::COMPOSITE_INDEX(), static_cast<int>(flat));
    vtkNew<vtkSelection> selection;
    selection->AddNode(node);
    mapper->SetSelection(selection);
    scene.Render();
    return pixels();
  };
  // Leaf 0's display box.
  double box[4] = { 1e9, -1e9, 1e9, -1e9 };
  const double* b = data.Leaves[0]->GetBounds();
  for (int corner = 0; corner < 8; ++corner)
  {
    scene.Renderer->SetWorldPoint(b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + (corner >> 2)], 1);
    scene.Renderer->WorldToDisplay();
    const double* d = scene.Renderer->GetDisplayPoint();
    box[0] = std::min(box[0], d[0]);
    box[1] = std::max(box[1], d[0]);
    box[2] = std::min(box[2], d[1]);
    box[3] = std::max(box[3], d[1]);
  }
  const std::vector<unsigned char> outlined = select(mapper->GetObjectFlatIndex(0));
  EXPECT_EQ(mapper->GetNumberOfDrawCalls(), 2); // the triangles and the outlines
  int inside = 0, outside = 0;
  for (int y = 0; y < ImageSize; ++y)
  {
    for (int x = 0; x < ImageSize; ++x)
    {
      const size_t k = 3 * (static_cast<size_t>(y) * ImageSize + x);
      if (std::equal(&plain[k], &plain[k] + 3, &outlined[k]))
      {
        continue;
      }
      const bool in = x >= box[0] - 2 && x <= box[1] + 2 && y >= box[2] - 2 && y <= box[3] + 2;
      (in ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 30);
  EXPECT_EQ(outside, 0);
  // A node of no leaf's flat index outlines nothing.
  EXPECT_EQ(select(12345), plain);
}

//------------------------------------------------------------------------------
// Block pickability: an unpickable block is drawn but never selected, and the
// block behind it is selected through it, as with vtkCompositePolyDataMapper2.
namespace
{
// Flat indices: root 0, A 1, inner 2, B 3, C 4. A at the left; B at the
// right in front of C, which is larger and farther from the camera (+z).
struct PickScene
{
  PickScene()
  {
    this->Leaves = { MakeTOM(0.45, 40, 30, -1.0, 0, 0), MakeTOM(0.4, 40, 30, 1.0, 0, 1.0),
      MakeTOM(0.7, 44, 32, 1.0, 0, -1.0) };
    this->Inner->SetNumberOfBlocks(2);
    this->Inner->SetBlock(0, this->Leaves[1]);
    this->Inner->SetBlock(1, this->Leaves[2]);
    this->Input->SetNumberOfBlocks(2);
    this->Input->SetBlock(0, this->Leaves[0]);
    this->Input->SetBlock(1, this->Inner);
  }
  std::vector<vtkSmartPointer<vtkPolyData>> Leaves;
  vtkNew<vtkMultiBlockDataSet> Inner;
  vtkNew<vtkMultiBlockDataSet> Input;
};

// Flat indices selected in the whole window, or in a 5-pixel square around
// the projection of `world`.
std::set<unsigned int> SelectedBlocks(Scene& scene, int association, const double* world = nullptr)
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(scene.Renderer);
  selector->SetFieldAssociation(association);
  const int* size = scene.Window->GetSize();
  unsigned int area[4] = { 0, 0, static_cast<unsigned int>(size[0] - 1),
    static_cast<unsigned int>(size[1] - 1) };
  if (world)
  {
    scene.Renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
    scene.Renderer->WorldToDisplay();
    const double* display = scene.Renderer->GetDisplayPoint();
    const auto x = static_cast<unsigned int>(std::lround(display[0]));
    const auto y = static_cast<unsigned int>(std::lround(display[1]));
    area[0] = x - 2;
    area[1] = y - 2;
    area[2] = x + 2;
    area[3] = y + 2;
  }
  selector->SetArea(area);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  std::set<unsigned int> flats;
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    auto ids = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    if (ids && ids->GetNumberOfTuples() > 0)
    {
      flats.insert(static_cast<unsigned int>(
        node->GetProperties()->Get(vtkSelectionNode::COMPOSITE_INDEX())));
    }
  }
  return flats;
}

using Flats = std::set<unsigned int>;
}

TEST(MultiresolutionMapperSelection, UnpickableBlocksAreNeverSelected)
{
  PickScene data;
  vtkNew<vtkCompositeDataDisplayAttributes> attributes;
  vtkNew<vtkMultiresolutionPolyDataMapper> mapper;
  mapper->SetInputDataObject(data.Input);
  mapper->SetCompositeDataDisplayAttributes(attributes);
  Scene scene(mapper);
  scene.SetCamera(0, 0, 7);
  scene.Render();
  vtkNew<vtkCompositePolyDataMapper2> composite;
  composite->SetInputDataObject(data.Input);
  composite->SetCompositeDataDisplayAttributes(attributes);
  Scene reference(composite);
  reference.SetCamera(0, 0, 7);
  reference.Render();
  const double centerB[3] = { 1.0, 0.0, 1.4 }; // B's front, in front of C
  const int cells = vtkDataObject::FIELD_ASSOCIATION_CELLS;
  const int points = vtkDataObject::FIELD_ASSOCIATION_POINTS;

  // Everything pickable: B hides C at its centre.
  EXPECT_EQ(SelectedBlocks(scene, cells), Flats({ 1, 3, 4 }));
  EXPECT_EQ(SelectedBlocks(scene, cells, centerB), Flats({ 3 }));
  EXPECT_EQ(SelectedBlocks(reference, cells, centerB), Flats({ 3 }));
  scene.Render();
  const int drawn = scene.CountForeground();

  // B unpickable: never selected, C selected through it; B still drawn.
  mapper->SetBlockPickability(3, false);
  EXPECT_EQ(attributes->GetBlockPickability(data.Leaves[1]), false);
  scene.Render();
  EXPECT_EQ(scene.CountForeground(), drawn);
  EXPECT_FALSE(mapper->GetObjectPickability(1));
  EXPECT_TRUE(mapper->GetObjectPickability(2));
  EXPECT_TRUE(mapper->GetObjectVisibility(1));
  EXPECT_EQ(SelectedBlocks(scene, cells), Flats({ 1, 4 }));
  EXPECT_EQ(SelectedBlocks(scene, cells, centerB), Flats({ 4 }));
  EXPECT_EQ(SelectedBlocks(reference, cells), Flats({ 1, 4 }));
  EXPECT_EQ(SelectedBlocks(reference, cells, centerB), Flats({ 4 }));
  EXPECT_EQ(SelectedBlocks(scene, points), SelectedBlocks(reference, points));
  EXPECT_EQ(SelectedBlocks(scene, points).count(3), 0u);
  scene.Actor->GetProperty()->SetRepresentationToWireframe();
  EXPECT_EQ(SelectedBlocks(scene, cells), Flats({ 1, 4 }));
  scene.Actor->GetProperty()->SetRepresentationToSurface();

  // The parent's pickability passes to its children; a child's own wins.
  attributes->RemoveBlockPickabilities();
  attributes->SetBlockPickability(data.Inner, false);
  EXPECT_EQ(SelectedBlocks(scene, cells), Flats({ 1 }));
  EXPECT_EQ(SelectedBlocks(reference, cells), Flats({ 1 }));
  attributes->SetBlockPickability(data.Leaves[2], true);
  EXPECT_EQ(SelectedBlocks(scene, cells), Flats({ 1, 4 }));
  EXPECT_EQ(SelectedBlocks(reference, cells), Flats({ 1, 4 }));

  // Everything pickable again, with no render between the two selections.
  attributes->RemoveBlockPickabilities();
  EXPECT_EQ(SelectedBlocks(scene, cells), Flats({ 1, 3, 4 }));
  EXPECT_EQ(SelectedBlocks(scene, cells, centerB), Flats({ 3 }));

  // The flags follow the objects when they are read again (a changed leaf).
  mapper->SetBlockPickability(1, false);
  EXPECT_EQ(SelectedBlocks(scene, cells), Flats({ 3, 4 }));
  data.Leaves[0]->Modified();
  scene.Render();
  EXPECT_EQ(SelectedBlocks(scene, cells), Flats({ 3, 4 }));

  // A flat index of no block is an error.
  EventCounter errors(mapper, vtkCommand::ErrorEvent);
  mapper->SetBlockPickability(99, false);
  EXPECT_EQ(errors.Count, 1);
}
