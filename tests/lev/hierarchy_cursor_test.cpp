#include "lev/hierarchy_cursor.h"

#include <gtest/gtest.h>

#include <vector>

#include "lev/important_lights.h"
#include "lev/light_description.h"
#include "lev/light_hierarchy.h"

namespace {

// Every node kind (thesis 4.2.2): master 0 is a union of a point light and a rotated, scaled
// spotlight; master 1 is an extent volume over a union of two instances of master 0, one behind
// a translation, one behind a chain of a rotation and a translation; the root is a union of an
// instance of master 1, an extent volume over a translated light, and a translated instance.
lev::LightDescription every_kind_tree() {
  lev::LightDescription tree;
  const lev::Similarity turn =
      lev::compose(lev::make_rotation({0.0f, 1.0f, 0.0f}, 0.4f), lev::make_scale(1.5f));
  tree.masters.push_back(lev::union_node(
      {lev::light_node(lev::make_point_light({1.0f, 0.0f, 0.0f}, {2.0f, 1.0f, 0.5f})),
       lev::affine_node(
           turn, lev::light_node(lev::make_spot_light({0.0f, 1.0f, 0.0f}, {0.0f, 0.0f, -1.0f},
                                                      {4, 4, 4}, 0.6f, 2.0f)))}));
  tree.masters.push_back(lev::extent_volume_node(lev::union_node(
      {lev::affine_node(lev::make_translation({5.0f, 0.0f, 0.0f}), lev::instance_node(0)),
       lev::affine_node(
           lev::make_rotation({0.0f, 0.0f, 1.0f}, 0.7f),
           lev::affine_node(lev::make_translation({0.0f, 3.0f, -2.0f}), lev::instance_node(0)))})));
  tree.root = lev::union_node(
      {lev::instance_node(1),
       lev::extent_volume_node(lev::affine_node(
           lev::make_translation({-4.0f, 2.0f, 1.0f}),
           lev::light_node(lev::make_point_light({0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f})))),
       lev::affine_node(lev::make_translation({0.0f, 0.0f, 9.0f}), lev::instance_node(1))});
  return tree;
}

bool same_light_with_range(const lev::Light& a, const lev::Light& b) {
  return a.position == b.position && a.intensity == b.intensity && a.direction == b.direction &&
         a.kind == b.kind && a.range == b.range && a.cos_cone_half_angle == b.cos_cone_half_angle;
}

// Every light below `node` in world space, found with the cursor alone: down the nodes with one
// child to a light or group, composing the transforms passed, then each child of a group.
void lights_by_cursor(const lev::LightHierarchy& h, std::uint32_t node,
                      lev::Similarity world_from_local, std::vector<lev::Light>& out) {
  node = lev::pass_to_light_or_group(h, node, [&](const lev::HierarchyNode& n) {
    world_from_local = lev::compose(world_from_local, lev::node_transform(h, n));
  });
  const lev::HierarchyNode& n = h.nodes[node];
  if (lev::node_role(n) == lev::NodeRole::light) {
    out.push_back(lev::transform_light(lev::leaf_light(h, n), world_from_local));
    return;
  }
  ASSERT_EQ(lev::node_role(n), lev::NodeRole::group);
  for (const std::uint32_t child : lev::group_children(h, n))
    lights_by_cursor(h, child, world_from_local, out);
}

TEST(HierarchyCursor, EveryKindHasItsRole) {
  EXPECT_EQ(lev::node_role(lev::NodeKind::point_light), lev::NodeRole::light);
  EXPECT_EQ(lev::node_role(lev::NodeKind::spot_light), lev::NodeRole::light);
  EXPECT_EQ(lev::node_role(lev::NodeKind::affine), lev::NodeRole::transform);
  EXPECT_EQ(lev::node_role(lev::NodeKind::extent_volume), lev::NodeRole::bounded);
  EXPECT_EQ(lev::node_role(lev::NodeKind::master), lev::NodeRole::bounded);
  EXPECT_EQ(lev::node_role(lev::NodeKind::instance), lev::NodeRole::reference);
  EXPECT_EQ(lev::node_role(lev::NodeKind::set_union), lev::NodeRole::group);
}

TEST(HierarchyCursor, FindsEveryLightOfTheDescription) {
  const lev::LightDescription tree = every_kind_tree();
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  std::vector<lev::Light> found;
  lights_by_cursor(h, h.root, lev::Similarity{}, found);
  const std::vector<lev::Light> expected = lev::flatten_light_description(tree);
  ASSERT_EQ(found.size(), 9u);  // 2 instances of master 1, each 2 of master 0's 2 lights, + 1
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t i = 0; i < found.size(); ++i)
    EXPECT_TRUE(same_light_with_range(found[i], expected[i])) << "light " << i;
}

TEST(HierarchyCursor, ReferencesLeadToTheirMasters) {
  const lev::LightHierarchy h = lev::build_hierarchy(every_kind_tree());
  int references = 0;
  for (std::uint32_t i = 0; i < h.nodes.size(); ++i) {
    const lev::HierarchyNode& n = h.nodes[i];
    if (lev::node_role(n) != lev::NodeRole::reference) continue;
    ++references;
    const std::uint32_t master = lev::only_child(n, i);
    EXPECT_EQ(h.nodes[master].kind, lev::NodeKind::master);
    EXPECT_TRUE(master == h.master_ranges[0].begin || master == h.master_ranges[1].begin);
    EXPECT_EQ(lev::below_referenced_master(n), lev::only_child(h.nodes[master], master));
    // A reference keeps its master's aggregate; a master shares its child's.
    EXPECT_EQ(&lev::kept_aggregate(h, i), &lev::kept_aggregate(h, master));
    EXPECT_EQ(&lev::kept_aggregate(h, master), lev::stored_aggregate(h, master + 1));
  }
  EXPECT_EQ(references, 4);
}

