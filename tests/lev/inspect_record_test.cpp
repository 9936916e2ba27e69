// complete_inspection (lev/inspect_record.h) expands a culled subtree into every one of its
// lights, and reads its cancel flag while doing so: raised during the expansion (as the viewer's
// inspector raises it for a new pixel, Clear or quitting), it stops within kCancelCheckLights
// lights instead of casting a shadow ray for each of the subtree's lights.
#include <atomic>
#include <cstddef>
#include <vector>

#include <gtest/gtest.h>

#include "lev/inspect_record.h"
#include "lev/light_description.h"
#include "lev/light_hierarchy.h"
#include "lev/light_selector.h"
#include "tests/lev/open_point.h"

namespace {

// A point that raises `cancel` at its first shadow ray and counts them.
class CancellingPoint final : public lev::ShadingPoint {
 public:
  explicit CancellingPoint(std::atomic<bool>* cancel) : open_(glm::vec3(0.0f)), cancel_(cancel) {}
  glm::vec3 position() const override { return open_.position(); }
  glm::vec3 unshadowed_radiance(const lev::Light& light) const override {
    return open_.unshadowed_radiance(light);
  }
  bool visible(const lev::Light& light) override {
    ++rays;
    if (cancel_) cancel_->store(true);
    return open_.visible(light);
  }
  std::size_t rays = 0;

 private:
  lev_test::OpenPoint open_;
  std::atomic<bool>* cancel_;
};

lev::LightHierarchy many_lights(std::size_t count) {
  std::vector<lev::LightDescriptionNode> lights;
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec3 position(static_cast<float>(i % 64), static_cast<float>(i / 64), 5.0f);
    lights.push_back(lev::light_node(lev::make_point_light(position, glm::vec3(1.0f))));
  }
  lev::LightDescription tree;
  tree.root = lev::union_node(std::move(lights));
  return lev::build_hierarchy(tree);
}

TEST(InspectRecord, ACulledSubtreeListsEveryLightAndStopsSoonOnceCancelled) {
  const std::size_t count = 3 * lev::kCancelCheckLights + 7;
  const lev::LightHierarchy h = many_lights(count);
  lev::InspectRecord whole;
  whole.culled_subtrees.push_back({h.root, {}, {}});
  CancellingPoint uncancelled(nullptr);
  lev::complete_inspection(h, uncancelled, whole);
  EXPECT_EQ(whole.culled.size(), count);
  EXPECT_EQ(uncancelled.rays, count);

  std::atomic<bool> cancel{false};
  lev::InspectRecord cut;
  cut.culled_subtrees.push_back({h.root, {}, {}});
  CancellingPoint cancelling(&cancel);
  lev::complete_inspection(h, cancelling, cut, &cancel);
  EXPECT_EQ(cut.culled.size(), lev::kCancelCheckLights);
  EXPECT_EQ(cancelling.rays, lev::kCancelCheckLights);
}

}  // namespace
