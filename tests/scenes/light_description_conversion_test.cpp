// The automatic hierarchy for every light structure a scene can state: a lamp master placed
// 10,000 times renders like the same lights written bare, with a walk of a few dozen nodes per
// point, and no random union of bare lights, instances, affine subtrees and nested unions makes
// the walk meet every light.
#include "scenes/light_description_conversion.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "renderer/ray_scene.h"
#include "scenes/scene_instantiation.h"
#include "tests/lev/random_light_scenes.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

using scenes::SceneDescription;
using scenes::SceneNode;

constexpr int kLampsPerSide = 100;  // 10,000 lamps
constexpr float kLampSpacing = 4.0f;
constexpr float kLampHeight = 3.0f;  // a whole number: every light position is exact in float
constexpr glm::vec3 kLampIntensity{1.0f, 0.9f, 0.7f};
constexpr float kLampConeDegrees = 60.0f;
// rt and lev at tolerance 0 test all 10,000 lights at every point of the frame: 32 x 24 keeps
// that affordable under ASan (the test took 41 CPU s at 64 x 48).
constexpr int kFrameWidth = 32;
constexpr int kFrameHeight = 24;

// A street grid of lamps over a floor: each lamp a post and a light at its top. Instanced, one
// master holds both and is placed at every lamp; bare, a master holds the post alone and every
// light is written where the instance would put it (the file `levrt export` would write with
// the lamps flattened).
SceneDescription lamp_grid(bool instanced) {
  SceneDescription s;
  s.name = instanced ? "instanced lamps" : "bare lamps";
  const float side = kLampSpacing * static_cast<float>(kLampsPerSide);
  s.camera.position = {0.5f * side, -8.0f, 14.0f};
  s.camera.target = {0.5f * side, 30.0f, 0.0f};
  renderer::Material m;
  m.kd = 0.7f;
  m.ks = 0.3f;
  const std::uint32_t material = scenes::add_material(s, "m", m);
  const SceneNode post = scenes::cylinder_node(material, {0.0f, 0.0f, 0.0f},
                                               {0.0f, 0.0f, kLampHeight - 0.2f}, 0.1f, 8);
  const SceneNode light = scenes::translate_node(
      {0.0f, 0.0f, kLampHeight}, scenes::spot_light_node(kLampIntensity, kLampConeDegrees, 1.0f));
  const std::uint32_t lamp = scenes::add_master(
      s, "lamp", instanced ? scenes::union_node({post, light}) : scenes::union_node({post}));
  std::vector<SceneNode> parts;
  parts.push_back(scenes::quad_node(material, {-10.0f, -10.0f, 0.0f}, {side + 20.0f, 0.0f, 0.0f},
                                    {0.0f, side + 20.0f, 0.0f}));
  for (int j = 0; j < kLampsPerSide; ++j) {
    for (int i = 0; i < kLampsPerSide; ++i) {
      const glm::vec3 at{kLampSpacing * static_cast<float>(i), kLampSpacing * static_cast<float>(j),
                         0.0f};
      parts.push_back(scenes::translate_node(at, scenes::instance_node(lamp)));
      if (!instanced) {
        parts.push_back(scenes::translate_node(
            at + glm::vec3(0.0f, 0.0f, kLampHeight),
            scenes::spot_light_node(kLampIntensity, kLampConeDegrees, 1.0f)));
      }
    }
  }
  s.root = scenes::union_node(std::move(parts));
  return s;
}

