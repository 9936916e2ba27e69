// Every ray of levrt goes through Embree 3 here: the scene's prototypes become Embree scenes,
// placed once each by single-level instances. Embree reports errors through one callback that
// records the message; construction throws it, so a failure is never a silent black image.
// Meshes whose material culls back faces or cuts out holes (material.h) get an Embree filter
// function that rejects those hits during traversal, so every ray still makes one Embree query;
// other meshes have no filter and cost nothing more.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "renderer/camera.h"
#include "renderer/geometry.h"
#include "renderer/scene.h"

namespace renderer {

struct SurfaceHit {
  float distance = 0.0f;
  glm::vec3 position{0.0f};
  glm::vec3 geometric_normal{0.0f};  // world space, unit, as the surface is oriented
  glm::vec3 shading_normal{0.0f};    // world space, unit, interpolated
  std::uint32_t material = 0;
  glm::vec2 uv{0.0f};  // interpolated texture coordinates (0 where the mesh has none)
};

// Origin offset along the normal that keeps a secondary ray off the surface it leaves: a floor
// (RayScene::offset_floor, which follows the scene's size) plus ~32 float ulps of the largest
// coordinate, so it holds at large coordinates too.
glm::vec3 offset_ray_origin(const glm::vec3& position, const glm::vec3& normal,
                            float extra_magnitude, float offset_floor);

// The offset floor of a scene whose geometry spans extent units (its bounding box's largest
// side): 1e-5 for scenes of a unit or more (every built-in model; their images keep every bit),
// 1e-5 * extent below, so a scene scaled by 1e-6 is offset as it is at its own size instead of
// by half its width.
float offset_floor_for_extent(float extent);

class RayScene {
 public:
  // Keeps references to the scene's geometry, materials and textures: the scene outlives it.
  explicit RayScene(const Scene& scene);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // Closest hit along the ray, or false. A camera ray does not see culled back faces.
  bool intersect(const Ray& ray, SurfaceHit& hit, bool camera_ray = false) const;
  // True when something lies on the segment origin + t * direction, t in (0, max_distance).
  bool occluded(const glm::vec3& origin, const glm::vec3& direction, float max_distance) const;
  // The bare Embree query behind intersect: the closest hit's distance (+inf for a miss), with
  // none of the hit record work. For measuring Embree alone (ray_log.h).
  float closest_distance(const Ray& ray) const;

  float offset_floor() const { return offset_floor_; }

 private:
  struct ErrorLog {
    std::mutex mutex;
    std::string first_message;
  };
  // What the filter of one mesh needs (its user data); kept in a deque, so addresses stay.
  struct SurfaceFilter {
    const TriangleMesh* mesh = nullptr;
    const Material* material = nullptr;
    const Texture* alpha_texture = nullptr;
  };
  static void record_error(void* user, RTCError code, const char* message);
  static void filter_hit(const RTCFilterFunctionNArguments* args);
  void attach_filter(RTCGeometry geometry, const TriangleMesh& mesh);
  void throw_if_error(const char* stage) const;

  std::unique_ptr<ErrorLog> errors_;
  RTCDevice device_ = nullptr;
  RTCScene top_ = nullptr;
  std::vector<RTCScene> prototype_scenes_;
  float offset_floor_ = 1e-5f;
  const Geometry& geometry_;
  const Scene& scene_;
  std::deque<SurfaceFilter> filters_;
  std::vector<PlacedPrototype> instances_;
};

}  // namespace renderer
