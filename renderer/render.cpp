#include "renderer/render.h"

#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <vector>

#include "renderer/denormal_mode.h"
#include "renderer/display_transform.h"
#include "renderer/shading.h"
#include "renderer/tile_workers.h"

namespace renderer {

struct RenderState {
  const Scene& scene;
  const RayScene& rays;
  RenderSettings settings;
  // The method's selector, or rt's when the probe chose rt's loop (rt_fallback).
  std::unique_ptr<lev::LightSelector> selector;
  std::optional<RtFallbackProbe> rt_fallback;
  Framebuffer framebuffer;
  // Preview passes of a method that learns between passes (AST's statistics): their own
  // selector (made at the first preview), so that it never learns from preview samples. Every
  // other method previews with `selector`, so a new render state fits its extent volumes once.
  std::unique_ptr<lev::LightSelector> preview_selector;
  Framebuffer preview;
  int passes_done = 0;
  double seconds = 0.0;
  int tiles_x = 0, tiles_y = 0;
  std::unique_ptr<std::atomic<TileStatus>[]> tiles;
  // Passes each tile has completed: a pass resumed after a cancel skips the tiles it already
  // finished, so no pixel gets the same sample twice.
  std::vector<int> tile_passes;
  // One scratch per worker thread of a pass (tile_workers.h), kept from pass to pass.
  std::vector<lev::SelectorScratch> scratch;
  RayLog* ray_log = nullptr;