TEST(LightDescriptionConversion, InstancedLampsRenderLikeTheSameLightsWrittenBare) {
  const renderer::Scene instanced = scenes::instantiate_scene(lamp_grid(true));
  const renderer::Scene bare = scenes::instantiate_scene(lamp_grid(false));
  ASSERT_EQ(instanced.lights.light_count, 10000u);
  ASSERT_EQ(bare.lights.light_count, 10000u);
  // The master stays shared: one light stored, not 10,000.
  EXPECT_EQ(instanced.lights.lights.size(), 1u);
  // The same world-space lights in the same order, so every sum adds the same terms in turn.
  const std::vector<lev::Light> instanced_lights = lev::flatten_lights(instanced.lights);
  const std::vector<lev::Light> bare_lights = lev::flatten_lights(bare.lights);
  ASSERT_EQ(instanced_lights.size(), bare_lights.size());
  for (std::size_t i = 0; i < bare_lights.size(); ++i) {
    ASSERT_EQ(instanced_lights[i].position, bare_lights[i].position) << i;
    ASSERT_EQ(instanced_lights[i].intensity, bare_lights[i].intensity) << i;
  }

  const renderer::RayScene instanced_rays(instanced);
  const renderer::RayScene bare_rays(bare);
  // rt, and lev at tolerance 0 and at a working tolerance: the same lights tested in the same
  // order, so the same image bit for bit.
  for (const auto& [method, tolerance] :
       {std::pair{lev::Method::rt, 0.0f}, std::pair{lev::Method::lev, 0.0f},
        std::pair{lev::Method::lev, 0.01f}}) {
    const renderer::Framebuffer a = render_test_image(instanced, instanced_rays, method, tolerance,
                                                      2, 1, kFrameWidth, kFrameHeight);
    const renderer::Framebuffer b =
        render_test_image(bare, bare_rays, method, tolerance, 2, 1, kFrameWidth, kFrameHeight);
    EXPECT_TRUE(bitwise_equal(a, b)) << lev::method_info(method).name << " " << tolerance;
    const renderer::FramebufferTotals ta = renderer::sum_framebuffer(a);
    const renderer::FramebufferTotals tb = renderer::sum_framebuffer(b);
    EXPECT_EQ(ta.lights_tested, tb.lights_tested) << lev::method_info(method).name;
    if (method == lev::Method::rt || tolerance == 0.0f) continue;
    ASSERT_GT(ta.shading_points, 0u);
    const double nodes_per_point =
        static_cast<double>(ta.nodes_visited) / static_cast<double>(ta.shading_points);
    EXPECT_LT(nodes_per_point, 100.0)
        << "bare: "
        << static_cast<double>(tb.nodes_visited) / static_cast<double>(tb.shading_points);
  }
  // lev_est stands for what it culls by a light per culled subtree, placed from the subtree's
  // aggregate; the subtrees of instances are boxed apart from the lights' own boxes, so its
  // estimate may differ in the last bits, never by more than a trace of a colour step.
  const renderer::Framebuffer a = render_test_image(instanced, instanced_rays, lev::Method::lev_est,
                                                    0.01f, 2, 1, kFrameWidth, kFrameHeight);
  const renderer::Framebuffer b = render_test_image(bare, bare_rays, lev::Method::lev_est, 0.01f, 2,
                                                    1, kFrameWidth, kFrameHeight);
  float max_difference = 0.0f;
  for (std::size_t i = 0; i < a.radiance_sum.size(); ++i) {
    const glm::vec3 d = glm::abs(a.radiance_sum[i] - b.radiance_sum[i]);
    max_difference = std::max({max_difference, d.x, d.y, d.z});
  }
  EXPECT_LT(max_difference, 1e-3f);
}

// A random light structure of the scene format: bare lights, instances of masters (themselves
// random structures), affine subtrees with rotation and scale, and nested unions of any width.
class RandomStructure {
 public:
  RandomStructure(std::uint64_t seed, SceneDescription& scene) : random_(seed), scene_(scene) {}

  SceneNode light() {
    const float intensity = std::pow(10.0f, random_.uniform(-1.0f, 0.5f));
    if (random_.integer(0, 2) == 0)
      return scenes::spot_light_node(glm::vec3(intensity), 60.0f, 1.0f);
    return scenes::point_light_node(glm::vec3(intensity));
  }

  scenes::Affine placement(float spread) {
    scenes::Affine a;
    a.translate = {random_.uniform(-spread, spread), random_.uniform(-spread, spread),
                   random_.uniform(0.0f, 4.0f)};
    if (random_.integer(0, 2) == 0) {
      a.rotate_axis = random_.direction();
      a.rotate_degrees = random_.uniform(0.0f, 360.0f);
    }
    if (random_.integer(0, 3) == 0) a.scale = std::pow(2.0f, random_.uniform(-1.0f, 1.0f));
    return a;
  }

