#include "app/viewer/view_mode.h"

#include <stdexcept>

namespace app::viewer {

const std::vector<ViewModeInfo>& view_mode_table() {
  static const std::vector<ViewModeInfo> table = {
      {ViewMode::image, "image", "Image", "", ""},
      {ViewMode::lights, "lights", "Lights tested", "lights tested per sample (pixel mean)",
       "no shadow ray to any light: every light was culled or unlit"},
      {ViewMode::nodes, "nodes", "Nodes visited", "hierarchy nodes visited per sample (pixel mean)",
       "this method does not walk the light hierarchy"},
      {ViewMode::error, "error", "Error vs rt", "error per pixel, % of 765 (pass 0 against rt)",
       "the image equals rt"},
      {ViewMode::bound, "bound", "Error bound",
       "certified bound of the error vs rt per pixel, % of 765, assuming no shadows (every "
       "culled light counted as seen; no reference needed)",
       "no light was left out: the image is rt's, up to 8-bit rounding"},
      {ViewMode::noise, "noise", "Noise",
       "estimated standard error of the pixel mean over passes, % of 765",
       "the passes agree: no noise (or fewer than two passes yet)"},
  };
  return table;
}

const ViewModeInfo& view_mode_info(ViewMode mode) {
  for (const ViewModeInfo& info : view_mode_table()) {
    if (info.mode == mode) return info;
  }
  throw std::logic_error("view mode missing from view_mode_table");
}

std::optional<ViewMode> parse_view_mode(std::string_view name) {
  for (const ViewModeInfo& info : view_mode_table()) {
    if (name == info.name) return info.mode;
  }
  return std::nullopt;
}

std::string view_mode_names(const char* separator) {
  std::string s;
  for (const ViewModeInfo& info : view_mode_table()) {
    if (!s.empty()) s += separator;
    s += info.name;
  }
  return s;
}

}  // namespace app::viewer
