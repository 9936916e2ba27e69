// The stage rig class: thousands of coloured spots, every one aimed at the stage and most of them
// reaching its centre, the rig's summed intensity the same at every level, a mirror and glass on
// the stage; its parameters make other rigs and are checked.
#include "scenes/stage_rig.h"

#include <cmath>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "scenes/scene_instantiation.h"

namespace {

const glm::vec3 kStageCentre{0.0f, 4.0f, 1.0f};

TEST(StageRig, EverySpotIsAimedAtTheStageAndMostReachItsCentre) {
  const scenes::StageRigParams p = scenes::stage_rig_params(4);
  const renderer::Scene scene = scenes::build_stage_rig(4);
  const std::vector<lev::Light> lights = lev::flatten_lights(scene.lights);
  ASSERT_EQ(lights.size(), scenes::stage_rig_light_count(4));
  int reaching_centre = 0;
  std::set<std::tuple<float, float, float>> colours;
  for (const lev::Light& l : lights) {
    ASSERT_EQ(l.kind, lev::LightKind::spot);
    // The axis meets the stage's top within the aim radius of its centre.
    const float t = (kStageCentre.z - l.position.z) / l.direction.z;
    ASSERT_GT(t, 0.0f);
    const glm::vec3 hit = l.position + t * l.direction;
    EXPECT_LT(glm::length(hit - kStageCentre), p.aim_radius_m + 1e-3f);
    if (glm::dot(lev::irradiance(l, kStageCentre + glm::vec3(0.0f, 0.0f, 0.01f)), glm::vec3(1.0f)) >
        0.0f) {
      ++reaching_centre;
    }
    const glm::vec3 c = l.intensity / std::max({l.intensity.x, l.intensity.y, l.intensity.z});
    colours.emplace(std::round(c.x * 8.0f), std::round(c.y * 8.0f), std::round(c.z * 8.0f));
  }
  // Overlapping: a large share of the rig reaches the centre; coloured: many distinct tints.
  EXPECT_GT(reaching_centre, static_cast<int>(lights.size()) / 5);
  EXPECT_GT(colours.size(), 20u);
}

TEST(StageRig, TheRigShinesAsBrightlyAtEveryLevel) {
  glm::dvec3 previous(0.0);
  for (int level : {3, 4, 5}) {
    glm::dvec3 sum(0.0);
    for (const lev::Light& l : lev::flatten_lights(scenes::build_stage_rig(level).lights))
      sum += glm::dvec3(l.intensity);
    const double total = sum.x + sum.y + sum.z;
    if (level > 3) {
      EXPECT_NEAR(total, previous.x + previous.y + previous.z, 0.05 * total) << level;
    }
    previous = sum;
  }
}

TEST(StageRig, TheStageHoldsAMirrorAndGlass) {
  const scenes::SceneDescription s = scenes::describe_stage_rig(3);
  bool mirror = false, glass = false;
  for (const scenes::NamedMaterial& m : s.materials) {
    mirror = mirror || m.material.kr >= 0.8f;
    glass = glass || (m.material.kt >= 0.8f && m.material.ior > 1.0f);
  }
  EXPECT_TRUE(mirror);
  EXPECT_TRUE(glass);
}

TEST(StageRig, ParametersMakeOtherRigsAndAreChecked) {
  scenes::StageRigParams p;
  p.spots = 500;
  p.seed = 7;
  EXPECT_EQ(scenes::instantiate_scene(scenes::describe_stage_rig_from(p)).lights.light_count, 500u);
  for (auto breaks : {+[](scenes::StageRigParams& r) { r.spots = 0; },
                      +[](scenes::StageRigParams& r) { r.cone_min_degrees = 45.0f; },
                      +[](scenes::StageRigParams& r) { r.truss_height_m = 1.0f; },
                      +[](scenes::StageRigParams& r) { r.total_intensity = -1.0f; }}) {
    scenes::StageRigParams r = p;
    breaks(r);
    EXPECT_THROW(scenes::describe_stage_rig_from(r), std::invalid_argument);
  }
  EXPECT_THROW(scenes::stage_rig_params(8), std::invalid_argument);
}

}  // namespace
