// The lamp street class: one lamp master placed at every lamp and shared by the light hierarchy;
// the same town with its lights written bare renders the same image with a walk as short; its
// parameters make other towns and are checked.
#include "scenes/lamp_street.h"

#include <string>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "renderer/ray_scene.h"
#include "scenes/scene_instantiation.h"
#include "tests/support/framebuffer_compare.h"
#include "tests/support/test_render.h"

namespace {

double nodes_per_point(const renderer::Framebuffer& f) {
  const renderer::FramebufferTotals t = renderer::sum_framebuffer(f);
  return static_cast<double>(t.nodes_visited) / static_cast<double>(t.shading_points);
}

TEST(LampStreet, LevelsPlaceFourToTheLevelLampsOfOneSharedMaster) {
  for (int level : {3, 4, 5}) {
    const renderer::Scene instanced = scenes::build_lamp_street(level);
    EXPECT_EQ(instanced.lights.light_count, scenes::lamp_street_light_count(level));
    EXPECT_EQ(instanced.lights.lights.size(), 1u) << level;  // the master's one light
    const renderer::Scene bare = scenes::build_bare_lamp_street(level);
    EXPECT_EQ(bare.lights.light_count, scenes::lamp_street_light_count(level));
    EXPECT_EQ(bare.lights.lights.size(), scenes::lamp_street_light_count(level));
  }
  EXPECT_EQ(scenes::lamp_street_light_count(7), 16384u);
}

TEST(LampStreet, InstancedAndBareRenderTheSameImageWithShortWalks) {
  const renderer::Scene instanced = scenes::build_lamp_street(5);
  const renderer::Scene bare = scenes::build_bare_lamp_street(5);
  const renderer::RayScene instanced_rays(instanced), bare_rays(bare);
  for (const auto& [method, tolerance] :
       {std::pair{lev::Method::rt, 0.0f}, std::pair{lev::Method::lev, 0.01f}}) {
    const renderer::Framebuffer a =
        render_test_image(instanced, instanced_rays, method, tolerance, 2, 1);
    const renderer::Framebuffer b = render_test_image(bare, bare_rays, method, tolerance, 2, 1);
    EXPECT_TRUE(bitwise_equal(a, b)) << lev::method_info(method).name;
    if (method == lev::Method::rt) continue;
    EXPECT_LT(nodes_per_point(a), 100.0);
    EXPECT_LT(nodes_per_point(a), 3.0 * nodes_per_point(b));
    // Lamps light the street: most shading points test some lamp.
    EXPECT_GT(renderer::sum_framebuffer(a).lights_tested,
              renderer::sum_framebuffer(a).shading_points);
  }
}

TEST(LampStreet, ParametersMakeOtherTownsAndAreChecked) {
  scenes::LampStreetParams p;
  p.streets = 3;
  p.lamps_per_side = 10;
  EXPECT_EQ(scenes::instantiate_scene(scenes::describe_lamp_street_from(p)).lights.light_count,
            60u);
  scenes::LampStreetParams q = p;
  q.seed = 2;
  // Another seed, other houses: the descriptions differ somewhere in the boxes.
  bool differs = false;
  const auto a = scenes::describe_lamp_street_from(p), b = scenes::describe_lamp_street_from(q);
  ASSERT_EQ(a.root.children.size(), b.root.children.size());
  for (std::size_t i = 0; i < a.root.children.size(); ++i) {
    const auto* ba = std::get_if<scenes::BoxShape>(&a.root.children[i].data);
    const auto* bb = std::get_if<scenes::BoxShape>(&b.root.children[i].data);
    if (ba && bb && ba->hi != bb->hi) differs = true;
  }
  EXPECT_TRUE(differs);
  for (auto breaks : {+[](scenes::LampStreetParams& r) { r.streets = 0; },
                      +[](scenes::LampStreetParams& r) { r.lamps_per_side = -1; },
                      +[](scenes::LampStreetParams& r) { r.lamp_intensity = 0.0f; },
                      +[](scenes::LampStreetParams& r) { r.street_spacing_m = 5.0f; }}) {
    scenes::LampStreetParams r = p;
    breaks(r);
    EXPECT_THROW(scenes::describe_lamp_street_from(r), std::invalid_argument);
  }
  EXPECT_THROW(scenes::lamp_street_params(2), std::invalid_argument);
  EXPECT_THROW(scenes::lamp_street_params(8), std::invalid_argument);
}

}  // namespace
