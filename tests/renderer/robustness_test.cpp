// Scenes the file format accepts that used to crash or hang the renderer: cameras and
// boxes so small that the render threads' flush-to-zero turned their normals into NaN rays, a
// refraction index that computed inf * 0, and trees of reflection and refraction too deep to
// finish, which must still stop promptly when cancelled.
#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "lev/selector_ast.h"
#include "renderer/direction.h"
#include "renderer/ray_scene.h"
#include "renderer/render.h"
#include "scenes/scene_file.h"
#include "scenes/scene_instantiation.h"
#include "scenes/scene_models.h"

namespace {

std::string error_of(const std::string& text) {
  try {
    scenes::parse_scene_json(text, "test.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

// A floor, a box and a light; `camera` and `box` are JSON fragments.
std::string scene_text(const std::string& camera, const std::string& material,
                       const std::string& box) {
  return R"({"levrt_scene": 1, "camera": )" + camera +
         R"(, "materials": [{"name": "m", "kd": 0.5}, )" + material +
         R"(], "root": {"type": "union", "children": [
           {"type": "quad", "material": "m", "corner": [-5, -5, 0], "edge_u": [10, 0, 0],
            "edge_v": [0, 10, 0]},
           )" +
         box + R"(,
           {"type": "affine", "translate": [1, -2, 4],
             "child": {"type": "point_light", "intensity": [20, 20, 20]}}]}})";
}

const std::string kCamera = R"({"position": [0, -10, 5], "target": [0, 0, 0]})";
const std::string kMirror = R"({"name": "mirror", "kd": 0.2, "kr": 0.8})";
const std::string kBox =
    R"({"type": "box", "material": "mirror", "lo": [-1, -1, 0], "hi": [1, 1, 2]})";

struct RobustRender {
  bool finite = true;
  std::uint64_t samples = 0, shading_points = 0;
};

RobustRender render_text(const std::string& text, int depth = 5) {
  renderer::Scene scene = scenes::instantiate_scene(scenes::parse_scene_json(text, "test.json"));
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs;
  rs.width = 48;
  rs.height = 36;
  rs.max_depth = depth;
  auto state = renderer::make_render_state(scene, rays, rs);
  EXPECT_TRUE(renderer::render_pass(*state));
  EXPECT_TRUE(renderer::render_pass(*state));
  const renderer::Framebuffer& fb = renderer::render_framebuffer(*state);
  RobustRender r;
  for (std::size_t i = 0; i < fb.radiance_sum.size(); ++i) {
    for (int c = 0; c < 3; ++c) r.finite = r.finite && std::isfinite(fb.radiance_sum[i][c]);
    r.samples += fb.samples[i];
    r.shading_points += fb.shading_points[i];
  }
  return r;
}

TEST(Robustness, TinyCameraUpRendersFinitePixels) {
  for (const char* up : {"1e-19", "1e-30", "1e-37"}) {
    const RobustRender r = render_text(scene_text(
        R"({"position": [0, -10, 5], "target": [0, 0, 0], "up": [0, 0, )" + std::string(up) + "]}",
        kMirror, kBox));
    EXPECT_TRUE(r.finite) << up;
    EXPECT_EQ(r.samples, 2u * 48u * 36u) << up;
    EXPECT_GT(r.shading_points, 0u) << up;
  }
}

TEST(Robustness, CameraTinyDistanceFromItsTargetRendersFinitePixels) {
  const RobustRender r = render_text(
      scene_text(R"({"position": [0, -1e-20, 1e-20], "target": [0, 0, 0]})", kMirror, kBox));
  EXPECT_TRUE(r.finite);
  EXPECT_GT(r.shading_points, 0u);
}

