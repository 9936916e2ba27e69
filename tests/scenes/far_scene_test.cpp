// One small scene rendered three ways: at the origin, translated to coordinates near 1e6, and
// scaled by 1e-3 (camera and lights moved and scaled with it). Floats near 1e6 are 0.0625 apart
// and at 1e-3 scale the scene is smaller than fixed ray offsets, so both tempt shadow acne (a lit
// surface shadowing itself) and light leaks (shadow rays starting past the occluder). The images
// must match the one at the origin but for a few edge pixels.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "renderer/pixel_error.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/scene_instantiation.h"
#include "scenes/scene_models.h"

namespace {

// 1e6 - 64: every coordinate of the moved scene stays within the loader's kMaxCoordinate.
constexpr float kFarOffset = 999936.0f;

// A floor, a shiny box and a sphere, lit by point lights (one grazing, for long shadows) and a
// spotlight. `placement` moves and scales all of it; the camera follows.
scenes::SceneDescription shadow_scene(const scenes::Affine& placement) {
  scenes::SceneDescription d;
  d.name = "far";
  renderer::Material grey;
  const std::uint32_t floor_material = scenes::add_material(d, "grey", grey);
  renderer::Material shiny;
  shiny.ks = 0.4f;
  shiny.kr = 0.3f;
  const std::uint32_t box_material = scenes::add_material(d, "shiny", shiny);

  std::vector<scenes::SceneNode> content;
  content.push_back(scenes::quad_node(floor_material, {-10, -10, 0}, {20, 0, 0}, {0, 20, 0}));
  content.push_back(scenes::box_node(box_material, {-2, -2, 0}, {0, 0, 2}));
  content.push_back(scenes::sphere_node(floor_material, {3, 1, 1}, 1.0f));
  content.push_back(scenes::translate_node({0, 4, 3}, scenes::point_light_node({4, 4, 4})));
  content.push_back(scenes::translate_node({-4, -4, 5}, scenes::point_light_node({6, 5, 4})));
  content.push_back(scenes::translate_node({4, -3, 2}, scenes::point_light_node({2, 2, 3})));
  content.push_back(scenes::translate_node({-5, -1, 0.5f}, scenes::point_light_node({1, 1, 1})));
  content.push_back(
      scenes::translate_node({-5, 5, 6}, scenes::spot_light_node({20, 20, 20}, 40.0f, 2.0f)));
  d.root = scenes::affine_node(placement, scenes::union_node(std::move(content)));

  const lev::Similarity xf = scenes::affine_similarity(placement);
  d.camera.position = lev::apply_point(xf, {0, -18, 9});
  d.camera.target = lev::apply_point(xf, {0, 0, 0});
  return d;
}

scenes::Affine at_origin() {
  return {};
}

scenes::Affine far_away() {
  scenes::Affine a;
  a.translate = glm::vec3(kFarOffset);
  return a;
}

scenes::Affine scaled(float scale) {
  scenes::Affine a;
  a.scale = scale;
  return a;
}

std::vector<std::uint8_t> render_far_rgb8(const scenes::SceneDescription& description,
                                          lev::Method method) {
  renderer::Scene scene = scenes::instantiate_scene(description);
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs;
  rs.width = 160;
  rs.height = 120;
  rs.method = method;
  rs.tolerance = 0.01f;
  auto state = renderer::make_render_state(scene, rays, rs);
  EXPECT_TRUE(renderer::render_pass(*state));
  return renderer::framebuffer_rgb8(renderer::render_framebuffer(*state));
}

struct Difference {
  double differing_fraction = 0.0;  // pixels off by more than 1% (|dR|+|dG|+|dB| > 7.65)
  int brighter = 0;                 // pixels lit well above the reference: leaks
  int darker = 0;                   // pixels well below it: acne, lost light
};

// "Well" above or below: by more than 10% of 765 in total, the size of a shadow's step.
Difference compare(const std::vector<std::uint8_t>& image,
                   const std::vector<std::uint8_t>& reference) {
  Difference d;
  const std::vector<double> error = renderer::pixel_error_pct(image, reference);
  int differing = 0;
  for (std::size_t p = 0; p < error.size(); ++p) {
    if (error[p] > 1.0) ++differing;
    int signed_sum = 0;
    for (int c = 0; c < 3; ++c) signed_sum += int{image[3 * p + c]} - int{reference[3 * p + c]};
    if (signed_sum > 76) ++d.brighter;
    if (signed_sum < -76) ++d.darker;
  }
  d.differing_fraction = static_cast<double>(differing) / static_cast<double>(error.size());
  return d;
}

void expect_same_picture(const scenes::Affine& placement, const std::string& label) {
  for (lev::Method method : {lev::Method::rt, lev::Method::lev}) {
    const std::string what = label + " " + lev::method_info(method).name;
    const std::vector<std::uint8_t> reference = render_far_rgb8(shadow_scene(at_origin()), method);
    const std::vector<std::uint8_t> image = render_far_rgb8(shadow_scene(placement), method);
    const Difference d = compare(image, reference);
    EXPECT_LT(d.differing_fraction, 0.005) << what;
    EXPECT_LE(d.brighter, 2) << what << ": light leaks";
    EXPECT_LE(d.darker, 2) << what << ": shadow acne";
  }
}

// Before render space, the translated scene differed from the origin in 5.5% of its pixels (17
// well darker, 3 well brighter): shadow-ray offsets grow with the coordinates and reached four
// units at 1e6, and hit points were 0.0625 apart.
TEST(FarScene, TranslatedNearOneMillionMatchesTheOrigin) {
  expect_same_picture(far_away(), "translated");
}

TEST(FarScene, ScaledToOneThousandthMatchesTheOrigin) {
  expect_same_picture(scaled(1e-3f), "scaled");
}

TEST(FarScene, ScaledToOneMillionthMatchesTheOrigin) {
  expect_same_picture(scaled(1e-6f), "scaled by 1e-6");
}

TEST(FarScene, ScaledByTenThousandMatchesTheOrigin) {
  expect_same_picture(scaled(1e4f), "scaled by 1e4");
}

// The largest whole-scene scale the reader lets this scene have: its camera (18 by 9 units from
// the target at the origin) then stands 9e5 away, inside the 1e6 coordinate limit; scaled by 1e6
// it would stand beyond it and be refused. The scene spans 1e6.
TEST(FarScene, ScaledByFiftyThousandMatchesTheOrigin) {
  expect_same_picture(scaled(5e4f), "scaled by 5e4");
}

// A floor quad lit from above and seen at 45 degrees; the quad's edges are `edge` units under an
// affine scale of `scale` (the camera and light are where the unscaled floor has them).
scenes::SceneDescription floor_scene(float edge, float scale) {
  scenes::SceneDescription d;
  d.name = "floor";
  const std::uint32_t grey = scenes::add_material(d, "grey", renderer::Material{});
  scenes::Affine placement;
  placement.scale = scale;
  std::vector<scenes::SceneNode> content;
  content.push_back(scenes::affine_node(
      placement, scenes::quad_node(grey, {-edge / 2, -edge / 2, 0}, {edge, 0, 0}, {0, edge, 0})));
  content.push_back(
      scenes::translate_node({0, 0, 5e4f}, scenes::point_light_node({2.5e9f, 2.5e9f, 2.5e9f})));
  d.root = scenes::union_node(std::move(content));
  d.camera.position = {0, -1e5f, 1e5f};
  d.camera.target = {0, 0, 0};
  return d;
}

// A quad of 1e4 under scale 1e6 spans 1e10: the cross product of its edges (1e20) squared to
// +inf and its normal came out zero, so it rendered unlit. It must render as a 1e6 floor does.
TEST(FarScene, HugeQuadUnderScaleOneMillionIsLitLikeTheUnscaledFloor) {
  for (lev::Method method : {lev::Method::rt, lev::Method::lev}) {
    const std::vector<std::uint8_t> reference = render_far_rgb8(floor_scene(1e6f, 1.0f), method);
    const std::vector<std::uint8_t> image = render_far_rgb8(floor_scene(1e4f, 1e6f), method);
    int lit = 0;
    for (std::uint8_t v : reference) lit += v > 0 ? 1 : 0;
    EXPECT_GT(lit, static_cast<int>(reference.size() / 2));
    const Difference d = compare(image, reference);
    EXPECT_LT(d.differing_fraction, 0.005) << lev::method_info(method).name;
    EXPECT_EQ(d.darker, 0) << lev::method_info(method).name;
  }
}

// The far scene is traced around its camera: camera, geometry and lights are moved by the same
// whole-unit origin, and the lights land exactly where the origin scene has them, shifted.
TEST(FarScene, IsInstantiatedAroundItsCamera) {
  const renderer::Scene near = scenes::instantiate_scene(shadow_scene(at_origin()));
  const renderer::Scene far = scenes::instantiate_scene(shadow_scene(far_away()));
  EXPECT_EQ(near.world_origin, glm::vec3(0.0f));
  EXPECT_EQ(far.world_origin, glm::vec3(kFarOffset) + glm::vec3(0, -18, 9));
  EXPECT_EQ(far.camera.position, glm::vec3(0.0f));
  const glm::vec3 shift = glm::vec3(kFarOffset) - far.world_origin;
  const std::vector<lev::Light> near_lights = lev::flatten_lights(near.lights);
  const std::vector<lev::Light> far_lights = lev::flatten_lights(far.lights);
  ASSERT_EQ(near_lights.size(), far_lights.size());
  for (std::size_t i = 0; i < near_lights.size(); ++i) {
    EXPECT_EQ(far_lights[i].position, near_lights[i].position + shift) << i;
    EXPECT_EQ(far_lights[i].intensity, near_lights[i].intensity) << i;
  }
  // The root's primitives are baked into one prototype placed as is: its vertices moved too.
  ASSERT_EQ(far.geometry.prototypes.size(), 1u);
  ASSERT_EQ(far.geometry.instances.size(), 1u);
  EXPECT_TRUE(lev::is_identity(far.geometry.instances[0].world_from_object));
  const std::vector<renderer::TriangleMesh>& near_meshes = near.geometry.prototypes[0].meshes;
  const std::vector<renderer::TriangleMesh>& far_meshes = far.geometry.prototypes[0].meshes;
  ASSERT_EQ(near_meshes.size(), far_meshes.size());
  for (std::size_t m = 0; m < near_meshes.size(); ++m) {
    ASSERT_EQ(near_meshes[m].positions.size(), far_meshes[m].positions.size());
    for (std::size_t v = 0; v < near_meshes[m].positions.size(); ++v) {
      EXPECT_EQ(far_meshes[m].positions[v], near_meshes[m].positions[v] + shift) << m << " " << v;
    }
  }
}

// The built-in models extend far from the origin at their top levels (the largest building spans
// 10,240 units) but are in view from about as far: they gain nothing from moving and are traced
// where they stand, so their images and hierarchies stay as the thesis tables have them.
TEST(FarScene, BuiltInModelsStayWhereTheyAre) {
  for (const scenes::SceneModel& model : scenes::scene_models()) {
    for (int level = model.min_level; level <= model.max_level; ++level) {
      EXPECT_EQ(scenes::render_space_origin(model.describe(level).camera), glm::vec3(0.0f))
          << model.name << " level " << level;
    }
  }
}

}  // namespace
