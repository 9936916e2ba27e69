#include "app/viewer/inspector_rows.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace app::viewer {
namespace {

constexpr int kOutlineSegments = 32;

float brightest_of(const glm::vec3& v) {
  return std::max({v.x, v.y, v.z});
}

// Two unit vectors perpendicular to unit `axis` and to each other.
void perpendiculars(const glm::vec3& axis, glm::vec3& u, glm::vec3& v) {
  const glm::vec3 other =
      std::abs(axis.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  u = glm::normalize(glm::cross(axis, other));
  v = glm::cross(axis, u);
}

// A world polyline's points that project, as image points (a point behind the camera ends the
// run: the outline is cut there).
void add_projected(const renderer::Camera& camera, int width, int height,
                   const std::vector<glm::vec3>& world,
                   std::vector<std::vector<glm::vec2>>& lines) {
  std::vector<glm::vec2> run;
  for (const glm::vec3& p : world) {
    glm::vec2 image;
    float depth = 0.0f;
    if (renderer::project_point(camera, width, height, p, image, depth)) {
      run.push_back(image);
    } else if (!run.empty()) {
      if (run.size() > 1) lines.push_back(run);
      run.clear();
    }
  }
  if (run.size() > 1) lines.push_back(run);
}

}  // namespace

std::vector<InspectorRow> inspector_rows(const renderer::PixelInspection& inspection,
                                         std::size_t keep, std::size_t* all_rows) {
  std::vector<InspectorRow> rows;
  for (const renderer::InspectedHit& hit : inspection.hits) {
    const float weight = hit.path_weight;
    for (const lev::ShadedLight& s : hit.record.shaded) {
      InspectorRow& row = rows.emplace_back();
      row.depth = hit.depth;
      row.light = s.light;
      row.role = lev::role_name(s.role);
      row.node = s.node;
      row.members = s.members.size();
      row.unshadowed = s.unshadowed_radiance * weight;
      row.seen = s.visible;
      row.to_pixel = s.contribution * weight;
    }
    for (const lev::InspectedLight& c : hit.record.culled) {
      InspectorRow& row = rows.emplace_back();
      row.depth = hit.depth;
      row.light = c.light;
      row.role = "culled";
      row.node = c.node;
      row.unshadowed = c.unshadowed_radiance * weight;
      row.seen = c.visible;
      row.to_pixel = c.visible_radiance() * weight;
    }
  }
  if (all_rows) *all_rows = rows.size();
  // Ranked by renderer::ranks_before (a total order, NaN last), equal rows in record order.
  std::vector<std::pair<renderer::ContributionRank, std::size_t>> ranks;
  ranks.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ranks.emplace_back(renderer::contribution_rank(glm::dvec3(rows[i].to_pixel),
                                                   glm::dvec3(rows[i].unshadowed), i),
                       i);
  }
  const std::size_t kept = std::min(keep, rows.size());
  std::partial_sort(
      ranks.begin(), ranks.begin() + static_cast<std::ptrdiff_t>(kept), ranks.end(),
      [](const auto& a, const auto& b) { return renderer::ranks_before(a.first, b.first); });
  std::vector<InspectorRow> top;
  top.reserve(kept);
  for (std::size_t i = 0; i < kept; ++i) top.push_back(std::move(rows[ranks[i].second]));
  return top;
}

float extent_radius(const lev::Light& light, float tolerance) {
  if (!(tolerance > 0.0f)) return std::numeric_limits<float>::infinity();
  const float radius = std::sqrt(std::max(brightest_of(light.intensity), 0.0f) / tolerance);
  return std::min(radius, light.range);
}

std::vector<std::vector<glm::vec2>> extent_outline(const renderer::Camera& camera, int width,
                                                   int height, const lev::Light& light,
                                                   float tolerance) {
  std::vector<std::vector<glm::vec2>> lines;
  const float radius = extent_radius(light, tolerance);
  if (!std::isfinite(radius) || !(radius > 0.0f)) return lines;
  const float pi = 3.14159265f;
  if (light.kind == lev::LightKind::spot && light.cos_cone_half_angle > -1.0f) {
    // The cone: its base circle at the sphere's radius along the axis, and four lines to it.
    const glm::vec3 axis = glm::normalize(light.direction);
    const float cos_half = std::clamp(light.cos_cone_half_angle, -1.0f, 1.0f);
    const float sin_half = std::sqrt(std::max(0.0f, 1.0f - cos_half * cos_half));
    glm::vec3 u, v;
    perpendiculars(axis, u, v);
    const glm::vec3 centre = light.position + axis * (radius * cos_half);
    const float rim = radius * sin_half;
    std::vector<glm::vec3> circle;
    for (int i = 0; i <= kOutlineSegments; ++i) {
      const float a = 2.0f * pi * static_cast<float>(i) / kOutlineSegments;
      circle.push_back(centre + rim * (std::cos(a) * u + std::sin(a) * v));
    }
    add_projected(camera, width, height, circle, lines);
    for (int i = 0; i < 4; ++i) {
      add_projected(camera, width, height,
                    {light.position, circle[static_cast<std::size_t>(i * kOutlineSegments / 4)]},
                    lines);
    }
    return lines;
  }
  // The sphere's silhouette: the circle around the centre perpendicular to the line of sight.
  const glm::vec3 to_camera = camera.position - light.position;
  const float distance = glm::length(to_camera);
  if (!(distance > radius)) return lines;  // the camera is inside: no outline
  const glm::vec3 axis = to_camera / distance;
  const float along = radius * radius / distance;  // the silhouette's plane, from the centre
  const float rim =
      radius * std::sqrt(std::max(0.0f, 1.0f - (radius / distance) * (radius / distance)));
  glm::vec3 u, v;
  perpendiculars(axis, u, v);
  std::vector<glm::vec3> circle;
  for (int i = 0; i <= kOutlineSegments; ++i) {
    const float a = 2.0f * pi * static_cast<float>(i) / kOutlineSegments;
    circle.push_back(light.position + axis * along + rim * (std::cos(a) * u + std::sin(a) * v));
  }
  add_projected(camera, width, height, circle, lines);
  return lines;
}

}  // namespace app::viewer
