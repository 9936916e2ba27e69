#include "scenes/gltf_lights.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "scenes/gltf_refusal.h"
#include "scenes/scene_validation.h"

namespace scenes {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void check_gltf_lights(const tinygltf::Model& model, const std::string& path) {
  for (std::size_t i = 0; i < model.lights.size(); ++i) {
    const tinygltf::Light& light = model.lights[i];
    // The light's glTF path, in every refusal below (most are the schema's backstops; the spot's
    // inner angle against its outer one is checked here alone).
    const std::string where = "extensions.KHR_lights_punctual.lights[" + std::to_string(i) + "]";
    if (!std::isfinite(light.intensity) || light.intensity < 0.0) {
      fail_gltf(path, where + ".intensity",
                gltf_number_text(light.intensity) + " (a number from 0 is expected)");
    }
    // levrt's bound on any light (kMaxIntensity; colours are at most 1), refused here with the
    // glTF path rather than by the scene check, which names the node levrt built from it.
    // Compared as levrt holds it, a float: the double 1e12 is above the float 1e12f (999999995904)
    // that the limit is, and the bound it names must itself be accepted, as a scene file's is.
    const bool beyond_float = light.intensity > static_cast<double>(FLT_MAX);
    if (beyond_float || static_cast<float>(light.intensity) > kMaxIntensity) {
      std::ostringstream limit;  // six digits: "1e+12", not the float's 9.99999996e+11
      limit << static_cast<double>(kMaxIntensity);
      fail_gltf(path, where + ".intensity",
                gltf_number_text(light.intensity) + " (levrt renders at most " + limit.str() + ")");
    }
    if (!std::isfinite(light.range) || light.range < 0.0)
      fail_gltf(path, where + ".range",
                gltf_number_text(light.range) + " (a number above 0 is expected)");
    if (!light.color.empty() && light.color.size() != 3) {
      fail_gltf(path, where + ".color",
                std::to_string(light.color.size()) + " values (3 are expected)");
    }
    for (const double c : light.color) {
      if (!std::isfinite(c) || c < 0.0) {
        fail_gltf(path, where + ".color",
                  gltf_number_text(c) + " (numbers from 0 to 1 are expected)");
      }
    }
    if (light.type == "spot") {
      const double inner = light.spot.innerConeAngle;
      const double outer = light.spot.outerConeAngle;
      // The extension: 0 <= inner < outer <= PI/2.
      if (!std::isfinite(outer) || !(outer > 0.0) || outer > kPi / 2.0) {
        fail_gltf(path, where + ".spot.outerConeAngle",
                  gltf_number_text(outer) + " (a number above 0 to pi/2 is expected)");
      }
      if (!std::isfinite(inner) || inner < 0.0 || inner >= outer) {
        fail_gltf(path, where + ".spot.innerConeAngle",
                  gltf_number_text(inner) + " (a number from 0 to below the outerConeAngle, " +
                      gltf_number_text(outer) + ", is expected)");
      }
    } else if (light.type != "point" && light.type != "directional") {
      fail_gltf(path, where + ".type",
                "'" + light.type + "' (one of point spot directional is expected)");
    }
  }
}

int gltf_light_of(const tinygltf::Model& model, const tinygltf::Node& node, const std::string& path,
                  const std::string& where) {
  const auto ext = node.extensions.find("KHR_lights_punctual");
  if (ext == node.extensions.end()) return -1;
  const tinygltf::Value& index = ext->second.Get("light");
  if (!index.IsNumber())
    fail_gltf(path, where + ".extensions.KHR_lights_punctual.light", "missing");
  const double value = index.GetNumberAsDouble();
  if (!(value >= 0.0) || value >= static_cast<double>(model.lights.size()) ||
      value != std::floor(value)) {
    fail_gltf(path, where + ".extensions.KHR_lights_punctual.light", gltf_number_text(value));
  }
  return static_cast<int>(value);
}

SceneNode gltf_light_node(const tinygltf::Light& light, const glm::vec3& intensity,
                          const glm::dvec3& position, const glm::dvec3& direction) {
  Affine place;
  place.translate = glm::vec3(position);
  // The rotation carrying levrt's spot axis -Z onto the light's world direction.
  const glm::dvec3 axis = glm::cross(glm::dvec3(0.0, 0.0, -1.0), direction);
  const double cosine = glm::clamp(-direction.z, -1.0, 1.0);
  if (glm::length(axis) > 1e-12) {
    place.rotate_axis = glm::vec3(glm::normalize(axis));
    place.rotate_degrees = static_cast<float>(std::acos(cosine) * 180.0 / kPi);
  } else if (cosine < 0.0) {
    place.rotate_axis = {1.0f, 0.0f, 0.0f};
    place.rotate_degrees = 180.0f;
  }
  // The extension: range 0 or absent is infinite. glTF's numbers are doubles and levrt's floats:
  // a valid light must stay one once rounded, so a positive range or cone angle is at least the
  // smallest normal float (1e-300 rounds to 0) and the inner cone stays below the outer one (0.5
  // and 0.49999999999 round to one float).
  const float range = light.range > 0.0 ? std::max(static_cast<float>(light.range), FLT_MIN)
                                        : std::numeric_limits<float>::infinity();
  if (light.type == "point") {
    SceneNode node = point_light_node(intensity);
    std::get<PointLightSource>(node.data).range = range;
    return affine_node(place, std::move(node));
  }
  const float outer =
      std::max(static_cast<float>(light.spot.outerConeAngle * 180.0 / kPi), FLT_MIN);
  SceneNode node = spot_light_node(intensity, outer, 0.0f);
  auto& spot = std::get<SpotLightSource>(node.data);
  spot.range = range;
  spot.inner_cone_degrees = std::min(static_cast<float>(light.spot.innerConeAngle * 180.0 / kPi),
                                     std::nextafter(outer, 0.0f));
  return affine_node(place, std::move(node));
}

}  // namespace scenes
