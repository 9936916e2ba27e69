#include "renderer/shading.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "renderer/direction.h"
#include "renderer/error_bound.h"
#include "renderer/pixel_inspection.h"

namespace renderer {
namespace {

class SurfacePoint final : public lev::ShadingPoint {
 public:
  // normal: the shading normal on the viewer's side; side: the geometric normal on that side,
  // along which shadow rays leave the surface.
  SurfacePoint(const RayScene& rays, const SurfaceHit& hit, const Material& material,
               const glm::vec3& normal, const glm::vec3& side, const glm::vec3& to_viewer,
               std::vector<LoggedRay>* ray_log)
      : rays_(rays),
        material_(material),
        normal_(normal),
        to_viewer_(to_viewer),
        position_(hit.position),
        shadow_origin_(offset_ray_origin(hit.position, side, hit.distance, rays.offset_floor())),
        ray_log_(ray_log) {}

  glm::vec3 position() const override { return position_; }
  glm::vec3 normal() const override { return normal_; }

  glm::vec3 unshadowed_radiance(const lev::Light& light) const override {
    const glm::vec3 to_light = light.position - position_;
    const float d2 = glm::dot(to_light, to_light);
    // A light exactly at the shading point has no direction to arrive from: it adds nothing
    // (and the irradiance clamp in lev keeps its neighbourhood finite).
    if (!(d2 > 0.0f)) return glm::vec3(0.0f);
    const glm::vec3 l = to_light / std::sqrt(d2);
    const float cos_theta = glm::dot(normal_, l);
    if (cos_theta <= 0.0f) return glm::vec3(0.0f);
    // Clamped to the largest float as the irradiance is: the irradiance (up to the largest
    // float) times a response of up to 2e6 (kd, colour and ks up to 1e3) overflowed to +inf,
    // which AST's estimate multiplied by a hit ratio of 0 (NaN pixels).
    constexpr float kLargest = std::numeric_limits<float>::max();
    return glm::min(lev::irradiance(light, position_) * response(l, cos_theta),
                    glm::vec3(kLargest));
  }

  // A sun: its irradiance times the response toward it, when the ray to infinity is free.
  glm::vec3 directional_radiance(const DirectionalLight& sun,
                                 lev::SelectionCounters& counters) const {
    const glm::vec3 l = -sun.direction;
    const float cos_theta = glm::dot(normal_, l);
    if (cos_theta <= 0.0f || !castable(shadow_origin_, l)) return glm::vec3(0.0f);
    ++counters.shadow_rays;
    constexpr float kToInfinity = std::numeric_limits<float>::infinity();
    if (ray_log_) ray_log_->push_back({shadow_origin_, kToInfinity, l, RayKind::shadow});
    if (rays_.occluded(shadow_origin_, l, kToInfinity)) return glm::vec3(0.0f);
    return sun.irradiance * response(l, cos_theta);
  }

  lev::SurfaceResponse surface_response() const override {
    lev::SurfaceResponse s;
    s.normal = normal_;
    s.mirrored_view = 2.0f * glm::dot(normal_, to_viewer_) * normal_ - to_viewer_;
    s.diffuse = material_.kd * material_.colour;
    // response() adds the specular lobe only for ks > 0.
    s.specular = std::max(material_.ks, 0.0f);
    s.shininess = material_.shininess;
    return s;
  }

  bool visible(const lev::Light& light) override {
    const glm::vec3 to_light = light.position - shadow_origin_;
    const float d = glm::length(to_light);
    if (!(d > 0.0f)) return true;
    // Stop just short of the light so a light resting on a surface is not hidden by it.
    const glm::vec3 direction = to_light / d;
    const float max_distance = d * (1.0f - 1e-5f);
    if (!castable(shadow_origin_, direction)) return false;
    if (ray_log_) ray_log_->push_back({shadow_origin_, max_distance, direction, RayKind::shadow});
    return !rays_.occluded(shadow_origin_, direction, max_distance);
  }

 private:
  // Phong's diffuse and specular response (thesis eq. 6) to light arriving along unit l; at most
  // largest_response(material) (error_bound.h), which the error bound relies on.
  glm::vec3 response(const glm::vec3& l, float cos_theta) const {
    glm::vec3 r = material_.kd * cos_theta * material_.colour;
    if (material_.ks > 0.0f) {
      const glm::vec3 mirror = 2.0f * cos_theta * normal_ - l;
      const float cos_alpha = glm::dot(mirror, to_viewer_);
      if (cos_alpha > 0.0f) r += glm::vec3(material_.ks * std::pow(cos_alpha, material_.shininess));
    }
    return r;
  }

