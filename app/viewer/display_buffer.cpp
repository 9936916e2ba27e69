#include "app/viewer/display_buffer.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "renderer/error_bound.h"
#include "renderer/missed_light.h"
#include "renderer/pixel_noise.h"

namespace app::viewer {

void exposed_rgb8(const glm::vec3& mean_radiance, float exposure_scale, std::uint8_t* rgb) {
  const glm::vec3 exposed = mean_radiance * exposure_scale;
  for (int c = 0; c < 3; ++c) {
    const float v = std::isnan(exposed[c]) ? 0.0f : std::clamp(exposed[c], 0.0f, 1.0f);
    rgb[c] = static_cast<std::uint8_t>(std::lround(v * 255.0f));
  }
}

void mean_rgb8(const renderer::Framebuffer& f, std::size_t pixel, std::uint8_t* rgb) {
  if (f.samples[pixel] == 0) {
    rgb[0] = rgb[1] = rgb[2] = 0;
    return;
  }
  exposed_rgb8(f.radiance_sum[pixel] / static_cast<float>(f.samples[pixel]), f.exposure_scale, rgb);
}

namespace {

TileUpdate copy_rect(const renderer::Framebuffer& f, std::uint64_t generation, int tile, int pass,
                     const TileRect& rect) {
  TileUpdate u;
  u.generation = generation;
  u.image_width = f.width;
  u.image_height = f.height;
  u.tile = tile;
  u.pass = pass;
  u.rect = rect;
  u.exposure_scale = f.exposure_scale;
  const auto count =
      static_cast<std::size_t>(rect.x1 - rect.x0) * static_cast<std::size_t>(rect.y1 - rect.y0);
  u.rgb.resize(3 * count);
  u.radiance.assign(count, glm::vec3(0.0f));
  u.samples.resize(count);
  u.lights_tested.resize(count);
  u.nodes_visited.resize(count);
  u.error_bound_mean.resize(count);
  u.std_error.resize(count);
  const bool missed = !f.missed_sum.empty();
  if (missed) {
    u.missed_mean.resize(count);
    u.missed_std_error.resize(count);
  }
  std::size_t k = 0;
  for (int y = rect.y0; y < rect.y1; ++y) {
    for (int x = rect.x0; x < rect.x1; ++x, ++k) {
      const auto i = static_cast<std::size_t>(y) * static_cast<std::size_t>(f.width) +
                     static_cast<std::size_t>(x);
      mean_rgb8(f, i, &u.rgb[3 * k]);
      const std::uint32_t n = f.samples[i];
      if (n > 0) u.radiance[k] = f.radiance_sum[i] / static_cast<float>(n);
      u.samples[k] = n;
      u.lights_tested[k] =
          n > 0 ? static_cast<float>(f.lights_tested[i]) / static_cast<float>(n) : 0.0f;
      u.nodes_visited[k] =
          n > 0 ? static_cast<float>(f.nodes_visited[i]) / static_cast<float>(n) : 0.0f;
      u.error_bound_mean[k] = renderer::pixel_error_bound_mean(f, i);
      u.std_error[k] = renderer::pixel_std_error(f, i);
      if (missed) {
        u.missed_mean[k] = renderer::pixel_missed_mean(f, i);
        u.missed_std_error[k] = renderer::pixel_missed_std_error(f, i);
      }
      renderer::add_pixel_totals(f, i, u.totals);
    }
  }
  return u;
}

int first_multiple_at_or_after(int x, int step) {
  return (x + step - 1) / step;
}

}  // namespace

TileUpdate copy_tile(const renderer::Framebuffer& framebuffer, std::uint64_t generation, int tile,
                     int pass, const TileRect& rect) {
  return copy_rect(framebuffer, generation, tile, pass, rect);
}

TileUpdate copy_preview_tile(const renderer::Framebuffer& preview, int step, int image_width,
                             int image_height, std::uint64_t generation, int tile,
                             const TileRect& rect) {
  // The tile's samples are at the multiples of step inside it: preview pixels
  // ceil(x0 / step) .. ceil(x1 / step) - 1.
  const TileRect samples{
      first_multiple_at_or_after(rect.x0, step), first_multiple_at_or_after(rect.y0, step),
      first_multiple_at_or_after(rect.x1, step), first_multiple_at_or_after(rect.y1, step)};
  TileUpdate u = copy_rect(preview, generation, tile, 0, samples);
  u.preview_step = step;
  u.image_width = image_width;
  u.image_height = image_height;
  u.totals = {};  // preview work is no part of the render's statistics
  return u;
}

void DisplayBuffer::raise_floor(std::uint64_t generation) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (generation <= floor_) return;
  floor_ = generation;
  updates_.erase(std::remove_if(updates_.begin(), updates_.end(),
                                [&](const TileUpdate& u) { return u.generation < floor_; }),
                 updates_.end());
}

void DisplayBuffer::post(TileUpdate update) {
  const std::lock_guard<std::mutex> lock(mutex_);
  posted_ += 1;
  if (update.generation < floor_) return;
  updates_.push_back(std::move(update));
}

TakenTiles DisplayBuffer::take_all() {
  TakenTiles taken;
  const std::lock_guard<std::mutex> lock(mutex_);
  taken.floor = floor_;
  taken.updates.swap(updates_);
  return taken;
}

std::uint64_t DisplayBuffer::posted() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return posted_;
}

}  // namespace app::viewer
