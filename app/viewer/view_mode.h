// The pictures the viewer can show of one render: the image itself and five heatmaps (lights
// tested, nodes visited, the error against the `rt` reference of the same view, the certified
// bound of that error, known without the reference (renderer/error_bound.h), and the noise: the
// estimated standard error of the mean over the passes so far).
// One table names them for the panel, for --set view=... and for snapshot file names.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace app::viewer {

enum class ViewMode { image, lights, nodes, error, bound, noise };

struct ViewModeInfo {
  ViewMode mode;
  const char* name;   // --set view=NAME, file names
  const char* label;  // panel
  const char* unit;   // heatmap legend: the quantity, its unit, per sample or per pixel
  const char* zero;   // legend of a field that is 0 in every rendered pixel: what that means
};

const std::vector<ViewModeInfo>& view_mode_table();
const ViewModeInfo& view_mode_info(ViewMode mode);
std::optional<ViewMode> parse_view_mode(std::string_view name);
std::string view_mode_names(const char* separator);

}  // namespace app::viewer
