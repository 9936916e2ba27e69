#include "lev/selector_lightcuts.h"

namespace lev {

LightcutsSelector::LightcutsSelector(const LightHierarchy& hierarchy, float relative_error)
    : tree_(build_light_cut_tree(hierarchy)), settings_{relative_error, kDefaultMaxCutSize} {}

glm::vec3 LightcutsSelector::direct_radiance(ShadingPoint& point, SelectorScratch& scratch,
                                             SelectionCounters& counters,
                                             glm::vec3* culled_irradiance_bound) const {
  CutScratch& cut = method_scratch<CutScratch>(scratch);
  const bool radiance_bound_asked = scratch.culled_radiance && culled_irradiance_bound;
  glm::vec3 cluster_error(0.0f);
  const glm::vec3 radiance =
      shade_light_cut(tree_, settings_, point, cut, counters, culled_irradiance_bound,
                      scratch.cancel, radiance_bound_asked ? &cluster_error : nullptr);
  if (radiance_bound_asked) {
    scratch.culled_radiance->bound = cluster_error;
    scratch.culled_radiance->bounded = true;
  }
  if (scratch.inspect) record_light_cut(tree_, cut, point, *scratch.inspect);
  return radiance;
}

std::size_t LightcutsSelector::bookkeeping_bytes() const {
  return tree_.nodes.size() * sizeof(CutTreeNode) + tree_.lights.size() * sizeof(Light);
}

}  // namespace lev