// What flushes to zero in the render mode is refused with one line naming the field.
TEST(Robustness, CameraDegenerateInTheRenderFloatModeIsRefused) {
  const std::string up = error_of(scene_text(
      R"({"position": [0, -10, 5], "target": [0, 0, 0], "up": [0, 0, 1e-40]})", kMirror, kBox));
  EXPECT_EQ(up.rfind("test.json: /camera/up: ", 0), 0u) << up;
  const std::string target =
      error_of(scene_text(R"({"position": [0, 0, 3], "target": [1e-40, 0, 3]})", kMirror, kBox));
  EXPECT_EQ(target.rfind("test.json: /camera/target: ", 0), 0u) << target;
  EXPECT_EQ(up.find('\n'), std::string::npos);
  EXPECT_EQ(target.find('\n'), std::string::npos);
}

// The box's geometric normal (a cross product of 1e-10 edges, 1e-20) squared to zero before.
TEST(Robustness, TinyReflectiveBoxRendersFinitePixels) {
  const RobustRender r = render_text(
      scene_text(R"({"position": [3e-10, -4e-10, 2e-10], "target": [0, 0, 0.5e-10]})", kMirror,
                 R"({"type": "box", "material": "mirror", "lo": [-1e-10, -1e-10, 0], )"
                 R"("hi": [1e-10, 1e-10, 1e-10]})"));
  EXPECT_TRUE(r.finite);
  EXPECT_GT(r.shading_points, 2u * 48u * 36u / 4u);
}

TEST(Robustness, ExtremeRefractionIndexIsRefusedAndTheLimitRendersFinitePixels) {
  const std::string glass = R"({"name": "glass", "kd": 0.1, "kt": 0.9, "ior": IOR})";
  const std::string box =
      R"({"type": "box", "material": "glass", "lo": [-1, -1, 0], "hi": [1, 1, 2]})";
  const std::string head_on = R"({"position": [0, -10, 1], "target": [0, 0, 1]})";
  for (const char* ior : {"1e-30", "0.0099", "100.5"}) {
    std::string material = glass;
    material.replace(material.find("IOR"), 3, ior);
    const std::string message = error_of(scene_text(head_on, material, box));
    EXPECT_EQ(message.rfind("test.json: /materials/1/ior: must be in [0.01, 100]", 0), 0u)
        << message;
  }
  for (const char* ior : {"0.01", "100"}) {
    std::string material = glass;
    material.replace(material.find("IOR"), 3, ior);
    const RobustRender r = render_text(scene_text(head_on, material, box));
    EXPECT_TRUE(r.finite) << ior;
  }
}

TEST(Robustness, RobustNormalizeSurvivesTinyAndHugeVectors) {
  EXPECT_EQ(renderer::robust_normalize(glm::vec3(0, 1e-20f, 0)), glm::vec3(0, 1, 0));
  EXPECT_EQ(renderer::robust_normalize(glm::vec3(0, 0, -1e30f)), glm::vec3(0, 0, -1));
  EXPECT_EQ(renderer::robust_normalize(glm::vec3(0.0f)), glm::vec3(0.0f));
  EXPECT_EQ(renderer::robust_normalize(glm::vec3(NAN, 1, 0)), glm::vec3(0.0f));
  const glm::vec3 v(0.3f, -2.0f, 5.0f);
  EXPECT_EQ(renderer::robust_normalize(v), glm::normalize(v));  // ordinary vectors: every bit kept
}

// Starts a pass, raises its cancel flag 200 ms in, and expects it to return false: a pass returns
// false only when the cancel stopped it, and one that ignored it runs to its end and returns
// true. The 60 s wait is a hang guard, not a measurement (a depth bomb never ends uncancelled; a
// cancelled pass returns in milliseconds, so no load on the machine comes near it).
bool pass_cancelled_mid_way(renderer::RenderState& state) {
  std::atomic<bool> cancel{false};
  auto pass = std::async(std::launch::async, [&] { return renderer::render_pass(state, &cancel); });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  cancel = true;
  if (pass.wait_for(std::chrono::seconds(60)) != std::future_status::ready) {
    ADD_FAILURE() << "the pass ignored the cancel";
    pass.wait();
    return false;
  }
  return !pass.get();
}

