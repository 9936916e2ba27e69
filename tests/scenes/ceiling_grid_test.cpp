// The ceiling grid class: a flat grid of lights under the ceiling, each a little of what a floor
// point receives; partitions from floor to ceiling between bay columns, broken by lanes; its
// parameters make other floors and are checked.
#include "scenes/ceiling_grid.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_hierarchy.h"
#include "scenes/scene_instantiation.h"

namespace {

TEST(CeilingGrid, ManyDimLightsLightEachFloorPoint) {
  const scenes::CeilingGridParams p = scenes::ceiling_grid_params(5);
  const std::vector<lev::Light> lights = lev::flatten_lights(scenes::build_ceiling_grid(5).lights);
  ASSERT_EQ(lights.size(), 1024u);
  for (const lev::Light& l : lights) EXPECT_FLOAT_EQ(l.position.z, p.ceiling_height_m - 0.05f);
  const glm::vec3 floor_point{16.0f * p.spacing_m, 16.0f * p.spacing_m, 0.0f};
  float sum = 0.0f, brightest = 0.0f;
  int reaching = 0;
  for (const lev::Light& l : lights) {
    const float e = lev::irradiance(l, floor_point).x;
    sum += e;
    brightest = std::max(brightest, e);
    reaching += e > 0.0f ? 1 : 0;
  }
  EXPECT_GT(reaching, 500);
  EXPECT_LT(brightest, 0.25f * sum);  // no light dominates
}

TEST(CeilingGrid, PartitionsRunFloorToCeilingBetweenBayColumns) {
  const scenes::CeilingGridParams p = scenes::ceiling_grid_params(4);
  const scenes::SceneDescription s = scenes::describe_ceiling_grid(4);
  int walls = 0;
  for (const scenes::SceneNode& n : s.root.children) {
    const auto* box = std::get_if<scenes::BoxShape>(&n.data);
    if (box && box->lo.z == 0.0f && box->hi.z == p.ceiling_height_m &&
        box->hi.x - box->lo.x < 0.25f)
      ++walls;
  }
  // Three walls between four bay columns of 16, each broken by one lane into two.
  EXPECT_EQ(walls, (p.columns / p.bay_columns - 1) * 2);
}

TEST(CeilingGrid, ParametersMakeOtherFloorsAndAreChecked) {
  scenes::CeilingGridParams p;
  p.columns = 30;
  p.rows = 12;
  EXPECT_EQ(scenes::instantiate_scene(scenes::describe_ceiling_grid_from(p)).lights.light_count,
            360u);
  for (auto breaks : {+[](scenes::CeilingGridParams& r) { r.rows = 0; },
                      +[](scenes::CeilingGridParams& r) { r.spacing_m = 0.0f; },
                      +[](scenes::CeilingGridParams& r) { r.car_share = 2.0f; },
                      +[](scenes::CeilingGridParams& r) { r.bay_columns = 0; }}) {
    scenes::CeilingGridParams r = p;
    breaks(r);
    EXPECT_THROW(scenes::describe_ceiling_grid_from(r), std::invalid_argument);
  }
  EXPECT_THROW(scenes::ceiling_grid_params(2), std::invalid_argument);
}

}  // namespace
