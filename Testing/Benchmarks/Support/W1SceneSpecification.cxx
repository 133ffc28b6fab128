// SPDX-License-Identifier: BSD-3-Clause
#include "W1SceneSpecification.h"

#include "BenchmarkTiming.h"
#include "W1SceneSpecificationText.h"

#include <json/json.h>

#include <memory>
#include <sstream>
#include <stdexcept>

namespace timecritical
{
namespace benchmark
{
namespace
{
const Json::Value& Member(const Json::Value& object, const char* section, const char* key)
{
  const Json::Value& group = object[section];
  if (!group.isObject() || !group.isMember(key))
  {
    throw std::runtime_error(std::string("W1 scene specification: missing ") + section + "." + key);
  }
  return group[key];
}

double NumberAt(const Json::Value& object, const char* section, const char* key)
{
  const Json::Value& value = Member(object, section, key);
  if (!value.isNumeric())
  {
    throw std::runtime_error(
      std::string("W1 scene specification: ") + section + "." + key + " is not a number");
  }
  return value.asDouble();
}

int IntegerAt(const Json::Value& object, const char* section, const char* key)
{
  const Json::Value& value = Member(object, section, key);
  if (!value.isInt())
  {
    throw std::runtime_error(
      std::string("W1 scene specification: ") + section + "." + key + " is not an integer");
  }
  return value.asInt();
}

template <size_t N>
std::array<double, N> VectorAt(const Json::Value& object, const char* section, const char* key)
{
  const Json::Value& value = Member(object, section, key);
  if (!value.isArray() || value.size() != N)
  {
    throw std::runtime_error(std::string("W1 scene specification: ") + section + "." + key +
      " is not an array of " + std::to_string(N) + " numbers");
  }
  std::array<double, N> out{};
  for (Json::ArrayIndex i = 0; i < N; ++i)
  {
    if (!value[i].isNumeric())
    {
      throw std::runtime_error(
        std::string("W1 scene specification: ") + section + "." + key + " holds a non-number");
    }
    out[i] = value[i].asDouble();
  }
  return out;
}

Json::Value ParseDocument(const std::string& json)
{
  Json::CharReaderBuilder builder;
  std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  Json::Value root;
  std::string errors;
  if (!reader->parse(json.data(), json.data() + json.size(), &root, &errors) || !root.isObject())
  {
    throw std::runtime_error("W1 scene specification: not a JSON object: " + errors);
  }
  return root;
}

void ReadPlacement(const Json::Value& root, W1SceneSpecification& spec)
{
  spec.SubstituteLatitudes = IntegerAt(root, "substitute_object", "latitudes");
  spec.SubstituteLongitudes = IntegerAt(root, "substitute_object", "longitudes");
  spec.BumpAmplitude = NumberAt(root, "substitute_object", "bump_amplitude");
  spec.BumpFrequencies = VectorAt<3>(root, "substitute_object", "bump_frequencies");
  spec.SubstituteScale = VectorAt<3>(root, "substitute_object", "scale");
  spec.Gap = NumberAt(root, "placement", "gap");
  spec.JitterFractionOfGap = NumberAt(root, "placement", "jitter_fraction_of_gap");
  spec.FocusNear = VectorAt<2>(root, "placement", "focus_near");
  spec.Hue = VectorAt<2>(root, "colors", "hue");
  spec.Saturation = VectorAt<2>(root, "colors", "saturation");
  spec.Value = VectorAt<2>(root, "colors", "value");
}

void ReadCameraPath(const Json::Value& root, W1SceneSpecification& spec)
{
  spec.AOffset = VectorAt<3>(root, "camera_path", "a_offset");
  spec.TargetHeight = NumberAt(root, "camera_path", "target_height");
  spec.BDistance = NumberAt(root, "camera_path", "b_distance");
  spec.BHeight = NumberAt(root, "camera_path", "b_height");
  spec.TurnDirection = VectorAt<3>(root, "camera_path", "turn_direction");
  spec.TurnFocusDistance = NumberAt(root, "camera_path", "turn_focus_distance");
  spec.CDirection = VectorAt<3>(root, "camera_path", "c_direction");
  spec.CDistance = NumberAt(root, "camera_path", "c_distance");
  spec.CHeight = NumberAt(root, "camera_path", "c_height");
  spec.KeyB = NumberAt(root, "camera_path", "key_b");
  spec.FocusEaseScale = NumberAt(root, "camera_path", "focus_ease_scale");
}
}

W1SceneSpecification W1SceneSpecification::Parse(const std::string& json)
{
  const Json::Value root = ParseDocument(json);
  W1SceneSpecification spec;
  const int seed = IntegerAt(root, "defaults", "seed");
  if (seed < 0)
  {
    throw std::runtime_error("W1 scene specification: defaults.seed is negative");
  }
  spec.DefaultSeed = static_cast<unsigned>(seed);
  spec.DefaultObjects = IntegerAt(root, "defaults", "objects");
  spec.DefaultFrames = IntegerAt(root, "defaults", "frames");
  spec.WindowSize = IntegerAt(root, "view", "window_size");
  spec.ViewAngle = NumberAt(root, "view", "view_angle");
  spec.Background = VectorAt<3>(root, "view", "background");
  ReadPlacement(root, spec);
  ReadCameraPath(root, spec);
  return spec;
}

const W1SceneSpecification& W1SceneSpecification::Get()
{
  static const W1SceneSpecification spec = [] {
    W1SceneSpecification parsed = Parse(W1SceneSpecificationText);
    // The window size and view angle are compile-time constants of the
    // image code; the specification must agree with them.
    if (parsed.WindowSize != benchmark::WindowSize || parsed.ViewAngle != benchmark::ViewAngle)
    {
      throw std::runtime_error("W1Scene.json's view disagrees with BenchmarkTiming.h's "
                               "WindowSize and ViewAngle");
    }
    return parsed;
  }();
  return spec;
}
}
}