// A glass box reflecting and refracting at every hit with weight 1 (kr = kt = 1): the tree has
// 2^64 leaves at depth 64. A cancel raised mid-pass must return within the bound, and a tile it
// interrupted must add no sample.
TEST(Robustness, DepthBombCancelsPromptlyAndLeavesNoPartialTile) {
  const std::string glass = R"({"name": "bomb", "kd": 0.1, "kr": 1, "kt": 1, "ior": 1.5})";
  renderer::Scene scene = scenes::instantiate_scene(scenes::parse_scene_json(
      scene_text(kCamera, glass,
                 R"({"type": "box", "material": "bomb", "lo": [-3, -3, 0], "hi": [3, 3, 4]})"),
      "test.json"));
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs;
  rs.width = 32;
  rs.height = 32;
  rs.tile_size = 32;  // one tile: the cancel always lands inside it
  rs.max_depth = 64;
  auto state = renderer::make_render_state(scene, rays, rs);
  EXPECT_TRUE(pass_cancelled_mid_way(*state));
  EXPECT_EQ(renderer::render_passes_done(*state), 0);
  for (std::uint32_t s : renderer::render_framebuffer(*state).samples) ASSERT_EQ(s, 0u);
}

// rt over 2^22 lights: one shading point's light loop is long; the cancel reaches it through the
// selector's scratch.
TEST(Robustness, RtOverMillionsOfLightsCancelsPromptly) {
  const scenes::SceneModel* building = nullptr;
  for (const scenes::SceneModel& model : scenes::scene_models()) {
    if (std::string(model.name) == "building") building = &model;
  }
  ASSERT_NE(building, nullptr);
  renderer::Scene scene = scenes::instantiate_scene(building->describe(building->max_level));
  const renderer::RayScene rays(scene);
  renderer::RenderSettings rs;
  rs.width = 64;
  rs.height = 48;
  rs.method = lev::Method::rt;
  auto state = renderer::make_render_state(scene, rays, rs);
  EXPECT_TRUE(pass_cancelled_mid_way(*state));
}

// A shading point every light reaches unoccluded, counting how often the selector asks about one.
class CountingPoint final : public lev::ShadingPoint {
 public:
  explicit CountingPoint(const glm::vec3& position) : position_(position) {}
  glm::vec3 position() const override { return position_; }
  glm::vec3 unshadowed_radiance(const lev::Light&) const override {
    ++questions_;
    return glm::vec3(1.0f);
  }
  bool visible(const lev::Light&) override {
    ++questions_;
    return true;
  }
  std::uint64_t questions() const { return questions_; }

 private:
  glm::vec3 position_;
  mutable std::uint64_t questions_ = 0;
};

// AST ranks every light in front of a point, then shadow-tests them largest first: over the
// building's million lights at a low tolerance one point takes over a second. Once the cancel is
// raised the selector must stop within kCancelCheckLights lights of each loop; before, it went
// through every light (a SIGINT waited 1.3 s at tolerance 0).
TEST(Robustness, AstOverAMillionLightsStopsWithinItsFirstLightsOnceCancelled) {
  const scenes::SceneModel* building = scenes::find_scene_model("building");
  ASSERT_NE(building, nullptr);
  const renderer::Scene scene = scenes::instantiate_scene(building->describe(building->max_level));
  const lev::AstSelector ast(scene.lights, renderer::RenderSettings{}.tolerance);
  const std::atomic<bool> cancel{true};
  lev::SelectorScratch scratch;
  scratch.cancel = &cancel;
  CountingPoint point(scene.camera.target);
  lev::SelectionCounters counters;
  ast.direct_radiance(point, scratch, counters);
  EXPECT_LT(point.questions(), lev::kCancelCheckLights);
  EXPECT_LT(counters.lights_tested, lev::kCancelCheckLights);

  // Not cancelled, the same point is asked about (nearly) every light: the bound above is the
  // cancel's doing.
  const std::atomic<bool> running{false};
  scratch.cancel = &running;
  CountingPoint uncancelled(scene.camera.target);
  lev::SelectionCounters all;
  ast.direct_radiance(uncancelled, scratch, all);
  EXPECT_GT(uncancelled.questions(), 100 * lev::kCancelCheckLights);
}

}  // namespace
