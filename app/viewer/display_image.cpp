#include "app/viewer/display_image.h"
#include "app/viewer/heatmap_scale.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "renderer/error_bound.h"
#include "renderer/missed_light.h"
#include "renderer/pixel_error.h"
#include "renderer/pixel_noise.h"

namespace app::viewer {

const std::uint8_t kNotRenderedRgb[3] = {38, 38, 42};

namespace {

std::size_t pixel_count(const DisplayImage& image) {
  return static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
}

// L with 2^L <= n < 2^(L+1), for n >= 1.
int power_of_two_level(std::uint32_t n) {
  int level = 0;
  while (n >>= 1) ++level;
  return level;
}

// Pixel i's mean radiance over `samples` of its samples (all of them, or a power of two it has
// kept), or null when it has not kept that one.
const glm::vec3* mean_radiance_at(const DisplayImage& image, std::size_t i, std::uint32_t samples) {
  if (samples == image.samples[i]) return &image.radiance[i];
  const auto level = static_cast<std::size_t>(power_of_two_level(samples));
  if (level >= image.radiance_at_power_of_two.size() ||
      image.radiance_at_power_of_two[level].empty())
    return nullptr;
  return &image.radiance_at_power_of_two[level][i];
}

void start_generation(DisplayImage& image, std::uint64_t generation, int width, int height,
                      float exposure_scale) {
  const bool same_size = width == image.width && height == image.height;
  image.exposure_scale = exposure_scale;
  image.width = width;
  image.height = height;
  image.generation = generation;
  const std::size_t n = pixel_count(image);
  if (!same_size) {
    image.rgb.assign(3 * n, 0);
    image.radiance.assign(n, glm::vec3(0.0f));
  }
  image.radiance_at_power_of_two.clear();
  image.samples.assign(n, 0);
  image.lights_tested.assign(n, 0.0f);
  image.nodes_visited.assign(n, 0.0f);
  image.error_bound_pct.assign(n, 0.0f);
  image.noise_pct.assign(n, 0.0f);
  image.missed_pct.assign(n, 0.0f);
  image.missed_std_error_pct.assign(n, 0.0f);
  image.has_missed = false;
  image.std_error.assign(n, 0.0);
  image.error_bound_mean.assign(n, glm::vec3(0.0f));
  image.missed_mean.assign(n, glm::vec3(0.0f));
  image.missed_std_error.assign(n, glm::vec3(0.0f));
  image.tile_totals.clear();
  image.tile_seen.clear();
  image.tiles_seen = 0;
  image.pass = 0;
  image.tiles_done_in_pass = 0;
}

// Pixel i's figures in percent at the image's exposure, from the exposure-free ones (a pixel
// without samples has zeros there, and 0 % then, as the renderer's functions give).
void expose_pixel_figures(DisplayImage& image, std::size_t i) {
  const float scale = image.exposure_scale;
  const bool sampled = image.samples[i] > 0;
  image.error_bound_pct[i] =
      sampled ? static_cast<float>(renderer::error_bound_pct(image.error_bound_mean[i] * scale))
              : 0.0f;
  image.noise_pct[i] = static_cast<float>(renderer::std_error_pct(image.std_error[i], scale));
  if (image.has_missed) {
    image.missed_pct[i] =
        sampled ? static_cast<float>(renderer::missed_pct(image.missed_mean[i], scale)) : 0.0f;
    image.missed_std_error_pct[i] =
        sampled
            ? static_cast<float>(renderer::missed_std_error_pct(image.missed_std_error[i], scale))
            : 0.0f;
  }
}

void apply_tile_update(DisplayImage& image, const TileUpdate& u) {
  const auto tile = static_cast<std::size_t>(u.tile);
  if (tile >= image.tile_totals.size()) {
    image.tile_totals.resize(tile + 1);
    image.tile_seen.resize(tile + 1, 0);
  }
  image.tile_totals[tile] = u.totals;
  if (!image.tile_seen[tile]) {
    image.tile_seen[tile] = 1;
    image.tiles_seen += 1;
  }
  if (u.pass != image.pass) {
    image.pass = u.pass;
    image.tiles_done_in_pass = 0;
  }
  image.tiles_done_in_pass += 1;
  const bool missed = !u.missed_mean.empty();
  if (missed) image.has_missed = true;
  std::size_t k = 0;
  for (int y = u.rect.y0; y < u.rect.y1; ++y) {
    for (int x = u.rect.x0; x < u.rect.x1; ++x, ++k) {
      const auto i = static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                     static_cast<std::size_t>(x);
      image.samples[i] = u.samples[k];
      image.lights_tested[i] = u.lights_tested[k];
      image.nodes_visited[i] = u.nodes_visited[k];
      image.std_error[i] = u.std_error[k];
      image.error_bound_mean[i] = u.error_bound_mean[k];
      if (missed) {
        image.missed_mean[i] = u.missed_mean[k];
        image.missed_std_error[i] = u.missed_std_error[k];
      }
      expose_pixel_figures(image, i);
      // Pixels skipped by a subsample keep the backdrop.
      if (u.samples[k] == 0) continue;
      image.radiance[i] = u.radiance[k];
      exposed_rgb8(image.radiance[i], image.exposure_scale, &image.rgb[3 * i]);
      const std::uint32_t n = u.samples[k];
      if ((n & (n - 1)) == 0) {
        const auto level = static_cast<std::size_t>(power_of_two_level(n));
        if (image.radiance_at_power_of_two.size() <= level)
          image.radiance_at_power_of_two.resize(level + 1);
        std::vector<glm::vec3>& at = image.radiance_at_power_of_two[level];
        if (at.empty()) at.assign(pixel_count(image), glm::vec3(0.0f));
        at[i] = u.radiance[k];
      }
    }
  }
}

void start_preview(PreviewImage& preview, std::uint64_t generation, int width, int height) {
  preview.width = width;
  preview.height = height;
  preview.generation = generation;
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  preview.step.assign(n, 0);
  preview.rgb.assign(3 * n, 0);
  preview.radiance.assign(n, glm::vec3(0.0f));
  preview.lights_tested.assign(n, 0.0f);
  preview.nodes_visited.assign(n, 0.0f);
  preview.error_bound_pct.assign(n, 0.0f);
}

// Fills the block of each sample, where no finer level has been received.
void apply_preview_update(PreviewImage& preview, const TileUpdate& u) {
  const int step = u.preview_step;
  std::size_t k = 0;
  for (int py = u.rect.y0; py < u.rect.y1; ++py) {
    for (int px = u.rect.x0; px < u.rect.x1; ++px, ++k) {
      if (u.samples[k] == 0) continue;
      const int x1 = std::min(px * step + step, preview.width);
      const int y1 = std::min(py * step + step, preview.height);
      for (int y = py * step; y < y1; ++y) {
        for (int x = px * step; x < x1; ++x) {
          const auto i = static_cast<std::size_t>(y) * static_cast<std::size_t>(preview.width) +
                         static_cast<std::size_t>(x);
          if (preview.step[i] != 0 && preview.step[i] < step) continue;
          preview.step[i] = static_cast<std::uint8_t>(step);
          for (int c = 0; c < 3; ++c) preview.rgb[3 * i + c] = u.rgb[3 * k + c];
          preview.radiance[i] = u.radiance[k];
          preview.lights_tested[i] = u.lights_tested[k];
          preview.nodes_visited[i] = u.nodes_visited[k];
          preview.error_bound_pct[i] = static_cast<float>(
              renderer::error_bound_pct(u.error_bound_mean[k] * u.exposure_scale));
        }
      }
    }
  }
}

// The pixel shows the preview: the render has not reached it and the preview, of the same
// render, has.
bool shows_preview(const DisplayImage& image, const PreviewImage* preview, std::size_t i) {
  return preview != nullptr && image.samples[i] == 0 && preview->step[i] != 0;
}

// A tile of a newer render (or another size) starts that render's generation.
void follow_generation(DisplayImage& image, const TileUpdate& u) {
  if (u.generation > image.generation || image.width != u.image_width ||
      image.height != u.image_height) {
    start_generation(image, u.generation, u.image_width, u.image_height, u.exposure_scale);
  }
}

}  // namespace

void clear_display_image(DisplayImage& image) {
  const std::uint64_t version = image.version;
  image = DisplayImage{};
  image.version = version + 1;
}

bool expose_display_image(DisplayImage& image, float exposure_scale) {
  if (image.exposure_scale == exposure_scale) return false;
  image.exposure_scale = exposure_scale;
  for (std::size_t i = 0; i < image.samples.size(); ++i) {
    expose_pixel_figures(image, i);
    exposed_rgb8(image.radiance[i], exposure_scale, &image.rgb[3 * i]);
  }
  image.version += 1;
  return true;
}

bool apply_tile_updates(DisplayImage& image, const std::vector<TileUpdate>& updates) {
  bool changed = false;
  for (const TileUpdate& u : updates) {
    if (u.generation < image.generation) continue;
    follow_generation(image, u);
    apply_tile_update(image, u);
    changed = true;
  }
  if (changed) image.version += 1;
  return changed;
}

bool apply_preview_updates(PreviewImage& preview, DisplayImage& image,
                           const std::vector<TileUpdate>& updates) {
  bool changed = false;
  for (const TileUpdate& u : updates) {
    if (u.generation < image.generation || u.generation < preview.generation) continue;
    follow_generation(image, u);
    if (u.generation > preview.generation || preview.width != u.image_width ||
        preview.height != u.image_height) {
      start_preview(preview, u.generation, u.image_width, u.image_height);
    }
    apply_preview_update(preview, u);
    changed = true;
  }
  if (changed) image.version += 1;
  return changed;
}

TileTotals sum_tile_totals(const DisplayImage& image) {
  TileTotals sum;
  for (const TileTotals& t : image.tile_totals) renderer::add_totals(t, sum);
  return sum;
}

ErrorImage compute_error_image(const DisplayImage& image, const DisplayImage& reference,
                               float exposure_scale) {
  ErrorImage e;
  e.image_version = image.version;
  e.reference_version = reference.version;
  e.pct.assign(pixel_count(image), -1.0f);
  e.difference_pct.assign(pixel_count(image), 0.0f);
  if (image.width != reference.width || image.height != reference.height) return e;
  std::vector<std::size_t> compared;
  std::vector<std::uint8_t> a, b;
  std::uint32_t fewest = 0;
  for (std::size_t i = 0; i < e.pct.size(); ++i) {
    const std::uint32_t m = image.samples[i], r = reference.samples[i];
    if (m > 0) ++e.pixels_rendered;
    if (m == 0 || r == 0) continue;
    // All passes when both have as many, else the most passes, a power of two, both kept.
    const std::uint32_t passes = m == r ? m : 1u << power_of_two_level(std::min(m, r));
    const glm::vec3* ra = mean_radiance_at(image, i, passes);
    const glm::vec3* rb = mean_radiance_at(reference, i, passes);
    if (ra == nullptr || rb == nullptr) continue;
    compared.push_back(i);
    // Both exposed now, at one scale: the reference kept across an exposure change compares as
    // a reference rendered at it (its radiance does not depend on the exposure).
    a.resize(a.size() + 3);
    b.resize(b.size() + 3);
    renderer::display_rgb8(*ra, exposure_scale, renderer::DisplayCurve::linear, &a[a.size() - 3]);
    renderer::display_rgb8(*rb, exposure_scale, renderer::DisplayCurve::linear, &b[b.size() - 3]);
    fewest = compared.size() == 1 ? passes : std::min(fewest, passes);
  }
  e.passes = static_cast<int>(fewest);
  const std::vector<double> pct = renderer::pixel_error_pct(a, b);
  const renderer::PixelErrorStats stats = renderer::summarize_pixel_error(pct);
  for (std::size_t k = 0; k < compared.size(); ++k) {
    const std::size_t i = compared[k];
    e.pct[i] = static_cast<float>(pct[k]);
    int signed_sum = 0;
    for (std::size_t c = 0; c < 3; ++c)
      signed_sum += static_cast<int>(a[3 * k + c]) - static_cast<int>(b[3 * k + c]);
    e.difference_pct[i] = static_cast<float>(100.0 * signed_sum / 765.0);
  }
  e.average_pct = stats.average_pct;
  e.max_pct = stats.max_pct;
  e.pixels_compared = compared.size();
  return e;
}

namespace {

// The image as displayed (colours not rendered yet dimmed, or the preview's).
void image_rgb8(const DisplayImage& image, const PreviewImage* preview,
                const renderer::Display& display, std::vector<std::uint8_t>& rgb) {
  const float scale = renderer::exposure_scale(display.exposure_ev);
  for (std::size_t i = 0; i < pixel_count(image); ++i) {
    // Colours of the previous render (same size) stay visible, dimmed, until redrawn.
    if (shows_preview(image, preview, i)) {
      renderer::display_rgb8(preview->radiance[i], scale, display.curve, &rgb[3 * i]);
      continue;
    }
    renderer::display_rgb8(image.radiance[i], scale, display.curve, &rgb[3 * i]);
    if (image.samples[i] == 0) {
      for (int c = 0; c < 3; ++c)
        rgb[3 * i + c] = static_cast<std::uint8_t>(rgb[3 * i + c] * 2 / 5);
    }
  }
}

// The value range the row's rule gives over the known values.
renderer::HeatmapRange view_range(const ViewInfo& info, const std::vector<double>& values,
                                  const std::vector<std::uint8_t>& known) {
  switch (info.range_rule) {
    case RangeRule::none:
      return {};
    case RangeRule::symmetric_fixed:
      return {-info.fixed_range, info.fixed_range};
    case RangeRule::threshold:
      return {0.0, 1.0};
    case RangeRule::data: {
      double lo = std::numeric_limits<double>::max(), hi = 0.0;
      bool any = false;
      for (std::size_t i = 0; i < values.size(); ++i) {
        if (!known[i]) continue;
        any = true;
        lo = std::min(lo, values[i]);
        hi = std::max(hi, values[i]);
      }
      return any ? renderer::HeatmapRange{lo, hi} : renderer::HeatmapRange{};
    }
  }
  throw std::logic_error("range rule missing from view_range");
}

std::vector<std::uint8_t> compose_rgb8(
    const DisplayImage& image, const PreviewImage* preview, const ErrorImage& error, ViewMode mode,
    const renderer::Display& display, double mask_threshold_pct, renderer::HeatmapRange& range,
    const std::optional<renderer::HeatmapRange>& locked_range = std::nullopt) {
  const std::size_t n = pixel_count(image);
  if (preview != nullptr && (preview->generation != image.generation ||
                             preview->width != image.width || preview->height != image.height)) {
    preview = nullptr;
  }
  const ViewInfo& info = view_info(mode);
  std::vector<std::uint8_t> rgb(3 * n);
  range = {};
  if (info.colour_map == ColourMap::image || info.colour_map == ColourMap::mask)
    image_rgb8(image, preview, display, rgb);
  if (info.colour_map == ColourMap::image) return rgb;
  const ViewPixels pixels = view_pixels(image, error, mask_threshold_pct);
  // The preview's own fields (a preview sample counts as one sample).
  std::vector<std::uint32_t> preview_samples;
  ViewPixels preview_pixels;
  if (preview != nullptr) {
    preview_samples.resize(n);
    for (std::size_t i = 0; i < n; ++i) preview_samples[i] = preview->step[i] != 0 ? 1 : 0;
    preview_pixels.count = n;
    preview_pixels.samples = preview_samples.data();
    preview_pixels.lights_tested = preview->lights_tested.data();
    preview_pixels.nodes_visited = preview->nodes_visited.data();
    preview_pixels.error_bound_pct = preview->error_bound_pct.data();
  }
  std::vector<double> values(n, 0.0);
  std::vector<std::uint8_t> known(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::optional<double> v =
        shows_preview(image, preview, i) ? info.value(preview_pixels, i) : info.value(pixels, i);
    known[i] = v.has_value();
    if (v) values[i] = *v;
  }
  range = locked_range && info.range_rule == RangeRule::data ? *locked_range
                                                             : view_range(info, values, known);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint8_t* out = &rgb[3 * i];
    if (!known[i]) {
      for (int c = 0; c < 3; ++c) out[c] = kNotRenderedRgb[c];
      continue;
    }
    switch (info.colour_map) {
      case ColourMap::image:
        break;
      case ColourMap::sequential: {
        const glm::u8vec3 heat =
            renderer::viridis(static_cast<float>(heatmap_position(values[i], range)));
        for (int c = 0; c < 3; ++c) out[c] = heat[c];
        break;
      }
      case ColourMap::diverging: {
        const glm::u8vec3 c3 = diverging_rgb8(values[i] / info.fixed_range);
        for (int c = 0; c < 3; ++c) out[c] = c3[c];
        break;
      }
      case ColourMap::mask:
        if (values[i] > 0.0) {
          for (int c = 0; c < 3; ++c) out[c] = kMaskRgb[c];
        } else {
          for (int c = 0; c < 3; ++c) out[c] = static_cast<std::uint8_t>(out[c] / 3);
        }
        break;
    }
  }
  return rgb;
}

}  // namespace

