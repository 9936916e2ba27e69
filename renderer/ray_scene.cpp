#include "renderer/ray_scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "renderer/direction.h"
#include "renderer/texture.h"

namespace renderer {

glm::vec3 offset_ray_origin(const glm::vec3& position, const glm::vec3& normal,
                            float extra_magnitude, float offset_floor) {
  const glm::vec3 a = glm::abs(position);
  const float magnitude = std::max(std::max(a.x, a.y), a.z) + extra_magnitude;
  return position + normal * (offset_floor + 4e-6f * magnitude);
}

float offset_floor_for_extent(float extent) {
  constexpr float kUnitSceneFloor = 1e-5f;
  if (!(extent < 1.0f)) return kUnitSceneFloor;
  return kUnitSceneFloor * std::max(extent, std::numeric_limits<float>::min());
}

void RayScene::record_error(void* user, RTCError code, const char* message) {
  auto* log = static_cast<ErrorLog*>(user);
  std::lock_guard<std::mutex> lock(log->mutex);
  if (log->first_message.empty()) {
    log->first_message = "embree error " + std::to_string(static_cast<int>(code)) + ": " +
                         (message ? message : "(no message)");
  }
}

void RayScene::throw_if_error(const char* stage) const {
  std::lock_guard<std::mutex> lock(errors_->mutex);
  if (!errors_->first_message.empty()) {
    throw std::runtime_error(std::string(stage) + ": " + errors_->first_message);
  }
}

namespace {

// Embree's context with what the filters need to know about the ray (Embree hands the filter the
// context the query was given, so it may be extended).
struct RayContext {
  RTCIntersectContext embree;
  bool camera_ray = false;
};

RayContext make_context(bool camera_ray) {
  RayContext context;
  rtcInitIntersectContext(&context.embree);
  context.camera_ray = camera_ray;
  return context;
}

}  // namespace

// Rejects a hit on a culled back face (camera rays only) or in a cut-out's hole. Embree's Ng
// points to the side the triangle's vertices wind counter-clockwise on, glTF's front face; the
// ray and Ng are both in the instance's frame, where a similarity keeps the side.
void RayScene::filter_hit(const RTCFilterFunctionNArguments* args) {
  const auto& filter = *static_cast<const SurfaceFilter*>(args->geometryUserPtr);
  const Material& material = *filter.material;
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    if (material.cull_back_faces &&
        reinterpret_cast<const RayContext*>(args->context)->camera_ray) {
      const float facing =
          RTCHitN_Ng_x(args->hit, args->N, i) * RTCRayN_dir_x(args->ray, args->N, i) +
          RTCHitN_Ng_y(args->hit, args->N, i) * RTCRayN_dir_y(args->ray, args->N, i) +
          RTCHitN_Ng_z(args->hit, args->N, i) * RTCRayN_dir_z(args->ray, args->N, i);
      if (facing > 0.0f) {
        args->valid[i] = 0;
        continue;
      }
    }
    if (!material.is_cut_out()) continue;
    float alpha = material.alpha_factor;
    const TriangleMesh& mesh = *filter.mesh;
    if (filter.alpha_texture && !mesh.uvs.empty()) {
      const glm::uvec3 tri = mesh.triangles[RTCHitN_primID(args->hit, args->N, i)];
      const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
      const glm::vec2 uv =
          (1.0f - u - v) * mesh.uvs[tri.x] + u * mesh.uvs[tri.y] + v * mesh.uvs[tri.z];
      alpha *= sample_texture(*filter.alpha_texture, uv).x;
    }
    if (alpha < material.alpha_cutoff) args->valid[i] = 0;
  }
}

void RayScene::attach_filter(RTCGeometry geometry, const TriangleMesh& mesh) {
  const Material& material = scene_.materials.at(mesh.material);
  if (!material.cull_back_faces && !material.is_cut_out()) return;
  if (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED) == 0)
    throw std::runtime_error(
        "embree: built without filter functions, which cut-outs and "
        "single-sided materials need");
  SurfaceFilter& filter = filters_.emplace_back();
  filter.mesh = &mesh;
  filter.material = &material;
  if (material.is_cut_out() && material.alpha_texture >= 0)
    filter.alpha_texture = &scene_.textures.at(static_cast<std::size_t>(material.alpha_texture));
  rtcSetGeometryUserData(geometry, &filter);
  rtcSetGeometryIntersectFilterFunction(geometry, &RayScene::filter_hit);
  // Shadow rays meet both sides: only a cut-out's holes let them through.
  if (material.is_cut_out()) rtcSetGeometryOccludedFilterFunction(geometry, &RayScene::filter_hit);
}

