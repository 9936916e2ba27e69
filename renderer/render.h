// The one progressive render step, under the render service every front end calls
// (render_service.h): a RenderState plus render_pass, which renders one more sample per pixel
// over all tiles on the pass's worker threads (tile_workers.h). Pass 0 samples pixel centres,
// pass k > 0 a jittered position (unless RenderSettings::jitter_pixels is off) drawn from the
// (pixel, pass) random stream, so images never depend on thread count or tile order. A pass can be
// cancelled at any time (the flag is read between tiles, per row, in the recursion and every few
// thousand lights); finished tiles keep their sample, an interrupted tile adds none. The same pass
// with a pixel step > 1 is a preview: one pixel-centre sample every step pixels in x and y, kept
// apart from the framebuffer (see render_pass), for a viewer that shows the whole frame coarsely
// before the full-resolution passes arrive.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

#include "lev/methods.h"
#include "renderer/framebuffer.h"
#include "renderer/ray_log.h"
#include "renderer/ray_scene.h"
#include "renderer/rt_fallback.h"
#include "renderer/scene.h"

namespace renderer {

// The image size unless told otherwise: every image of the thesis is 320x240 (thesis 5.4).
inline constexpr int kDefaultImageWidth = 320;
inline constexpr int kDefaultImageHeight = 240;

// The image the user asks for: the renderer's group of the user's settings (app/settings.h
// composes it; RenderSettings is made from it and the method's group). Every member is compared.
struct ImageSettings {
  int width = kDefaultImageWidth;
  int height = kDefaultImageHeight;
  int spp = 1;        // passes, one sample per pixel each
  int depth = 5;      // reflection/refraction depth
  int subsample = 1;  // render every n-th pixel in x and y (for slow references)
  int threads = 0;    // 0 = all cores
  // Draws per shading point of the missed-light estimate (renderer/missed_light.h); 0: off.
  int missed_draws = 0;
};
bool operator==(const ImageSettings& a, const ImageSettings& b);
bool operator!=(const ImageSettings& a, const ImageSettings& b);

struct RenderSettings {
  int width = kDefaultImageWidth;
  int height = kDefaultImageHeight;
  int max_depth = 5;
  int threads = 0;  // 0 = all cores
  int tile_size = 16;
  int pixel_stride = 1;  // > 1: render only every stride-th pixel in x and y (a subsample)
  lev::Method method = lev::Method::lev;
  float tolerance = static_cast<float>(lev::kDefaultTolerance);
  int lights_per_point =
      1;  // lights a sampling method draws per shading point, [1, lev::kMaxLightsPerPoint]
  float relative_error = static_cast<float>(lev::kDefaultRelativeError);  // [0, 1] (lightcuts)
  std::uint64_t seed = 0;
  // Fill Framebuffer::error_bound_sum (error_bound.h). Off by default: the renders whose cost is
  // compared (the bench) skip the selectors' bound work; `levrt render` and the viewer ask for it.
  bool compute_error_bound = false;
  // Pass k > 0 samples a jittered position in the pixel (antialiasing). Off, every pass samples
  // the pixel centres, so only a sampling method's light draws differ between passes and its
  // passes converge to the one-pass rt image (the bench's converge experiment).
  bool jitter_pixels = true;
  // > 0: estimate the missed light (lev/missed_light.h) with this many draws per shading point
  // into Framebuffer::missed_sum (renderer/missed_light.h), in [kMinMissedDraws,
  // lev::kMaxLightsPerPoint]; 0: off, and the selectors do none of that work.
  int missed_draws = 0;
  // The exposure of the displayed units (renderer/display_transform.h): the tolerance, the
  // relative methods' absolute floor and every error metric read radiance x 2^exposure_ev, so
  // they mean the same on the displayed image at any exposure. The radiance itself stays
  // scene-linear. The framebuffer records it (Framebuffer::exposure_scale).
  double exposure_ev = 0.0;
  // A deterministic method may shade with rt's loop where a probe of the frame says its work
  // would cost more than rt's (rt_fallback.h). Off by default, so that a state renders the method
  // it is given; the user's settings turn it on (lev::MethodChoice::rt_fallback).
  bool rt_fallback = false;
};

// The primary ray of pixel (x, y)'s sample in pass `pass`, with the method's and the missed-light
// estimate's random streams seeded for it, as every render seeds them (the pixel inspector
// traces the same sample).
Ray pixel_sample_ray(const RenderSettings& settings, const Camera& camera, int x, int y,
                     std::uint64_t pass, lev::RandomStream& method_random,
                     lev::RandomStream& missed_random);

// The settings the method's selector is made with.
lev::MethodParams method_params(const RenderSettings& settings);

// The fewest draws the missed-light estimate takes: two, for the spread behind its standard error.
inline constexpr int kMinMissedDraws = 2;

enum class TileStatus : std::uint8_t { waiting, rendering, done };

struct RenderState;  // defined in render.cpp (holds the per-worker scratch)

struct RenderStateDeleter {
  void operator()(RenderState* state) const;
};
using RenderStatePtr = std::unique_ptr<RenderState, RenderStateDeleter>;

// The selector a render of `settings` shades with: the method's, or rt's where settings.rt_fallback
// is on, the method can fall back, and the probe (rt_fallback.h) chose rt's loop. *probe (when not
// null) receives the probe, or nothing when none was made. make_render_state and the pixel
// inspector (`levrt inspect`) both make theirs here, so the inspector traces what the render
// shades.
std::unique_ptr<lev::LightSelector> make_render_selector(const Scene& scene, const RayScene& rays,
                                                         const RenderSettings& settings,
                                                         std::optional<RtFallbackProbe>* probe);

// Makes the method's selector for settings.tolerance (a `lev` state fits its own extent volumes;
// the scene is only read, so states with different tolerances and methods may render one scene
// at the same time). The state refers to scene and rays; they must outlive it.
RenderStatePtr make_render_state(const Scene& scene, const RayScene& rays,
                                 const RenderSettings& settings);

// Called on the worker thread right after a tile's pixels are final for this pass; it may read
// that tile's framebuffer pixels (nothing else writes them until the next pass). The viewer
// copies finished tiles to its display buffer here, so the UI never reads pixels in flight.
using TileDoneCallback = std::function<void(int tile)>;

// One more pass. Returns false when *cancel became true before every tile was done.
// preview_step > 1 makes it a preview pass: each tile samples the pixel centres (x, y) with
// x and y multiples of preview_step into render_preview (cleared first), whose pixel
// (x / step, y / step) holds that sample. A preview never touches render_framebuffer, the pass
// count, the render time or the method's state between passes (a method that learns between
// passes previews with a selector of its own; the others with the render's, whose extent volumes
// are then fitted once), so nothing made from the framebuffer (image, heatmaps, stats) can
// contain a preview sample, and the passes after it equal those of a state that never previewed.
bool render_pass(RenderState& state, const std::atomic<bool>* cancel = nullptr,
                 const TileDoneCallback& on_tile_done = nullptr, int preview_step = 1);

// From the next pass on, every ray the passes cast is appended to *log, per tile (null stops
// recording). The log must outlive the passes that write it.
void record_rays(RenderState& state, RayLog* log);

const Framebuffer& render_framebuffer(const RenderState& state);
// The last preview pass's samples, ceil(width / step) x ceil(height / step); empty before one.
const Framebuffer& render_preview(const RenderState& state);
const RenderSettings& render_settings(const RenderState& state);
int render_passes_done(const RenderState& state);
double render_seconds(const RenderState& state);  // wall time spent in render_pass
const lev::LightSelector& render_selector(const RenderState& state);
// The probe that chose between the method and rt's loop (rt_fallback.h); null when the settings
// asked for none or the method cannot fall back.
const RtFallbackProbe* render_rt_fallback(const RenderState& state);
// Tile grid and the live status of each tile (for the viewer's in-flight markers).
int render_tile_count(const RenderState& state);
TileStatus render_tile_status(const RenderState& state, int tile);
void render_tile_rect(const RenderState& state, int tile, int& x0, int& y0, int& x1, int& y1);

}  // namespace renderer