ViewPixels view_pixels(const DisplayImage& image, const ErrorImage& error,
                       double mask_threshold_pct) {
  ViewPixels p;
  p.count = pixel_count(image);
  p.samples = image.samples.data();
  p.lights_tested = image.lights_tested.data();
  p.nodes_visited = image.nodes_visited.data();
  p.error_bound_pct = image.error_bound_pct.data();
  p.noise_pct = image.noise_pct.data();
  if (image.has_missed) {
    p.missed_pct = image.missed_pct.data();
    p.missed_std_error_pct = image.missed_std_error_pct.data();
  }
  if (error.pct.size() == p.count && p.count > 0) {
    p.error_pct = error.pct.data();
    p.difference_pct = error.difference_pct.data();
  }
  p.mask_threshold_pct = mask_threshold_pct;
  return p;
}

std::vector<std::uint8_t> view_rgb8(const DisplayImage& image, const ErrorImage& error,
                                    ViewMode mode, renderer::HeatmapRange& range,
                                    const renderer::Display& display, double mask_threshold_pct,
                                    const std::optional<renderer::HeatmapRange>& locked_range) {
  return compose_rgb8(image, nullptr, error, mode, display, mask_threshold_pct, range,
                      locked_range);
}

void compose_view_rgba(const DisplayImage& image, const PreviewImage& preview,
                       const ErrorImage& error, ViewMode mode, std::vector<std::uint8_t>& rgba,
                       renderer::HeatmapRange& range, const renderer::Display& display,
                       double mask_threshold_pct, const AbSplit& ab,
                       const std::optional<renderer::HeatmapRange>& locked_range) {
  std::vector<std::uint8_t> rgb =
      compose_rgb8(image, &preview, error, mode, display, mask_threshold_pct, range, locked_range);
  const DisplayImage* reference = ab.reference;
  if (view_info(mode).colour_map == ColourMap::image && reference != nullptr &&
      reference->width == image.width && reference->height == image.height &&
      ab.rt_from_x < image.width) {
    std::vector<std::uint8_t> rt(rgb.size());
    image_rgb8(*reference, nullptr, display, rt);
    const auto width = static_cast<std::size_t>(image.width);
    const auto from = static_cast<std::size_t>(std::max(ab.rt_from_x, 0));
    for (std::size_t i = 0; i < rt.size() / 3; ++i) {
      if (i % width < from) continue;
      for (int c = 0; c < 3; ++c) rgb[3 * i + c] = rt[3 * i + c];
    }
  }
  const std::size_t n = rgb.size() / 3;
  rgba.resize(4 * n);
  for (std::size_t i = 0; i < n; ++i) {
    rgba[4 * i] = rgb[3 * i];
    rgba[4 * i + 1] = rgb[3 * i + 1];
    rgba[4 * i + 2] = rgb[3 * i + 2];
    rgba[4 * i + 3] = 255;
  }
}

}  // namespace app::viewer