  RenderState(const Scene& s, const RayScene& r, const RenderSettings& settings_in)
      : scene(s), rays(r), settings(settings_in) {}
};

void RenderStateDeleter::operator()(RenderState* state) const {
  delete state;
}

namespace {

std::uint64_t mix(std::uint64_t a, std::uint64_t b) {
  lev::RandomStream s{a ^ (b * 0xD1B54A32D192ED03ull)};
  return s.next_u64();
}

// One sample for each pixel of the tile, or nothing: the samples are made in a local buffer and
// added to the framebuffer only when the whole tile is done, so a tile cancelled mid-way (the
// flag is read per row and in the recursion) leaves no pixel with a sample a resumed pass would
// add again. Returns false when cancelled. A preview (preview_step > 1) samples every step-th
// pixel into state.preview instead and records no rays.
bool render_tile(RenderState& state, int tile, lev::SelectorScratch& scratch,
                 const std::atomic<bool>* cancel, int preview_step) {
  DenormalModeGuard denormals;
  const RenderSettings& rs = state.settings;
  const bool preview = preview_step > 1;
  const int step = preview ? preview_step : rs.pixel_stride;
  int x0, y0, x1, y1;
  render_tile_rect(state, tile, x0, y0, x1, y1);
  std::vector<LoggedRay>* ray_log =
      state.ray_log && !preview ? &state.ray_log->tiles[static_cast<std::size_t>(tile)] : nullptr;
  const std::size_t logged_before = ray_log ? ray_log->size() : 0;
  scratch.cancel = cancel;
  const lev::LightSelector& selector =
      preview && state.preview_selector ? *state.preview_selector : *state.selector;
  TraceContext context{state.scene,  state.rays, selector, scratch,
                       rs.max_depth, ray_log,    cancel,   rs.compute_error_bound};
  context.missed_draws = preview ? 0 : rs.missed_draws;
  struct PixelSample {
    std::size_t pixel;
    glm::vec3 radiance;
    PathCounters counters;
  };
  std::vector<PixelSample> samples;
  samples.reserve(static_cast<std::size_t>(x1 - x0) * static_cast<std::size_t>(y1 - y0));
  // A preview samples pixel centres, as pass 0 does.
  const auto pass = preview ? 0 : static_cast<std::uint64_t>(state.passes_done);
  for (int y = y0; y < y1; ++y) {
    if (y % step != 0) continue;
    if (cancel && cancel->load(std::memory_order_relaxed)) break;
    for (int x = x0; x < x1; ++x) {
      if (x % step != 0) continue;
      const auto pixel = static_cast<std::size_t>(y) * static_cast<std::size_t>(rs.width) +
                         static_cast<std::size_t>(x);
      const Ray ray = pixel_sample_ray(rs, state.scene.camera, x, y, pass, scratch.random,
                                       context.missed_random);
      PixelSample& sample = samples.emplace_back();
      sample.pixel = preview ? static_cast<std::size_t>(y / step) *
                                       static_cast<std::size_t>(state.preview.width) +
                                   static_cast<std::size_t>(x / step)
                             : pixel;
      sample.radiance = clamp_sample_radiance(trace_radiance(context, ray, 0, sample.counters));
    }
  }
  if (cancel && cancel->load(std::memory_order_relaxed)) {
    if (ray_log) ray_log->resize(logged_before);
    return false;
  }
  Framebuffer& fb = preview ? state.preview : state.framebuffer;
  for (const PixelSample& sample : samples) {
    fb.radiance_sum[sample.pixel] += sample.radiance;
    fb.samples[sample.pixel] += 1;
    fb.shading_points[sample.pixel] += sample.counters.shading_points;
    fb.lights_tested[sample.pixel] += sample.counters.selection.lights_tested;
    fb.nodes_visited[sample.pixel] += sample.counters.selection.nodes_visited;
    fb.shadow_rays[sample.pixel] += sample.counters.selection.shadow_rays;
    fb.error_bound_sum[sample.pixel] += sample.counters.error_bound;
    const glm::dvec3 radiance(sample.radiance);
    fb.radiance_square_sum[sample.pixel] += radiance * radiance;
    if (!fb.missed_sum.empty()) {
      fb.missed_sum[sample.pixel] += sample.counters.missed;
      fb.missed_variance_sum[sample.pixel] += sample.counters.missed_variance;
    }
  }
  return true;
}

}  // namespace

Ray pixel_sample_ray(const RenderSettings& rs, const Camera& camera, int x, int y,
                     std::uint64_t pass, lev::RandomStream& method_random,
                     lev::RandomStream& missed_random) {
  const auto pixel = static_cast<std::size_t>(y) * static_cast<std::size_t>(rs.width) +
                     static_cast<std::size_t>(x);
  lev::RandomStream random{mix(mix(rs.seed, pixel), pass)};
  float jx = 0.5f, jy = 0.5f;
  if (pass > 0 && rs.jitter_pixels) {
    jx = random.next_float();
    jy = random.next_float();
  }
  method_random.state = random.next_u64();
  missed_random.state = random.next_u64();  // after the method's: it never moves it
  return primary_ray(camera, rs.width, rs.height, static_cast<float>(x) + jx,
                     static_cast<float>(y) + jy);
}

lev::MethodParams method_params(const RenderSettings& settings) {
  lev::MethodParams params;
  params.method = settings.method;
  params.tolerance = settings.tolerance;
  params.relative_error = settings.relative_error;
  params.lights_per_point = settings.lights_per_point;
  params.display_scale = exposure_scale(settings.exposure_ev);
  return params;
}

bool operator==(const ImageSettings& a, const ImageSettings& b) {
  // Binding every member: a member added to ImageSettings stops this compiling until it is
  // compared too.
  const auto& [width, height, spp, depth, subsample, threads, missed_draws] = a;
  return width == b.width && height == b.height && spp == b.spp && depth == b.depth &&
         subsample == b.subsample && threads == b.threads && missed_draws == b.missed_draws;
}

bool operator!=(const ImageSettings& a, const ImageSettings& b) {
  return !(a == b);
}

std::unique_ptr<lev::LightSelector> make_render_selector(const Scene& scene, const RayScene& rays,
                                                         const RenderSettings& settings,
                                                         std::optional<RtFallbackProbe>* probe) {
  if (probe) probe->reset();
  std::unique_ptr<lev::LightSelector> selector =
      lev::make_selector(scene.lights, method_params(settings));
  if (!settings.rt_fallback || !lev::rt_fallback_applies(lev::method_info(settings.method)))
    return selector;
  // A selector that learns would learn from the probe's points: it is probed through a copy.
  std::unique_ptr<lev::LightSelector> probed;
  if (selector->learns_between_passes())
    probed = lev::make_selector(scene.lights, method_params(settings));
  const RtFallbackProbe made =
      probe_rt_fallback(scene, rays, settings, probed ? *probed : *selector);
  if (probe) *probe = made;
  if (!made.use_rt) return selector;
  lev::MethodParams rt = method_params(settings);
  rt.method = lev::reference_method();
  return lev::make_selector(scene.lights, rt);
}

RenderStatePtr make_render_state(const Scene& scene, const RayScene& rays,
                                 const RenderSettings& settings) {
  if (settings.width < 1 || settings.height < 1 || settings.tile_size < 1 ||
      settings.pixel_stride < 1 || settings.max_depth < 0 || settings.threads < 0 ||
      settings.lights_per_point < 1 || settings.lights_per_point > lev::kMaxLightsPerPoint ||
      !(settings.relative_error >= 0.0f && settings.relative_error <= 1.0f) ||
      (settings.missed_draws != 0 && (settings.missed_draws < kMinMissedDraws ||
                                      settings.missed_draws > lev::kMaxLightsPerPoint))) {
    throw std::invalid_argument("render settings out of range");
  }
  RenderStatePtr state(new RenderState(scene, rays, settings));
  state->selector = make_render_selector(scene, rays, settings, &state->rt_fallback);
  state->framebuffer = make_framebuffer(settings.width, settings.height);
  state->framebuffer.exposure_scale = exposure_scale(settings.exposure_ev);
  if (settings.missed_draws > 0) allocate_missed_light(state->framebuffer);
  state->tiles_x = (settings.width + settings.tile_size - 1) / settings.tile_size;
  state->tiles_y = (settings.height + settings.tile_size - 1) / settings.tile_size;
  const int tile_count = state->tiles_x * state->tiles_y;
  state->tiles.reset(new std::atomic<TileStatus>[static_cast<std::size_t>(tile_count)]);
  for (int i = 0; i < tile_count; ++i) state->tiles[i].store(TileStatus::waiting);
  state->tile_passes.assign(static_cast<std::size_t>(tile_count), 0);
  state->scratch.resize(static_cast<std::size_t>(worker_count(settings.threads)));
  return state;
}

bool render_pass(RenderState& state, const std::atomic<bool>* cancel,
                 const TileDoneCallback& on_tile_done, int preview_step) {
  if (preview_step < 1)
    throw std::invalid_argument("render_pass: the preview step must be at least 1");
  const bool preview = preview_step > 1;
  if (preview) {
    if (!state.preview_selector && state.selector->learns_between_passes())
      state.preview_selector =
          lev::make_selector(state.scene.lights, method_params(state.settings));
    state.preview = make_framebuffer((state.settings.width + preview_step - 1) / preview_step,
                                     (state.settings.height + preview_step - 1) / preview_step);
    state.preview.exposure_scale = state.framebuffer.exposure_scale;
  }
  const int tile_count = render_tile_count(state);
  for (int i = 0; i < tile_count; ++i) {
    const bool finished =
        !preview && state.tile_passes[static_cast<std::size_t>(i)] > state.passes_done;
    state.tiles[i].store(finished ? TileStatus::done : TileStatus::waiting);
  }
  const auto start = std::chrono::steady_clock::now();
  std::atomic<bool> cancelled{false};
  run_tile_workers(static_cast<int>(state.scratch.size()), tile_count, [&](int worker, int tile) {
    if (cancel && cancel->load(std::memory_order_relaxed)) {
      cancelled.store(true, std::memory_order_relaxed);
      return false;
    }
    int& passes = state.tile_passes[static_cast<std::size_t>(tile)];
    if (!preview && passes > state.passes_done) return true;
    state.tiles[tile].store(TileStatus::rendering, std::memory_order_release);
    if (!render_tile(state, tile, state.scratch[static_cast<std::size_t>(worker)], cancel,
                     preview_step)) {
      state.tiles[tile].store(TileStatus::waiting, std::memory_order_release);
      cancelled.store(true, std::memory_order_relaxed);
      return false;
    }
    if (!preview) passes += 1;
    if (on_tile_done) on_tile_done(tile);
    state.tiles[tile].store(TileStatus::done, std::memory_order_release);
    return true;
  });
  if (preview) return !cancelled.load();
  state.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (cancelled.load()) return false;
  state.selector->end_pass();
  state.passes_done += 1;
  return true;
}

void record_rays(RenderState& state, RayLog* log) {
  state.ray_log = log;
  if (log) log->tiles.resize(static_cast<std::size_t>(render_tile_count(state)));
}

const Framebuffer& render_framebuffer(const RenderState& state) {
  return state.framebuffer;
}
const Framebuffer& render_preview(const RenderState& state) {
  return state.preview;
}
const RenderSettings& render_settings(const RenderState& state) {
  return state.settings;
}
int render_passes_done(const RenderState& state) {
  return state.passes_done;
}
double render_seconds(const RenderState& state) {
  return state.seconds;
}
const lev::LightSelector& render_selector(const RenderState& state) {
  return *state.selector;
}
const RtFallbackProbe* render_rt_fallback(const RenderState& state) {
  return state.rt_fallback ? &*state.rt_fallback : nullptr;
}
int render_tile_count(const RenderState& state) {
  return state.tiles_x * state.tiles_y;
}
TileStatus render_tile_status(const RenderState& state, int tile) {
  return state.tiles[tile].load(std::memory_order_acquire);
}
void render_tile_rect(const RenderState& state, int tile, int& x0, int& y0, int& x1, int& y1) {
  const int ts = state.settings.tile_size;
  x0 = (tile % state.tiles_x) * ts;
  y0 = (tile / state.tiles_x) * ts;
  x1 = std::min(x0 + ts, state.settings.width);
  y1 = std::min(y0 + ts, state.settings.height);
}

}  // namespace renderer