  // About `lights` lights spread over [-spread, spread]^2.
  SceneNode subtree(int lights, float spread, int depth) {
    if (lights <= 1) return scenes::affine_node(placement(spread), light());
    if (depth > 5) {  // deep enough: a flat list
      std::vector<SceneNode> list;
      for (int k = 0; k < lights; ++k)
        list.push_back(scenes::affine_node(placement(spread), light()));
      return scenes::union_node(std::move(list));
    }
    const int kind = random_.integer(0, 4);
    if (kind == 0 && !masters_.empty() && lights <= 64) {
      const std::uint32_t m = masters_[static_cast<std::size_t>(
          random_.integer(0, static_cast<int>(masters_.size()) - 1))];
      return scenes::affine_node(placement(spread), scenes::instance_node(m));
    }
    if (kind == 1) {  // an affine subtree: a smaller structure moved, turned and scaled
      return scenes::affine_node(placement(spread), subtree(lights, 0.25f * spread, depth + 1));
    }
    // A union: many thin children (a flat list), two wide ones (a chain), or a mix.
    const int width =
        kind == 2 ? std::max(2, lights / random_.integer(1, 3)) : random_.integer(2, 9);
    std::vector<SceneNode> children;
    int left = lights;
    for (int c = 0; c < width && left > 0; ++c) {
      const int share =
          c + 1 == width ? left : std::max(1, left / (width - c) + random_.integer(-1, 1));
      children.push_back(subtree(share, spread, depth + 1));
      left -= share;
    }
    return scenes::union_node(std::move(children));
  }

  void add_masters(int count) {
    for (int m = 0; m < count; ++m) {
      masters_.push_back(scenes::add_master(scene_, "m" + std::to_string(m),
                                            subtree(random_.integer(1, 40), 2.0f, 3)));
    }
  }

 private:
  lev_test::Random random_;
  SceneDescription& scene_;
  std::vector<std::uint32_t> masters_;
};

using ConvertedLightKey = std::tuple<float, float, float, float>;
std::vector<ConvertedLightKey> sorted_converted_keys(const std::vector<lev::Light>& lights) {
  std::vector<ConvertedLightKey> keys;
  for (const lev::Light& l : lights)
    keys.emplace_back(l.position.x, l.position.y, l.position.z, l.intensity.x);
  std::sort(keys.begin(), keys.end());
  return keys;
}

TEST(LightDescriptionConversion, NoLightStructureMakesTheWalkMeetEveryLight) {
  constexpr float kTolerance = 0.01f;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SceneDescription s;
    s.camera.position = {0.0f, -10.0f, 5.0f};
    const std::uint32_t material = scenes::add_material(s, "m", renderer::Material{});
    RandomStructure structure(seed, s);
    structure.add_masters(static_cast<int>(seed % 4));
    s.root = scenes::union_node({scenes::quad_node(material, {-1, -1, 0}, {2, 0, 0}, {0, 2, 0}),
                                 structure.subtree(3000, 150.0f, 0)});
    const renderer::Scene scene = scenes::instantiate_scene(s);
    const std::vector<lev::Light> world = lev::flatten_lights(scene.lights);
    ASSERT_GT(world.size(), 1000u) << "seed " << seed;
    const lev::ExtentVolumes volumes = lev::fit_extent_volumes(scene.lights, kTolerance);
    lev_test::Random points(seed + 100);
    lev::WalkScratch scratch;
    std::uint64_t visited = 0, found_total = 0;
    constexpr int kPoints = 200;
    for (int k = 0; k < kPoints; ++k) {
      const glm::vec3 p(points.uniform(-150.0f, 150.0f), points.uniform(-150.0f, 150.0f),
                        points.uniform(0.0f, 4.0f));
      std::vector<lev::Light> found;
      lev::WalkCounters counters;
      lev::find_important_lights(scene.lights, volumes, kTolerance, p, scratch, found, counters);
      ASSERT_EQ(sorted_converted_keys(found),
                sorted_converted_keys(lev::important_lights_brute_force(world, p, kTolerance)))
          << "seed " << seed << " point " << k;
      visited += counters.nodes_visited;
      found_total += found.size();
    }
    // A few dozen lights matter at a point; the walk costs a few boxes per level for each.
    const double visited_avg = static_cast<double>(visited) / kPoints;
    const double found_avg = static_cast<double>(found_total) / kPoints;
    EXPECT_LT(visited_avg, 0.05 * static_cast<double>(world.size())) << "seed " << seed;
    EXPECT_LT(visited_avg, 40.0 + 12.0 * found_avg)
        << "seed " << seed << ", lights found " << found_avg;
  }
}

}  // namespace