RayScene::RayScene(const Scene& scene)
    : errors_(std::make_unique<ErrorLog>()),
      geometry_(scene.geometry),
      scene_(scene),
      instances_(scene.geometry.instances) {
  const Geometry& geometry = scene.geometry;
  device_ = rtcNewDevice(nullptr);
  if (!device_) {
    throw std::runtime_error("embree: cannot create a device (error " +
                             std::to_string(static_cast<int>(rtcGetDeviceError(nullptr))) + ")");
  }
  rtcSetDeviceErrorFunction(device_, &RayScene::record_error, errors_.get());

  for (const Prototype& prototype : geometry.prototypes) {
    RTCScene prototype_scene = rtcNewScene(device_);
    rtcSetSceneBuildQuality(prototype_scene, RTC_BUILD_QUALITY_HIGH);
    for (const TriangleMesh& mesh : prototype.meshes) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                            RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                            mesh.positions.size()));
      auto* t = static_cast<unsigned*>(
          rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                  3 * sizeof(unsigned), mesh.triangles.size()));
      if (!v || !t) {
        rtcReleaseGeometry(g);
        throw_if_error("embree mesh buffers");
        throw std::runtime_error("embree: cannot allocate mesh buffers");
      }
      for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        for (int c = 0; c < 3; ++c) v[3 * i + c] = mesh.positions[i][c];
      }
      for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        for (int c = 0; c < 3; ++c) t[3 * i + c] = mesh.triangles[i][c];
      }
      attach_filter(g, mesh);
      rtcCommitGeometry(g);
      rtcAttachGeometry(prototype_scene, g);  // geomID = index in prototype.meshes
      rtcReleaseGeometry(g);
    }
    if (!prototype.spheres.empty()) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                                            RTC_FORMAT_FLOAT4, 4 * sizeof(float),
                                                            prototype.spheres.size()));
      if (!v) {
        rtcReleaseGeometry(g);
        throw_if_error("embree sphere buffer");
        throw std::runtime_error("embree: cannot allocate the sphere buffer");
      }
      for (std::size_t i = 0; i < prototype.spheres.size(); ++i) {
        const Sphere& s = prototype.spheres[i];
        v[4 * i + 0] = s.centre.x;
        v[4 * i + 1] = s.centre.y;
        v[4 * i + 2] = s.centre.z;
        v[4 * i + 3] = s.radius;
      }
      rtcCommitGeometry(g);
      rtcAttachGeometry(prototype_scene, g);  // geomID = meshes.size()
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(prototype_scene);
    prototype_scenes_.push_back(prototype_scene);
    throw_if_error("embree prototype build");
  }

  top_ = rtcNewScene(device_);
  for (const PlacedPrototype& placed : instances_) {
    if (placed.prototype >= prototype_scenes_.size()) {
      throw std::invalid_argument("instance of prototype " + std::to_string(placed.prototype) +
                                  " which does not exist");
    }
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, prototype_scenes_[placed.prototype]);
    const lev::Similarity& xf = placed.world_from_object;
    float m[12];  // 3x4 column major: the three columns of rotation * scale, then translation
    for (int col = 0; col < 3; ++col) {
      for (int row = 0; row < 3; ++row) m[3 * col + row] = xf.rotation[col][row] * xf.scale;
    }
    m[9] = xf.translation.x;
    m[10] = xf.translation.y;
    m[11] = xf.translation.z;
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
    rtcCommitGeometry(g);
    rtcAttachGeometry(top_, g);  // instID = index in instances_
    rtcReleaseGeometry(g);
  }
  rtcCommitScene(top_);
  throw_if_error("embree scene build");
  RTCBounds bounds;
  rtcGetSceneBounds(top_, &bounds);
  const float extent = std::max({bounds.upper_x - bounds.lower_x, bounds.upper_y - bounds.lower_y,
                                 bounds.upper_z - bounds.lower_z});
  // An empty scene reports inverted bounds: it casts no secondary ray, any floor will do.
  offset_floor_ = offset_floor_for_extent(extent > 0.0f ? extent : 1.0f);
}

