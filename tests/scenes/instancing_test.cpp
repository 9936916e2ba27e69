// The instanced light hierarchy of a scene model against the same lights flattened into a plain
// list with an automatic BVH: both must select the same lights everywhere.
#include <algorithm>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "lev/important_lights.h"
#include "lev/light_bvh.h"
#include "lev/light_hierarchy.h"
#include "scenes/scene_models.h"

namespace {

using InstanceLightKey = std::tuple<float, float, float, float, float, float>;

std::vector<InstanceLightKey> sorted_instance_keys(const std::vector<lev::Light>& lights) {
  std::vector<InstanceLightKey> keys;
  for (const lev::Light& l : lights) {
    keys.emplace_back(l.position.x, l.position.y, l.position.z, l.intensity.x, l.intensity.y,
                      l.intensity.z);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

TEST(Instancing, InstancedHierarchyAndFlattenedBvhSelectTheSameLights) {
  for (const scenes::SceneModel& model : scenes::scene_models()) {
    const int level = std::min(model.min_level + 2, model.max_level);
    renderer::Scene scene = model.build(level);
    const std::vector<lev::Light> flat = lev::flatten_lights(scene.lights);
    lev::LightDescription flat_tree;
    flat_tree.root = lev::build_light_bvh(flat);
    lev::LightHierarchy bvh = lev::build_hierarchy(flat_tree);
    EXPECT_EQ(bvh.light_count, scene.lights.light_count) << model.name;
    // The thesis models instance masters of masters, so their hierarchy is the smaller; the
    // generated classes are flat lists or one level of instances, as large as the BVH or larger.
    const std::string name = model.name;
    if (name == "building" || name == "maze" || name == "hall") {
      EXPECT_GT(lev::hierarchy_bytes(bvh), lev::hierarchy_bytes(scene.lights)) << model.name;
    }

    lev::WalkScratch scratch;
    for (float tau : {0.001f, 0.01f, 0.1f}) {
      const lev::ExtentVolumes scene_volumes = lev::fit_extent_volumes(scene.lights, tau);
      const lev::ExtentVolumes bvh_volumes = lev::fit_extent_volumes(bvh, tau);
      for (int k = 0; k < 60; ++k) {
        // Points spread over the lights' footprint, from the floor to above the lights.
        glm::vec3 lo(0.0f), hi(1.0f);
        for (const lev::Light& l : flat) {
          lo = glm::min(lo, l.position);
          hi = glm::max(hi, l.position);
        }
        const float u = static_cast<float>((k * 37) % 60) / 60.0f,
                    v = static_cast<float>((k * 23) % 60) / 60.0f;
        const glm::vec3 p(lo.x + u * (hi.x - lo.x), lo.y + v * (hi.y - lo.y),
                          0.1f + 0.05f * static_cast<float>(k % 40));
        std::vector<lev::Light> a, b;
        lev::WalkCounters ca, cb;
        lev::find_important_lights(scene.lights, scene_volumes, tau, p, scratch, a, ca);
        lev::find_important_lights(bvh, bvh_volumes, tau, p, scratch, b, cb);
        ASSERT_EQ(sorted_instance_keys(a), sorted_instance_keys(b))
            << model.name << " tau " << tau << " point " << k;
      }
    }
  }
}

}  // namespace
