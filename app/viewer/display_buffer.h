// How finished tiles travel from the tile workers to the UI thread. The tile-done callback runs
// on a worker right after a tile's pixels are final; it copies them (colour, samples, counters)
// out of the framebuffer into a TileUpdate and posts it to a DisplayBuffer under a mutex. The UI
// thread takes everything posted so far in one swap each frame. Either side holds the lock only
// for a push or a swap, so the UI never waits for the tracer and never reads framebuffer pixels
// that a worker may be writing.
#pragma once

#include <cstdint>
#include <mutex>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/framebuffer.h"

namespace app::viewer {

// Sums over a tile's pixels, every pass so far.
using TileTotals = renderer::FramebufferTotals;

struct TileRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels, x1 and y1 exclusive
};

struct TileUpdate {
  std::uint64_t generation = 0;  // the render it belongs to (the request serial)
  int image_width = 0;
  int image_height = 0;
  int tile = 0;
  int pass = 0;  // the pass that just finished this tile
  // 1: a tile of the render, rect in image pixels. > 1: a preview tile, whose samples sit every
  // preview_step pixels; rect is in preview pixels (image pixels / preview_step) and each sample
  // stands for the preview_step x preview_step block of image pixels it is the corner of.
  int preview_step = 1;
  TileRect rect;
  std::vector<std::uint8_t> rgb;  // mean exposed linear colour, 8-bit RGB (what errors compare)
  float exposure_scale = 1.0f;    // the render's (Framebuffer::exposure_scale): of rgb
  // Mean scene-linear radiance, rows of the tile: the UI maps it through the current exposure
  // and display curve, so changing those re-maps the image without a new render.
  std::vector<glm::vec3> radiance;
  std::vector<std::uint32_t> samples;
  std::vector<float> lights_tested;  // per sample
  std::vector<float> nodes_visited;  // per sample
  TileTotals totals;
  // The figures measured on the displayed scale, before the exposure, so that the UI puts them in
  // percent at the exposure it shows (DisplayImage::exposure_scale), as a render at that exposure
  // reports them: the estimated standard error (renderer/pixel_noise.h), the certified error
  // bound per channel (renderer/error_bound.h), and the missed-light estimate and its standard
  // error (renderer/missed_light.h), those two empty when the render does not estimate it.
  std::vector<double> std_error;
  std::vector<glm::vec3> error_bound_mean;
  std::vector<glm::vec3> missed_mean;
  std::vector<glm::vec3> missed_std_error;
};

// 8-bit colour of a mean radiance exactly as renderer::framebuffer_rgb8 computes it, so that
// the viewer's pixel errors equal `levrt render --reference rt`'s.
void mean_rgb8(const renderer::Framebuffer& framebuffer, std::size_t pixel, std::uint8_t* rgb);
// The same of a pixel's mean scene-linear radiance at an exposure (what mean_rgb8 computes from
// the framebuffer's sums at its own exposure, bit for bit).
void exposed_rgb8(const glm::vec3& mean_radiance, float exposure_scale, std::uint8_t* rgb);

// Copies one tile out of the framebuffer; call only while that tile's pixels are final.
TileUpdate copy_tile(const renderer::Framebuffer& framebuffer, std::uint64_t generation, int tile,
                     int pass, const TileRect& rect);

// Copies the samples one preview tile (image-pixel rect `rect`) put into the render's preview
// framebuffer (renderer::render_preview) at pixel step `step`, for an image of image_width x
// image_height pixels.
TileUpdate copy_preview_tile(const renderer::Framebuffer& preview, int step, int image_width,
                             int image_height, std::uint64_t generation, int tile,
                             const TileRect& rect);

struct TakenTiles {
  std::uint64_t floor = 0;  // renders older than this are gone: their pixels are stale
  std::vector<TileUpdate> updates;
};

class DisplayBuffer {
 public:
  // Drops updates of renders older than `generation`, queued or posted later. The worker raises
  // the floor whenever it ends a render, so the UI never sees tiles of a render that is gone.
  void raise_floor(std::uint64_t generation);
  void post(TileUpdate update);
  TakenTiles take_all();
  // Tiles posted so far, kept or dropped: what a caller counts to know how many tiles a worker
  // finished after some moment (RenderWorker::shut_down).
  std::uint64_t posted() const;

 private:
  mutable std::mutex mutex_;
  std::uint64_t floor_ = 0;
  std::uint64_t posted_ = 0;
  std::vector<TileUpdate> updates_;
};

}  // namespace app::viewer