TEST(HierarchyCursor, NodesWithOneChildStepToTheNextNode) {
  const lev::LightHierarchy h = lev::build_hierarchy(every_kind_tree());
  for (std::uint32_t i = 0; i < h.nodes.size(); ++i) {
    const lev::HierarchyNode& n = h.nodes[i];
    const lev::NodeRole role = lev::node_role(n);
    if (role == lev::NodeRole::transform || role == lev::NodeRole::bounded) {
      EXPECT_EQ(lev::only_child(n, i), i + 1) << lev::node_kind_name(n.kind);
    }
    if (role == lev::NodeRole::transform || role == lev::NodeRole::light) {
      EXPECT_EQ(lev::stored_aggregate(h, i), nullptr) << lev::node_kind_name(n.kind);
    } else {
      EXPECT_NE(lev::stored_aggregate(h, i), nullptr) << lev::node_kind_name(n.kind);
    }
  }
}

TEST(HierarchyCursor, GroupsListTheirChildrenAndKeepTheirAggregate) {
  const lev::LightHierarchy h = lev::build_hierarchy(every_kind_tree());
  const lev::HierarchyNode& root = h.nodes[h.root];
  ASSERT_EQ(lev::node_role(root), lev::NodeRole::group);
  const lev::ChildNodes children = lev::group_children(h, root);
  ASSERT_EQ(children.count, 3u);
  EXPECT_EQ(h.nodes[children[0]].kind, lev::NodeKind::instance);
  EXPECT_EQ(h.nodes[children[1]].kind, lev::NodeKind::extent_volume);
  EXPECT_EQ(h.nodes[children[2]].kind, lev::NodeKind::affine);
  const std::uint32_t slot = lev::group_aggregate_slot(h, root);
  EXPECT_EQ(&lev::kept_aggregate(h, h.root), &h.aggregates[h.union_children[slot]]);
  EXPECT_EQ(lev::kept_aggregate(h, h.root).intensity,
            lev::kept_aggregate(h, h.master_ranges[1].begin).intensity * 2.0f + glm::vec3(1.0f));
}

TEST(HierarchyCursor, AffineChainCarriesPointAndNormalIntoTheLocalFrame) {
  const lev::LightHierarchy h = lev::build_hierarchy(every_kind_tree());
  // Master 1's second union child: rotation, then translation, then an instance.
  const std::uint32_t master = h.master_ranges[1].begin;
  const std::uint32_t group = lev::pass_to_light_or_group(
      h, master, [](const auto&) { ADD_FAILURE() << "no transform above master 1's union"; });
  const std::uint32_t chain = lev::group_children(h, h.nodes[group])[1];
  const glm::vec3 world_point(1.0f, 2.0f, 3.0f);
  const glm::vec3 world_normal(0.0f, 1.0f, 0.0f);
  lev::FramePoint point{world_point, 0.0f};
  glm::vec3 normal = world_normal;
  std::vector<lev::Similarity> passed;
  const std::uint32_t below = lev::pass_transforms(h, chain, [&](const lev::HierarchyNode& n) {
    passed.push_back(lev::node_transform(h, n));
    lev::enter_transform(h, n, point, normal);
  });
  ASSERT_EQ(passed.size(), 2u);
  EXPECT_EQ(h.nodes[below].kind, lev::NodeKind::instance);
  EXPECT_FALSE(lev::is_translation_only(h.nodes[chain]));
  EXPECT_TRUE(lev::is_translation_only(h.nodes[chain + 1]));
  const lev::Similarity world_from_local = lev::compose(passed[0], passed[1]);
  const glm::vec3 expected_point = lev::apply_inverse_point(world_from_local, world_point);
  const glm::vec3 expected_normal = glm::transpose(world_from_local.rotation) * world_normal;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(point.point[c], expected_point[c], 1e-5f);
    EXPECT_NEAR(normal[c], expected_normal[c], 1e-6f);
  }
  EXPECT_GT(point.rounding, 0.0f);  // each frame adds its rounding allowance
  // The rotation turned the normal; the translation below it left it alone.
  EXPECT_NE(normal, world_normal);
  // Down the rest: the instance leads through master 0 to its union.
  const std::uint32_t next = lev::pass_to_light_or_group(h, below, [](const auto&) {});
  EXPECT_EQ(next, lev::below_referenced_master(h.nodes[below]));
  EXPECT_EQ(h.nodes[next].kind, lev::NodeKind::set_union);
}

TEST(HierarchyCursor, LightsAreReadAtTheLeaves) {
  const lev::LightDescription tree = every_kind_tree();
  const lev::LightHierarchy h = lev::build_hierarchy(tree);
  std::vector<lev::Light> leaves;
  for (const lev::HierarchyNode& n : h.nodes) {
    if (lev::node_role(n) == lev::NodeRole::light) leaves.push_back(lev::leaf_light(h, n));
  }
  // Stored once each in their own frames: master 0's two and the root's one.
  ASSERT_EQ(leaves.size(), 3u);
  EXPECT_TRUE(same_light_with_range(leaves[0], tree.masters[0].children[0].light));
  EXPECT_TRUE(same_light_with_range(leaves[1], tree.masters[0].children[1].children[0].light));
  EXPECT_TRUE(
      same_light_with_range(leaves[2], tree.root.children[1].children[0].children[0].light));
}

}  // namespace
