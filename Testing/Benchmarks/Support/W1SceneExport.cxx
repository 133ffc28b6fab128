// SPDX-License-Identifier: BSD-3-Clause
#include "W1SceneExport.h"

#include "BenchmarkTiming.h"
#include "W1CameraPath.h"
#include "W1Scene.h"

#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>

#include <json/json.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
namespace
{
Json::Value ToJson(const Vec3& v)
{
  Json::Value out(Json::arrayValue);
  out.append(v.X);
  out.append(v.Y);
  out.append(v.Z);
  return out;
}

/// The bounds of the object's points moved by the placement's transform.
Json::Value PlacedBounds(vtkPolyData* object, const Placement& place)
{
  double bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  for (vtkIdType i = 0; i < object->GetNumberOfPoints(); ++i)
  {
    double p[3];
    object->GetPoint(i, p);
    place.Transform->TransformPoint(p, p);
    for (int k = 0; k < 3; ++k)
    {
      bounds[2 * k] = std::min(bounds[2 * k], p[k]);
      bounds[2 * k + 1] = std::max(bounds[2 * k + 1], p[k]);
    }
  }
  Json::Value out(Json::arrayValue);
  for (double b : bounds)
  {
    out.append(b);
  }
  return out;
}

Json::Value PlacementJson(vtkPolyData* object, const Placement& place)
{
  Json::Value out(Json::objectValue);
  out["x"] = place.X;
  out["z"] = place.Z;
  out["angle"] = place.Angle;
  Json::Value color(Json::arrayValue);
  for (unsigned char c : place.Color)
  {
    color.append(static_cast<int>(c));
  }
  out["color"] = color;
  Json::Value matrix(Json::arrayValue);
  vtkMatrix4x4* m = place.Transform->GetMatrix();
  for (int i = 0; i < 4; ++i)
  {
    Json::Value row(Json::arrayValue);
    for (int j = 0; j < 4; ++j)
    {
      row.append(m->GetElement(i, j));
    }
    matrix.append(row);
  }
  out["matrix"] = matrix;
  out["bounds"] = PlacedBounds(object, place);
  return out;
}

Json::Value LayoutJson(vtkPolyData* object, const Scene& scene)
{
  Json::Value layout(Json::objectValue);
  layout["grid"] = scene.GridSide;
  layout["spacing"] = scene.Spacing;
  layout["jitter"] = scene.Jitter;
  layout["extent"] = scene.Extent;
  layout["footprint_radius"] = scene.Radius;
  layout["height"] = scene.Height;
  layout["focus_object"] = scene.Focus;
  layout["center"] = ToJson(Vec3{ scene.Anchor[0], scene.Anchor[1], scene.Anchor[2] });
  Json::Value objects(Json::arrayValue);
  for (const Placement& place : scene.Objects)
  {
    objects.append(PlacementJson(object, place));
  }
  layout["objects"] = objects;
  return layout;
}

Json::Value PathJson(const W1CameraPath& path, int frames)
{
  Json::Value out(Json::objectValue);
  out["frames"] = frames;
  out["window"].append(WindowSize);
  out["window"].append(WindowSize);
  out["view_angle"] = ViewAngle;
  out["key_frames"]["A"] = path.GetKeyA();
  out["key_frames"]["B"] = path.GetKeyB();
  out["key_frames"]["turn"] = path.GetKeyTurn();
  out["key_frames"]["C"] = path.GetKeyC();
  Json::Value positions(Json::arrayValue), focalPoints(Json::arrayValue);
  for (int frame = 0; frame < frames; ++frame)
  {
    const Pose pose = path.At(frame);
    positions.append(ToJson(pose.Position));
    focalPoints.append(ToJson(pose.FocalPoint));
  }
  out["position"] = positions;
  out["focal_point"] = focalPoints;
  return out;
}
}

void WriteW1SceneJson(const std::string& file, const CowTOM& object, const Scene& scene,
  const W1CameraPath& path, int frames, unsigned seed)
{
  Json::Value root(Json::objectValue);
  root["generator"] = "WalkthroughBenchmark --write-scene";
  root["mesh"] = object.Source;
  root["substitute"] = object.Substitute;
  root["seed"] = seed;
  root["objects"] = static_cast<Json::UInt64>(scene.Objects.size());
  root["frames"] = frames;
  root["triangles_per_object"] = static_cast<Json::Int64>(object.Triangles);
  root["triangles"] = static_cast<Json::Int64>(scene.Triangles);
  root["points_per_object"] = static_cast<Json::Int64>(object.TOM->GetNumberOfPoints());
  root["layout"] = LayoutJson(object.TOM, scene);
  root["camera_path"] = PathJson(path, frames);

  std::ofstream stream(file);
  Json::StreamWriterBuilder builder;
  builder["indentation"] = " ";
  std::unique_ptr<Json::StreamWriter> writer(builder.newStreamWriter());
  writer->write(root, &stream);
  stream << "\n";
  if (!stream)
  {
    throw std::runtime_error("cannot write " + file);
  }
}
}
}