RayScene::~RayScene() {
  if (top_) rtcReleaseScene(top_);
  for (RTCScene s : prototype_scenes_) rtcReleaseScene(s);
  if (device_) rtcReleaseDevice(device_);
}

namespace {

RTCRayHit make_ray_hit(const Ray& ray) {
  RTCRayHit rh;
  rh.ray.org_x = ray.origin.x;
  rh.ray.org_y = ray.origin.y;
  rh.ray.org_z = ray.origin.z;
  rh.ray.dir_x = ray.direction.x;
  rh.ray.dir_y = ray.direction.y;
  rh.ray.dir_z = ray.direction.z;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.time = 0.0f;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.ray.id = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

}  // namespace

float RayScene::closest_distance(const Ray& ray) const {
  assert(castable(ray.origin, ray.direction));
  if (!castable(ray.origin, ray.direction)) return std::numeric_limits<float>::infinity();
  RayContext context = make_context(false);
  RTCRayHit rh = make_ray_hit(ray);
  rtcIntersect1(top_, &context.embree, &rh);
  return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? std::numeric_limits<float>::infinity()
                                                  : rh.ray.tfar;
}

bool RayScene::intersect(const Ray& ray, SurfaceHit& hit, bool camera_ray) const {
  assert(castable(ray.origin, ray.direction));
  if (!castable(ray.origin, ray.direction)) return false;
  RayContext context = make_context(camera_ray);
  RTCRayHit rh = make_ray_hit(ray);
  rtcIntersect1(top_, &context.embree, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

  const PlacedPrototype& placed = instances_[rh.hit.instID[0]];
  const Prototype& prototype = geometry_.prototypes[placed.prototype];
  const glm::mat3& rotation = placed.world_from_object.rotation;
  // Embree reports Ng in the instance's object space; similarities need only the rotation.
  // Ng is the unnormalised cross product of two edges: 1e-20 for a 1e-10 triangle, 1e24 for a
  // 1e12 one, both beyond what glm::normalize survives in the render mode.
  const glm::vec3 ng =
      robust_normalize(rotation * glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
  if (ng == glm::vec3(0.0f)) return false;
  glm::vec3 ns = ng;
  if (rh.hit.geomID < prototype.meshes.size()) {
    const TriangleMesh& mesh = prototype.meshes[rh.hit.geomID];
    const glm::uvec3 tri = mesh.triangles[rh.hit.primID];
    const float u = rh.hit.u, v = rh.hit.v;
    const glm::vec3 n =
        (1.0f - u - v) * mesh.normals[tri.x] + u * mesh.normals[tri.y] + v * mesh.normals[tri.z];
    const glm::vec3 unit = robust_normalize(n);
    if (unit != glm::vec3(0.0f)) ns = rotation * unit;
    hit.material = mesh.material;
    if (!mesh.uvs.empty())
      hit.uv = (1.0f - u - v) * mesh.uvs[tri.x] + u * mesh.uvs[tri.y] + v * mesh.uvs[tri.z];
  } else {
    hit.material = prototype.spheres[rh.hit.primID].material;
  }
  // Keep the interpolated normal on the geometric normal's side.
  if (glm::dot(ns, ng) < 0.0f) ns = -ns;
  hit.distance = rh.ray.tfar;
  hit.position = ray.origin + rh.ray.tfar * ray.direction;
  hit.geometric_normal = ng;
  hit.shading_normal = ns;
  return true;
}

bool RayScene::occluded(const glm::vec3& origin, const glm::vec3& direction,
                        float max_distance) const {
  // A shadow ray that cannot be cast lets no light through: it contributes nothing.
  assert(castable(origin, direction) && !std::isnan(max_distance));
  if (!castable(origin, direction) || std::isnan(max_distance)) return true;
  RayContext context = make_context(false);
  RTCRay r;
  r.org_x = origin.x;
  r.org_y = origin.y;
  r.org_z = origin.z;
  r.dir_x = direction.x;
  r.dir_y = direction.y;
  r.dir_z = direction.z;
  r.tnear = 0.0f;
  r.tfar = max_distance;
  r.time = 0.0f;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
  rtcOccluded1(top_, &context.embree, &r);
  return r.tfar < 0.0f;  // Embree writes -inf on a hit
}

}  // namespace renderer
