// The pictures of one render, in one table that the viewer and `levrt render` both read: the image
// itself and the per-pixel heatmaps (lights tested, nodes visited, the error against the `rt`
// reference, its certified bound, the noise across passes, the missed-light estimate, the signed
// difference against rt and the mask of pixels above an error threshold). A row names the view
// (for --set view=NAME, snapshot files and the stats' range key), labels it for the panel, says
// its unit and what a field of zeros means, picks its colour map and range rule, reads its value
// and hover line at a pixel, and names the headless flag that writes it as a PNG.
// Adding a view is an enum value and a row here, plus the per-pixel field it reads if that is new.
// A view missing from the table is refused loudly (view_info throws), never drawn as another.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace app {

enum class ViewMode { image, lights, nodes, error, bound, noise, missed, difference, mask };

enum class ColourMap {
  image,       // the rendered colours, through the display transform
  sequential,  // viridis, low to high
  diverging,   // blue (negative) through white (0) to red (positive)
  mask,        // red where the value is 1, the image dimmed where it is 0
};

enum class RangeRule {
  none,             // the image: no value range
  data,             // the rendered pixels' min .. max, log scale above the minimum
  symmetric_fixed,  // -fixed_range .. +fixed_range, linear
  threshold,        // 0 or 1: above the chosen threshold or not
};

// One per-pixel field, borrowed: floats (the viewer keeps them) or doubles (a headless render's,
// read at full precision so its heatmap ranges equal its statistics). Empty: not available.
class PixelField {
 public:
  // Implicit: a field is its array (`pixels.noise_pct = image.noise_pct.data()`).
  PixelField() = default;
  PixelField(const float* values) : floats_(values) {}
  PixelField(const double* values) : doubles_(values) {}
  explicit operator bool() const { return floats_ != nullptr || doubles_ != nullptr; }
  double operator[](std::size_t i) const {
    return floats_ != nullptr ? static_cast<double>(floats_[i]) : doubles_[i];
  }

 private:
  const float* floats_ = nullptr;
  const double* doubles_ = nullptr;
};

// The per-pixel fields a view reads, borrowed from the caller (the viewer's display image or a
// headless framebuffer), pixel order. A null field is not available (no reference, no
// missed-light estimate, a preview); the views reading it then have no value anywhere.
struct ViewPixels {
  std::size_t count = 0;
  const std::uint32_t* samples = nullptr;  // 0: not rendered
  PixelField lights_tested;                // per sample
  PixelField nodes_visited;                // per sample
  PixelField error_bound_pct;
  PixelField noise_pct;  // estimated standard error, from the second sample on
  PixelField missed_pct;
  PixelField missed_std_error_pct;
  PixelField error_pct;             // against rt; negative where not compared
  PixelField difference_pct;        // signed (method - rt), where error_pct is known
  double mask_threshold_pct = 1.0;  // the mask view's error threshold
};

struct ViewInfo {
  ViewMode mode;
  const char* name;   // --set view=NAME, snapshot file suffix, stats key heatmap_NAME_range
  const char* label;  // panel
  const char* unit;   // legend: the quantity, its unit, per sample or per pixel
  const char* zero;   // legend of a field that is 0 in every rendered pixel: what that means
  ColourMap colour_map;
  RangeRule range_rule;
  double fixed_range;  // symmetric_fixed: the range's half width, in the unit
  // The value at pixel i, none where the view has none (not rendered, not compared, no field).
  // Null for the image.
  std::optional<double> (*value)(const ViewPixels& pixels, std::size_t i);
  // The hover read-out of pixel i: the value in words and units (with its standard error where
  // there is one), or why there is none.
  std::string (*hover)(const ViewPixels& pixels, std::size_t i);
  const char* channel;      // EXR channel of the value (snapshots); "" for the image
  const char* output_flag;  // `levrt render` flag writing the heatmap PNG; "" for viewer-only
  const char* output_help;
  bool needs_reference;  // reads the comparison with rt (error_pct, difference_pct)
  bool needs_missed;     // reads the missed-light estimate (costs extra shadow rays)
};

const std::vector<ViewInfo>& view_table();
// The row of `mode`; throws std::logic_error for a mode missing from the table.
const ViewInfo& view_info(ViewMode mode);
std::optional<ViewMode> parse_view_mode(std::string_view name);
std::string view_mode_names(const char* separator);

// Every value of `info` over the pixels, 0 where it has none (the headless heatmaps' input).
std::vector<double> view_values(const ViewInfo& info, const ViewPixels& pixels);

}  // namespace app
