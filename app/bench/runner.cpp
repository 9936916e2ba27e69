#include "app/bench/runner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "app/bench/table.h"
#include "app/interrupt.h"
#include "lev/light_hierarchy.h"
#include "renderer/error_bound.h"
#include "renderer/pixel_error.h"
#include "renderer/pixel_noise.h"
#include "renderer/process_cpu_time.h"
#include "renderer/render_service.h"
#include "scenes/scene_models.h"

namespace app::bench {

SuiteConfig thesis_suite(bool quick) {
  SuiteConfig c;
  if (!quick) return c;
  // The same experiments at sizes that finish in seconds; the figures mean little, the files
  // and their columns are what CI checks.
  c.quick = true;
  c.width = 48;
  c.height = 36;
  c.extra_runs_seconds = 0.0;
  c.max_lights = 256;
  c.max_scaling_lights = 256;
  c.max_memory_lights = 4096;
  c.subsample_above = 64;  // so that the subsampled path runs too
  c.subsample_stride = 2;
  c.max_full_frame_seconds = 0.5;
  c.fraction_tolerances = {0.0, 0.002, 0.01};
  c.error_tolerances = {0.002, 0.01};
  c.trade_lights.clear();
  c.trade_default_lights = 64;
  c.scaling_base_lights = 64;
  c.control_renders = {{"building", 64}, {"maze", 45}, {"hall", 64}, {"hall", 256}};
  c.converge_renders = c.control_renders;
  c.converge_passes = 8;
  c.target_renders = {{"building", 64}, {"hall", 64},   {"stage", 72},
                      {"carpark", 64},  {"street", 64}, {"street_bare", 64}};
  return c;
}

namespace {

// A render's time with its passes scaled from `pixels` to `full_pixels` and its set-up, which
// does not depend on the pixels, counted once.
double scaled_to_frame(double total, double setup, std::uint64_t pixels,
                       std::uint64_t full_pixels) {
  if (pixels == 0) return kNaN;
  const double passes = std::max(total - setup, 0.0);
  return setup + passes * static_cast<double>(full_pixels) / static_cast<double>(pixels);
}

// The (scene, light count) lists of a suite, each experiment's (Config: SuiteConfig or const).
template <typename Config>
auto scene_render_lists(Config& c) {
  return std::array{&c.control_renders, &c.converge_renders, &c.target_renders};
}

bool named(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

std::vector<std::string> suite_scene_names(const SuiteConfig& config) {
  std::vector<std::string> names;
  const auto add = [&](const std::string& name) {
    if (!named(names, name)) names.push_back(name);
  };
  for (const std::string& name : config.scenes) add(name);
  for (const auto* list : scene_render_lists(config)) {
    for (const auto& render : *list) add(render.first);
  }
  return names;
}

void restrict_to_scenes(SuiteConfig& config, const std::vector<std::string>& names) {
  const auto unnamed = [&](const std::string& name) { return !named(names, name); };
  config.scenes.erase(std::remove_if(config.scenes.begin(), config.scenes.end(), unnamed),
                      config.scenes.end());
  for (auto* list : scene_render_lists(config)) {
    list->erase(std::remove_if(list->begin(), list->end(),
                               [&](const auto& render) { return unnamed(render.first); }),
                list->end());
  }
}

double Measurement::full_frame_seconds() const {
  return scaled_to_frame(seconds, setup_seconds, pixels, full_pixels);
}

double Measurement::full_frame_cpu_seconds() const {
  return scaled_to_frame(cpu_seconds, setup_cpu_seconds, pixels, full_pixels);
}

double Measurement::lights_tested_avg() const {
  return totals.shading_points ? static_cast<double>(totals.lights_tested) / totals.shading_points
                               : kNaN;
}

double Measurement::nodes_visited_avg() const {
  return totals.shading_points ? static_cast<double>(totals.nodes_visited) / totals.shading_points
                               : kNaN;
}

double Measurement::shadow_rays_avg() const {
  return totals.shading_points ? static_cast<double>(totals.shadow_rays) / totals.shading_points
                               : kNaN;
}

double ProgressMeasurement::full_frame_seconds(const PassSnapshot& snapshot) const {
  return scaled_to_frame(setup_seconds + snapshot.seconds, setup_seconds, pixels, full_pixels);
}

double ProgressMeasurement::full_frame_cpu_seconds(const PassSnapshot& snapshot) const {
  return scaled_to_frame(setup_cpu_seconds + snapshot.cpu_seconds, setup_cpu_seconds, pixels,
                         full_pixels);
}

PixelErrors pixel_errors(const std::vector<std::uint8_t>& image,
                         const std::vector<std::uint8_t>& reference) {
  PixelErrors e;
  if (image.empty() || image.size() != reference.size()) return e;
  const renderer::PixelErrorStats s =
      renderer::summarize_pixel_error(renderer::pixel_error_pct(image, reference));
  e.average_pct = s.average_pct;
  e.max_pct = s.max_pct;
  return e;
}

PixelErrors pixel_errors(const Measurement& image, const Measurement& reference) {
  return pixel_errors(image.rgb, reference.rgb);
}

double bound_holds_pct(const Measurement& image, const Measurement& reference) {
  if (image.rgb.empty() || image.rgb.size() != reference.rgb.size() ||
      image.error_bound_pct.size() * 3 != image.rgb.size())
    return kNaN;
  const std::vector<double> error = renderer::pixel_error_pct(image.rgb, reference.rgb);
  std::size_t held = 0;
  for (std::size_t i = 0; i < error.size(); ++i)
    held += renderer::within_error_bound(error[i], image.error_bound_pct[i]) ? 1 : 0;
  return 100.0 * static_cast<double>(held) / static_cast<double>(error.size());
}

double median(std::vector<double> values) {
  if (values.empty()) return kNaN;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::string duration_text(double seconds) {
  if (seconds >= 90.0) return "about " + std::to_string(std::lround(seconds / 60.0)) + " min";
  return "about " + std::to_string(std::lround(seconds)) + " s";
}

std::string pixels_text(int stride) {
  return stride <= 1 ? "all" : "1/" + std::to_string(stride * stride);
}

BenchRun::BenchRun(SuiteConfig config, int threads)
    : config_(std::move(config)), threads_(threads) {
  planned_measurement_.planned_only = true;
}

void BenchRun::start_running() {
  planning_ = false;
  started_ = std::chrono::steady_clock::now();
  int jobs = 0;
  for (const auto& [name, count] : jobs_planned_) jobs += count;
  std::fprintf(stderr,
               "levrt bench: planned %d renders and jobs, %s at this machine's present pace\n",
               jobs, duration_text(seconds_planned_).c_str());
}

void BenchRun::begin_experiment(const std::string& name) {
  experiment_ = name;
}

std::vector<std::string> BenchRun::available_scenes() const {
  std::vector<std::string> names;
  for (const std::string& s : config_.scenes) {
    if (scenes::find_scene_model(s)) names.push_back(s);
  }
  return names;
}

std::vector<std::string> BenchRun::missing_scenes() const {
  std::vector<std::string> names;
  for (const std::string& s : config_.scenes) {
    if (!scenes::find_scene_model(s)) names.push_back(s);
  }
  return names;
}

std::vector<int> BenchRun::levels(const std::string& scene, std::uint64_t lo,
                                  std::uint64_t hi) const {
  std::vector<int> out;
  const scenes::SceneModel* model = scenes::find_scene_model(scene);
  if (!model) return out;
  for (int level = model->min_level; level <= model->max_level; ++level) {
    const std::uint64_t n = model->light_count(level);
    if (n >= lo && n <= hi) out.push_back(level);
  }
  return out;
}

std::uint64_t BenchRun::light_count(const std::string& scene, int level) const {
  const scenes::SceneModel* model = scenes::find_scene_model(scene);
  return model ? model->light_count(level) : 0;
}

int BenchRun::stride_for(const std::string& scene, int level, lev::Method method,
                         double tolerance) {
  if (lev::method_info(method).scans_every_light &&
      light_count(scene, level) > config_.subsample_above)
    return config_.subsample_stride;
  return probe(scene, level, method, tolerance).full_frame_seconds() >
                 config_.max_full_frame_seconds
             ? config_.subsample_stride
             : 1;
}

double BenchRun::lev_tests_per_point(const std::string& scene, int level, double tolerance) {
  return probe(scene, level, lev::Method::lev, tolerance).lights_tested_avg();
}

const Measurement& BenchRun::probe(const std::string& scene, int level, lev::Method method,
                                   double tolerance) {
  const MeasureRequest request{scene, level, method, tolerance, kProbeStride, 1};
  const auto found = cache_.find(key_of(request));
  if (found != cache_.end()) return found->second;
  const Measurement& m = *render(std::vector<MeasureRequest>{request}).front();
  if (planning_ && ++probes_ % 25 == 0) {
    std::fprintf(stderr,
                 "levrt bench: planning: %d probe renders so far (1/%d of the pixels each)\n",
                 probes_, kProbeStride * kProbeStride);
  }
  return m;
}

double BenchRun::predicted_seconds(const MeasureRequest& r) {
  if (is_probe(r)) return 0.0;  // made while planning
  const double per_run = probe(r.scene, r.level, r.method, r.tolerance).full_frame_seconds() /
                         static_cast<double>(r.stride * r.stride);
  double runs = r.runs;
  if (r.runs > 1 && per_run > 0.0) {
    runs = std::max(
        runs, std::min<double>(config_.max_runs, std::ceil(config_.extra_runs_seconds / per_run)));
  }
  return per_run * runs;
}

namespace {

// The request's method choice: the sweep's value goes to the setting the method is swept over
// (lev/methods.h).
lev::MethodChoice method_choice(const MeasureRequest& r) {
  lev::MethodChoice choice;
  choice.method = r.method;
  if (lev::swept_setting(lev::method_info(r.method)) == &lev::MethodParams::relative_error) {
    choice.relative_error = r.tolerance;
  } else {
    choice.tolerance = r.tolerance;
  }
  choice.rt_fallback = r.rt_fallback;
  return choice;
}

}  // namespace

BenchRun::Key BenchRun::key_of(const MeasureRequest& r) const {
  // A method that ignores the sweep's value (rt) is measured once for every value: the method
  // choice compares only what its method reads.
  const lev::MethodChoice used = lev::used_settings(method_choice(r));
  return {r.scene,
          r.level,
          used.method,
          used.tolerance,
          used.relative_error,
          used.lights_per_point,
          used.rt_fallback,
          r.stride,
          r.error_bound,
          r.round};
}

renderer::RenderSettings BenchRun::render_settings_for(const MeasureRequest& r) const {
  Settings s;
  s.scene.name = r.scene;
  s.scene.level = r.level;
  s.method = method_choice(r);
  s.image.width = config_.width;
  s.image.height = config_.height;
  s.image.threads = threads_;
  s.image.subsample = r.stride;
  renderer::RenderSettings rs = render_settings_from(s);
  rs.compute_error_bound = r.error_bound;
  return rs;
}

LoadedScene& BenchRun::scene(const std::string& name, int level) {
  // The levels of one scene model stay loaded together (measurements across levels are run in
  // turns); moving to another model frees them first.
  if (loaded_name_ != name) {
    loaded_.clear();
    loaded_name_ = name;
  }
  std::unique_ptr<LoadedScene>& slot = loaded_[level];
  if (!slot) {
    scenes::SceneChoice choice;
    choice.name = name;
    choice.level = level;
    slot = load_scene(choice);
  }
  return *slot;
}

const Measurement& BenchRun::measure(const MeasureRequest& request) {
  return *measure_together({request}).front();
}

std::vector<const Measurement*> BenchRun::measure_together(
    const std::vector<MeasureRequest>& requests) {
  if (!planning_) return render(requests);
  for (const MeasureRequest& r : requests) {
    int& planned = planned_runs_[key_of(r)];
    if (planned >= r.runs) continue;
    planned = r.runs;
    seconds_planned_ += predicted_seconds(r);
    jobs_planned_[experiment_] += 1;
  }
  std::vector<const Measurement*> out(requests.size(), &planned_measurement_);
  if (!requests.empty()) {
    planned_measurement_.request = requests.back();
    planned_measurement_.lights = light_count(requests.back().scene, requests.back().level);
  }
  return out;
}

std::vector<const Measurement*> BenchRun::render(const std::vector<MeasureRequest>& requests) {
  std::vector<const Measurement*> out(requests.size(), nullptr);
  // What is not cached yet, with its settings.
  struct Pending {
    std::size_t index;
    renderer::RenderSettings render_settings;
    Measurement m;
    renderer::RenderResult last;
    double spent = 0.0;
  };
  std::vector<Pending> pending;
  for (std::size_t i = 0; i < requests.size(); ++i) {
    const MeasureRequest& r = requests[i];
    const auto found = cache_.find(key_of(r));
    if (found != cache_.end() && found->second.request.runs >= r.runs) {
      out[i] = &found->second;
      continue;
    }
    // A render the planning pass could not foresee (the targets' search between settings, which
    // depends on the errors found): the plan grows by it, so the progress line stays true.
    if (!planning_ && !is_probe(r) && planned_runs_.count(key_of(r)) == 0) {
      planned_runs_[key_of(r)] = r.runs;
      seconds_planned_ += predicted_seconds(r);
      jobs_planned_[experiment_] += 1;
    }
    Pending p{};
    p.index = i;
    p.render_settings = render_settings_for(r);
    p.m.request = r;
    pending.push_back(std::move(p));
  }
  // Round-robin: run k of every request before run k+1 of any, so a change in the machine's load
  // (it is shared) falls on all the methods of a comparison alike. Quick renders get extra runs
  // for a steadier median.
  for (int round = 0;; ++round) {
    bool any = false;
    for (Pending& p : pending) {
      const bool base = round < p.m.request.runs;
      const bool extra =
          p.m.request.runs > 1 && round < config_.max_runs && p.spent < config_.extra_runs_seconds;
      if (!base && !extra) continue;
      const MeasureRequest& r = p.m.request;
      LoadedScene& loaded = scene(r.scene, r.level);
      const double cpu_start = renderer::process_cpu_seconds();
      InterruptScope::throw_if_interrupted();  // the scene may have just been built
      if (!renderer::render_passes(loaded.scene, *loaded.rays, p.render_settings, 1, p.last,
                                   &InterruptScope::flag())) {
        throw Interrupted();
      }
      p.m.run_cpu_seconds.push_back(renderer::process_cpu_seconds() - cpu_start);
      p.m.run_seconds.push_back(p.last.setup_seconds + p.last.render_seconds);
      p.m.run_setup_seconds.push_back(p.last.setup_seconds);
      p.m.run_setup_cpu_seconds.push_back(p.last.setup_cpu_seconds);
      p.spent += p.last.setup_seconds + p.last.render_seconds;
      any = true;
    }
    if (!any) break;
  }

  for (Pending& p : pending) {
    Measurement& m = p.m;
    const MeasureRequest& r = m.request;
    LoadedScene& loaded = scene(r.scene, r.level);
    m.lights = loaded.scene.lights.light_count;
    m.seconds = median(m.run_seconds);
    m.cpu_seconds = median(m.run_cpu_seconds);
    m.setup_seconds = median(m.run_setup_seconds);
    m.setup_cpu_seconds = median(m.run_setup_cpu_seconds);
    m.full_pixels =
        static_cast<std::uint64_t>(config_.width) * static_cast<std::uint64_t>(config_.height);
    m.totals = p.last.totals;
    m.rt_fallback_used = p.last.rt_fallback && p.last.rt_fallback->use_rt;
    m.pixels = m.totals.samples;
    m.hierarchy_bytes = lev::hierarchy_bytes(loaded.scene.lights);
    m.rgb = std::move(p.last.rendered_rgb);
    if (r.error_bound) m.error_bound_pct = renderer::rendered_error_bound_pct(p.last.framebuffer);
    const int runs = static_cast<int>(m.run_seconds.size());
    Measurement& stored = cache_[key_of(r)] = std::move(m);
    out[p.index] = &stored;
    const MeasureRequest& done = stored.request;  // r was moved with m

    char what[256];
    std::snprintf(what, sizeof what, "%s %s lights, %s, tol %g, %s px: %.3f s%s",
                  done.scene.c_str(), format_count(stored.lights).c_str(),
                  lev::method_info(done.method).name, done.tolerance,
                  pixels_text(done.stride).c_str(), stored.seconds,
                  runs > 1 ? (" (median of " + std::to_string(runs) + ")").c_str() : "");
    // A probe is no job of the plan: the search between settings (experiment_targets.cpp) makes
    // new ones while running, which the progress line would count as renders.
    if (!planning_ && !is_probe(done)) report(what, predicted_seconds(done));
  }
  return out;
}

std::vector<ProgressMeasurement> BenchRun::measure_progress(
    const std::vector<MeasureRequest>& requests, const std::vector<int>& pass_counts,
    double deterministic_cpu_seconds) {
  std::vector<ProgressMeasurement> out(requests.size());
  const int last = pass_counts.empty() ? 0 : pass_counts.back();
  for (std::size_t i = 0; i < requests.size(); ++i) {
    out[i].request = requests[i];
    out[i].request.runs = 1;
    out[i].lights = light_count(requests[i].scene, requests[i].level);
    out[i].planned_only = planning_;
  }
  if (planning_) {
    for (const ProgressMeasurement& m : out) {
      seconds_planned_ += predicted_seconds(m.request) * last;
      jobs_planned_[experiment_] += 1;
    }
    return out;
  }
  // The jobs of one scene live together (BenchRun::scene keeps one model's levels loaded).
  std::vector<std::unique_ptr<renderer::RenderJob>> jobs;
  for (ProgressMeasurement& m : out) {
    renderer::RenderSettings rs = render_settings_for(m.request);
    rs.jitter_pixels = false;
    LoadedScene& loaded = scene(m.request.scene, m.request.level);
    InterruptScope::throw_if_interrupted();  // the scene may have just been built
    jobs.push_back(std::make_unique<renderer::RenderJob>(loaded.scene, *loaded.rays, rs));
    m.setup_seconds = jobs.back()->setup_seconds();
    m.setup_cpu_seconds = jobs.back()->setup_cpu_seconds();
    m.full_pixels =
        static_cast<std::uint64_t>(config_.width) * static_cast<std::uint64_t>(config_.height);
  }
  std::vector<double> cpu_spent(out.size(), 0.0);
  std::vector<bool> stopped(out.size(), false);
  std::size_t next_count = 0;
  for (int pass = 1; pass <= last; ++pass) {
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      if (stopped[i]) continue;
      const double cpu_start = renderer::process_cpu_seconds();
      if (!jobs[i]->pass(&InterruptScope::flag())) throw Interrupted();
      cpu_spent[i] += renderer::process_cpu_seconds() - cpu_start;
    }
    if (next_count >= pass_counts.size() || pass != pass_counts[next_count]) continue;
    ++next_count;
    for (std::size_t i = 0; i < jobs.size(); ++i) {
      if (stopped[i]) continue;
      renderer::RenderResult result = jobs[i]->result();
      PassSnapshot snapshot;
      snapshot.passes = pass;
      snapshot.seconds = result.render_seconds;
      snapshot.cpu_seconds = cpu_spent[i];
      snapshot.std_error_avg_pct = renderer::std_error_avg_pct(result.framebuffer);
      snapshot.rgb = std::move(result.rendered_rgb);
      out[i].pixels = result.rendered_pixels;
      out[i].snapshots.push_back(std::move(snapshot));
      stopped[i] =
          !lev::method_info(out[i].request.method).stochastic &&
          out[i].full_frame_cpu_seconds(out[i].snapshots.back()) > deterministic_cpu_seconds;
    }
  }
  for (const ProgressMeasurement& m : out) {
    const MeasureRequest& r = m.request;
    char what[256];
    std::snprintf(what, sizeof what, "%s %s lights, %s, tol %g, %s px, %d passes: %.3f s",
                  r.scene.c_str(), format_count(m.lights).c_str(), lev::method_info(r.method).name,
                  r.tolerance, pixels_text(r.stride).c_str(),
                  m.snapshots.empty() ? 0 : m.snapshots.back().passes,
                  m.snapshots.empty() ? kNaN : m.snapshots.back().seconds);
    report(what, predicted_seconds(r) * last);
  }
  return out;
}

bool BenchRun::run_job(const std::string& what, double predicted,
                       const std::function<void()>& body) {
  if (planning_) {
    seconds_planned_ += predicted;
    jobs_planned_[experiment_] += 1;
    return false;
  }
  body();
  report(what, predicted);
  return true;
}

void BenchRun::report(const std::string& what, double predicted) {
  seconds_done_ += predicted;
  const int done = ++jobs_done_[experiment_];
  const int planned = std::max(done, jobs_planned_[experiment_]);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const double fraction =
      seconds_planned_ > 0.0 ? std::min(1.0, seconds_done_ / seconds_planned_) : 1.0;
  std::string eta;
  if (fraction >= 1.0) {
    eta = "finishing";
  } else if (seconds_done_ > 0.0 && elapsed > 0.5) {
    // The predictions come from probes; scaling them by how the run is going so far follows
    // the machine's load.
    eta = duration_text(elapsed * (seconds_planned_ - seconds_done_) / seconds_done_) + " left";
  } else {
    eta = "estimating";
  }
  std::fprintf(stderr, "levrt bench: [%s %d/%d] %s | %d%% done, %s\n", experiment_.c_str(), done,
               planned, what.c_str(), static_cast<int>(100.0 * fraction), eta.c_str());
  std::fflush(stderr);
}

}  // namespace app::bench
