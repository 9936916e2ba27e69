#include "app/view_table.h"

#include <cstdio>
#include <stdexcept>

namespace app {
namespace {

using Value = std::optional<double>;

bool rendered(const ViewPixels& p, std::size_t i) {
  return p.samples != nullptr && p.samples[i] > 0;
}

// A per-sample field of a rendered pixel.
Value sampled(const ViewPixels& p, const PixelField& field, std::size_t i) {
  if (!field || !rendered(p, i)) return std::nullopt;
  return field[i];
}

bool compared(const ViewPixels& p, std::size_t i) {
  return p.error_pct && p.error_pct[i] >= 0.0;
}

Value lights_value(const ViewPixels& p, std::size_t i) {
  return sampled(p, p.lights_tested, i);
}
Value nodes_value(const ViewPixels& p, std::size_t i) {
  return sampled(p, p.nodes_visited, i);
}
Value bound_value(const ViewPixels& p, std::size_t i) {
  return sampled(p, p.error_bound_pct, i);
}
Value noise_value(const ViewPixels& p, std::size_t i) {
  // The spread of the passes is known from the second one on.
  if (p.samples == nullptr || p.samples[i] < 2) return std::nullopt;
  return sampled(p, p.noise_pct, i);
}
Value missed_value(const ViewPixels& p, std::size_t i) {
  return sampled(p, p.missed_pct, i);
}
Value error_value(const ViewPixels& p, std::size_t i) {
  if (!compared(p, i)) return std::nullopt;
  return p.error_pct[i];
}
Value difference_value(const ViewPixels& p, std::size_t i) {
  if (!compared(p, i) || !p.difference_pct) return std::nullopt;
  return p.difference_pct[i];
}
Value mask_value(const ViewPixels& p, std::size_t i) {
  if (!compared(p, i)) return std::nullopt;
  return p.error_pct[i] > p.mask_threshold_pct ? 1.0 : 0.0;
}

template <typename... Args>
std::string format(const char* pattern, Args... args) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, args...);
  return text;
}

// The read-out of a value by a printf pattern, or the reason there is none.
std::string read_out(const Value& v, const char* pattern, const char* none) {
  return v ? format(pattern, *v) : std::string(none);
}

std::string lights_hover(const ViewPixels& p, std::size_t i) {
  return read_out(lights_value(p, i), "lights tested  %.1f per sample",
                  "lights tested  not rendered yet");
}
std::string nodes_hover(const ViewPixels& p, std::size_t i) {
  return read_out(nodes_value(p, i), "nodes visited  %.1f per sample",
                  "nodes visited  not rendered yet");
}
std::string error_hover(const ViewPixels& p, std::size_t i) {
  return read_out(error_value(p, i), "error          %.3f%% (vs rt, same passes)",
                  "error          needs the rt reference");
}
std::string bound_hover(const ViewPixels& p, std::size_t i) {
  return read_out(bound_value(p, i), "error bound    %.3f%% (certified, no shadows)",
                  "error bound    not rendered yet");
}
std::string noise_hover(const ViewPixels& p, std::size_t i) {
  return read_out(noise_value(p, i), "noise          %.3f%% (std error of the mean)",
                  "noise          from the second sample on");
}
std::string difference_hover(const ViewPixels& p, std::size_t i) {
  return read_out(difference_value(p, i), "difference     %+.3f%% (method - rt)",
                  "difference     needs the rt reference");
}
std::string missed_hover(const ViewPixels& p, std::size_t i) {
  const Value v = missed_value(p, i);
  if (!v) return "missed light   shown with the Missed light view";
  const double se = p.missed_std_error_pct ? p.missed_std_error_pct[i] : 0.0;
  return format("missed light   %.3f%% +- %.3f%% (std error)", *v, se);
}
std::string mask_hover(const ViewPixels& p, std::size_t i) {
  const Value v = mask_value(p, i);
  if (!v) return "mask           needs the rt reference";
  return format("mask           %s %.3g%%", *v > 0.0 ? "above" : "at or below",
                p.mask_threshold_pct);
}

}  // namespace

