// The externally authored glTF samples (../shared/gltf, see its README) render headless with their
// intensities as authored and the framing camera, and the coloured light pools lie where the
// extension puts them: under each point light, and along each spot's axis on the plane, full inside
// the inner cone and dark beyond the outer one, each in its own colour channel. Skipped when the
// folder is absent (LEVRT_GLTF_SAMPLES overrides the configured place).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/scene_file.h"
#include "scenes/scene_instantiation.h"

namespace {

namespace fs = std::filesystem;

fs::path samples_dir() {
  if (const char* env = std::getenv("LEVRT_GLTF_SAMPLES")) return env;
  return LEVRT_GLTF_SAMPLES_DIR;
}

struct SampleRender {
  renderer::Scene scene;
  std::unique_ptr<renderer::RayScene> rays;
  renderer::Framebuffer image;
  int width = 160, height = 120;
};

std::unique_ptr<SampleRender> render_sample(const std::string& relative,
                                            lev::Method method = lev::Method::rt,
                                            float tolerance = 0.0f) {
  auto r = std::make_unique<SampleRender>();
  r->scene =
      scenes::instantiate_scene(scenes::load_scene_file((samples_dir() / relative).string()));
  r->rays = std::make_unique<renderer::RayScene>(r->scene);
  renderer::RenderSettings rs;
  rs.width = r->width;
  rs.height = r->height;
  rs.method = method;
  rs.tolerance = tolerance;
  auto state = renderer::make_render_state(r->scene, *r->rays, rs);
  EXPECT_TRUE(renderer::render_pass(*state));
  r->image = renderer::render_framebuffer(*state);
  return r;
}

// The pixel whose primary hit lies nearest to `target`, and its radiance; fails when no pixel's
// hit comes within `within`.
glm::vec3 pixel_at(const SampleRender& r, const glm::vec3& target, float within) {
  float best = std::numeric_limits<float>::infinity();
  glm::vec3 radiance(0.0f);
  for (int y = 0; y < r.height; ++y) {
    for (int x = 0; x < r.width; ++x) {
      renderer::SurfaceHit hit;
      if (!r.rays->intersect(
              renderer::primary_ray(r.scene.camera, r.width, r.height, x + 0.5f, y + 0.5f), hit))
        continue;
      const float d = glm::length(hit.position - target);
      if (d < best) {
        best = d;
        radiance = r.image.radiance_sum[static_cast<std::size_t>(y * r.width + x)];
      }
    }
  }
  EXPECT_LT(best, within) << "no pixel sees " << target.x << " " << target.y << " " << target.z;
  return radiance;
}

int brightest_channel(const glm::vec3& c) {
  return c.x >= c.y && c.x >= c.z ? 0 : (c.y >= c.z ? 1 : 2);
}

#define SKIP_WITHOUT_SAMPLES() \
  if (!fs::is_directory(samples_dir())) GTEST_SKIP() << samples_dir() << " is absent"

TEST(GltfSamples, PointLightsPoolInTheirColourBelowThem) {
  SKIP_WITHOUT_SAMPLES();
  const auto r = render_sample("LightsPoint/LightsPoint.gltf");
  const std::vector<lev::Light> lights = lev::flatten_lights(r->scene.lights);
  ASSERT_EQ(lights.size(), 3u);
  float dimmest_pool = std::numeric_limits<float>::infinity();
  for (const lev::Light& light : lights) {
    EXPECT_FLOAT_EQ(light.range, 10.0f);
    const int channel = brightest_channel(light.intensity);
    // On the plane (y = 0) under the light: its own colour, bright.
    const glm::vec3 below = pixel_at(*r, {light.position.x, 0.0f, light.position.z}, 0.2f);
    EXPECT_EQ(brightest_channel(below), channel);
    EXPECT_GT(below[channel], 0.9f);
    dimmest_pool = std::min(dimmest_pool, below[channel]);
  }
  // A corner of the plane, 5 to 7 units from every light, is far dimmer (the intensities are
  // photometric, as authored: the comparison is relative).
  const glm::vec3 corner = pixel_at(*r, {4.8f, 0.0f, -4.8f}, 0.3f);
  EXPECT_LT(corner.x + corner.y + corner.z, 0.6f * dimmest_pool);
}

TEST(GltfSamples, SpotsPoolAlongTheirAxesWithTheSmoothCone) {
  SKIP_WITHOUT_SAMPLES();
  const auto r = render_sample("LightsSpot/LightsSpot.gltf");
  const std::vector<lev::Light> lights = lev::flatten_lights(r->scene.lights);
  ASSERT_EQ(lights.size(), 3u);
  int ranged = 0;
  for (const lev::Light& light : lights) {
    ASSERT_EQ(light.kind, lev::LightKind::spot);
    EXPECT_EQ(light.profile, lev::SpotProfile::smooth);
    EXPECT_NEAR(light.cos_cone_half_angle, std::cos(0.5235988f), 1e-6f);
    ranged += std::isfinite(light.range) ? 1 : 0;
    const int channel = brightest_channel(light.intensity);
    ASSERT_LT(light.direction.y, -0.99f);  // the spots point down at the plane
    const glm::vec3 centre(light.position.x, 0.0f, light.position.z);
    const glm::vec3 at_centre = pixel_at(*r, centre, 0.2f);
    EXPECT_EQ(brightest_channel(at_centre), channel);
    EXPECT_GT(at_centre[channel], 0.2f);
    // 10 degrees off the axis (outward) is inside the inner cone; 35 degrees (inward: outward it
    // would leave the plane) beyond the outer one, where the other pools' channels are not its own.
    const glm::vec3 outward = glm::normalize(glm::vec3(centre.x, 0.0f, centre.z));
    const float height = light.position.y;
    const glm::vec3 inner = pixel_at(*r, centre + outward * (height * std::tan(0.17f)), 0.2f);
    const glm::vec3 beyond = pixel_at(*r, centre - outward * (height * std::tan(0.61f)), 0.2f);
    EXPECT_GT(inner[channel], 0.5f * at_centre[channel]);
    EXPECT_EQ(beyond[channel], 0.0f);
  }
  EXPECT_EQ(ranged, 1);
}

TEST(GltfSamples, TheLampRendersLitByItsFiveLightsAndLevAtZeroIsRt) {
  SKIP_WITHOUT_SAMPLES();
  const auto rt = render_sample("LightsPunctualLamp/LightsPunctualLamp.gltf");
  EXPECT_EQ(rt->scene.lights.light_count, 5u);
  EXPECT_FALSE(rt->scene.textures.empty());
  int lit = 0;
  glm::vec3 sum(0.0f);
  for (const glm::vec3& p : rt->image.radiance_sum) {
    if (p.x + p.y + p.z > 0.05f) ++lit;
    sum += p;
  }
  // The lit lamp covers a visible part of the framed view; its warm bulb outshines the teal ones.
  EXPECT_GT(lit, rt->width * rt->height / 100);
  EXPECT_GT(sum.x, sum.z);
  const auto lev =
      render_sample("LightsPunctualLamp/LightsPunctualLamp.gltf", lev::Method::lev, 0.0f);
  EXPECT_EQ(std::memcmp(rt->image.radiance_sum.data(), lev->image.radiance_sum.data(),
                        rt->image.radiance_sum.size() * sizeof(glm::vec3)),
            0);
}

}  // namespace