  const RayScene& rays_;
  const Material& material_;
  glm::vec3 normal_, to_viewer_, position_, shadow_origin_;
  std::vector<LoggedRay>* ray_log_;
};

// What the surface emits toward the ray: its emission times the emission texture at uv.
glm::vec3 emitted_radiance(const Scene& scene, const Material& material, const glm::vec2& uv) {
  if (material.emission_texture < 0) return material.emission;
  return material.emission *
         sample_texture(scene.textures[static_cast<std::size_t>(material.emission_texture)], uv);
}

}  // namespace

glm::vec3 trace_radiance(TraceContext& context, const Ray& ray, int depth, PathCounters& counters,
                         float path_weight) {
  // A ray the float mode degenerated (a NaN or zero direction) is not cast and adds nothing.
  assert(castable(ray.origin, ray.direction));
  if (!castable(ray.origin, ray.direction)) return glm::vec3(0.0f);
  if (context.cancel && context.cancel->load(std::memory_order_relaxed)) return glm::vec3(0.0f);
  SurfaceHit hit;
  if (context.ray_log)
    context.ray_log->push_back({ray.origin, 0.0f, ray.direction, RayKind::closest_hit});
  // Depth 0 is the camera's ray: the one that does not see culled back faces.
  if (!context.rays.intersect(ray, hit, depth == 0)) return context.scene.background;
  ++counters.shading_points;
  Material material = context.scene.materials[hit.material];
  if (material.colour_texture >= 0) {
    material.colour *= sample_texture(
        context.scene.textures[static_cast<std::size_t>(material.colour_texture)], hit.uv);
  }
  if (material.unlit) return material.colour;
  const bool entering = glm::dot(hit.geometric_normal, ray.direction) < 0.0f;
  // Surfaces are two-sided: shade with the normal that faces the incoming ray.
  const glm::vec3 facing = entering ? hit.shading_normal : -hit.shading_normal;
  const glm::vec3 side = entering ? hit.geometric_normal : -hit.geometric_normal;
  const glm::vec3 to_viewer = -ray.direction;

  glm::vec3 radiance = material.ka * context.scene.ambient * material.colour;
  if (material.has_emission()) radiance += emitted_radiance(context.scene, material, hit.uv);
  SurfacePoint point(context.rays, hit, material, facing, side, to_viewer, context.ray_log);
  lev::MissedLight missed;
  if (context.missed_draws > 0) {
    missed.draws = context.missed_draws;
    missed.random = &context.missed_random;
    context.scratch.missed = &missed;
  }
  const std::size_t inspected = context.inspection ? context.inspection->size() : 0;
  if (context.inspection) {
    InspectedHit& inspection = context.inspection->emplace_back();
    inspection.depth = depth;
    inspection.path_weight = path_weight;
    inspection.position = hit.position;
    inspection.normal = facing;
    context.scratch.inspect = &inspection.record;
    context.scratch.walk.inspect = &inspection.record;
  }
  glm::vec3 direct(0.0f), hit_error_bound(0.0f);
  if (context.compute_error_bound) {
    // The direct term is weighed by path_weight in the pixel, so is what it may miss.
    glm::vec3 culled_irradiance(0.0f);
    lev::CulledRadianceBound culled_radiance;
    context.scratch.culled_radiance = &culled_radiance;
    direct = context.selector.direct_radiance(point, context.scratch, counters.selection,
                                              &culled_irradiance);
    context.scratch.culled_radiance = nullptr;
    hit_error_bound =
        path_weight * shading_error_bound(material, culled_irradiance, culled_radiance);
    counters.error_bound += hit_error_bound;
  } else {
    direct = context.selector.direct_radiance(point, context.scratch, counters.selection);
  }
  radiance += direct;
  context.scratch.missed = nullptr;
  if (context.inspection) {
    context.scratch.inspect = nullptr;
    context.scratch.walk.inspect = nullptr;
    InspectedHit& inspection = (*context.inspection)[inspected];
    inspection.direct_radiance = direct;
    inspection.error_bound = hit_error_bound;
    lev::complete_inspection(context.scene.lights, point, inspection.record, context.cancel);
  }
  if (missed.estimated) {
    counters.missed += path_weight * missed.radiance;
    counters.missed_variance += path_weight * path_weight * missed.variance;
  }
  // Suns are outside every method's selection: all methods add them alike, after the rest.
  for (const DirectionalLight& sun : context.scene.directional_lights) {
    radiance += point.directional_radiance(sun, counters.selection);
  }

  if (depth >= context.max_depth) return radiance;
  const float cos_i = glm::dot(to_viewer, facing);
  const float reflected_weight = path_weight * material.kr;
  if (material.kr > 0.0f && reflected_weight >= kSmallestVisibleWeight) {
    const Ray reflected{
        offset_ray_origin(hit.position, side, hit.distance, context.rays.offset_floor()),
        robust_normalize(2.0f * cos_i * facing - to_viewer)};
    if (castable(reflected.origin, reflected.direction)) {
      radiance +=
          material.kr * trace_radiance(context, reflected, depth + 1, counters, reflected_weight);
    }
  }
  const float transmitted_weight = path_weight * material.kt;
  if (material.kt > 0.0f && transmitted_weight >= kSmallestVisibleWeight) {
    const float eta = entering ? 1.0f / material.ior : material.ior;
    const float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
    Ray transmitted;
    if (k < 0.0f) {  // total internal reflection
      transmitted = {
          offset_ray_origin(hit.position, side, hit.distance, context.rays.offset_floor()),
          robust_normalize(2.0f * cos_i * facing - to_viewer)};
    } else {
      transmitted = {
          offset_ray_origin(hit.position, -side, hit.distance, context.rays.offset_floor()),
          robust_normalize(eta * ray.direction + (eta * cos_i - std::sqrt(k)) * facing)};
    }
    if (castable(transmitted.origin, transmitted.direction)) {
      radiance += material.kt *
                  trace_radiance(context, transmitted, depth + 1, counters, transmitted_weight);
    }
  }
  return radiance;
}

}  // namespace renderer