const std::vector<ViewInfo>& view_table() {
  static const std::vector<ViewInfo> table = {
      {ViewMode::image, "image", "Image", "", "", ColourMap::image, RangeRule::none, 0.0, nullptr,
       nullptr, "", "", "", false, false},
      {ViewMode::lights, "lights", "Lights tested", "lights tested per sample (pixel mean)",
       "no shadow ray to any light: every light was culled or unlit", ColourMap::sequential,
       RangeRule::data, 0.0, lights_value, lights_hover, "lights_tested", "--heatmap-lights",
       "lights-tested heatmap PNG", false, false},
      {ViewMode::nodes, "nodes", "Nodes visited", "hierarchy nodes visited per sample (pixel mean)",
       "this method does not walk the light hierarchy", ColourMap::sequential, RangeRule::data, 0.0,
       nodes_value, nodes_hover, "nodes_visited", "--heatmap-nodes", "nodes-visited heatmap PNG",
       false, false},
      {ViewMode::error, "error", "Error vs rt",
       "error per pixel, % of 765 (mean over the same passes as rt's)", "the image equals rt",
       ColourMap::sequential, RangeRule::data, 0.0, error_value, error_hover, "error_pct",
       "--heatmap-error",
       "per-pixel error against the reference heatmap PNG (percent; needs --reference)", true,
       false},
      {ViewMode::bound, "bound", "Error bound",
       "certified bound of the error vs rt per pixel, % of 765, assuming no shadows (every "
       "culled light counted as seen; no reference needed)",
       "no light was left out: the image is rt's, up to 8-bit rounding", ColourMap::sequential,
       RangeRule::data, 0.0, bound_value, bound_hover, "error_bound_pct", "--heatmap-bound",
       "certified error bound heatmap PNG (percent)", false, false},
      {ViewMode::noise, "noise", "Noise",
       "estimated standard error of the pixel mean over passes, % of 765",
       "the passes agree: no noise (or fewer than two passes yet)", ColourMap::sequential,
       RangeRule::data, 0.0, noise_value, noise_hover, "noise_pct", "--heatmap-noise",
       "estimated standard error per pixel (noise across passes) heatmap PNG", false, false},
      {ViewMode::missed, "missed", "Missed light",
       "estimated light the method left out, with shadows, % of 765 (extra shadow rays while "
       "shown)",
       "nothing left out, or every culled light is hidden", ColourMap::sequential, RangeRule::data,
       0.0, missed_value, missed_hover, "missed_pct", "--heatmap-missed",
       "missed-light estimate per pixel heatmap PNG (percent; turns the estimate on)", false, true},
      {ViewMode::difference, "difference", "Difference",
       "signed difference method - rt per pixel, % of 765 (blue: darker than rt, red: brighter)",
       "the image equals rt", ColourMap::diverging, RangeRule::symmetric_fixed, 2.0,
       difference_value, difference_hover, "difference_pct", "", "", true, false},
      {ViewMode::mask, "mask", "Error mask",
       "pixels whose error vs rt is above the threshold (red), % of 765",
       "no pixel is above the threshold", ColourMap::mask, RangeRule::threshold, 0.0, mask_value,
       mask_hover, "mask", "", "", true, false},
  };
  return table;
}

const ViewInfo& view_info(ViewMode mode) {
  for (const ViewInfo& info : view_table()) {
    if (info.mode == mode) return info;
  }
  throw std::logic_error("view mode missing from view_table");
}

std::optional<ViewMode> parse_view_mode(std::string_view name) {
  for (const ViewInfo& info : view_table()) {
    if (name == info.name) return info.mode;
  }
  return std::nullopt;
}

std::string view_mode_names(const char* separator) {
  std::string s;
  for (const ViewInfo& info : view_table()) {
    if (!s.empty()) s += separator;
    s += info.name;
  }
  return s;
}

std::vector<double> view_values(const ViewInfo& info, const ViewPixels& pixels) {
  std::vector<double> values(pixels.count, 0.0);
  if (info.value == nullptr) return values;
  for (std::size_t i = 0; i < pixels.count; ++i) values[i] = info.value(pixels, i).value_or(0.0);
  return values;
}

}  // namespace app
