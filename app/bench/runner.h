// The machinery every experiment of `levrt bench` shares: the suite's sizes, one scene loaded at
// a time, measurements cached by what they measured (an rt reference or a lev run serves several
// experiments), medians of repeated runs, and progress on stderr with an estimate of the time
// left. The suite runs twice: a planning pass walks every experiment, rendering only a probe of
// each configuration (one pixel in 64) to predict its time, then the real pass renders, so the
// estimate covers the whole suite from the first line.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "app/scene_loading.h"
#include "lev/methods.h"
#include "renderer/framebuffer.h"
#include "renderer/render.h"

namespace app::bench {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct SuiteConfig {
  bool quick = false;
  int width = renderer::kDefaultImageWidth;
  int height = renderer::kDefaultImageHeight;
  int runs = 3;  // every timing is the median of at least this many runs
  // Timings quicker than this get extra runs (up to max_runs) for a steadier median.
  double extra_runs_seconds = 2.0;
  int max_runs = 9;
  std::vector<std::string> scenes{"building", "maze", "hall"};
  std::uint64_t min_lights = 40;     // the thesis starts at 45 (maze) and 64 lights
  std::uint64_t max_lights = 16384;  // speed, fraction, error: the thesis' range
  std::uint64_t max_scaling_lights = 1u << 20;
  std::uint64_t max_memory_lights = 1u << 20;
  // rt and ast above this many lights render one pixel of every subsample_stride^2 block and are
  // scaled to the whole frame; so does any render whose full frame would take longer than
  // max_full_frame_seconds (BenchRun::stride_for).
  std::uint64_t subsample_above = 4096;
  int subsample_stride = 4;
  double max_full_frame_seconds = 40.0;
  double tolerance = lev::kDefaultTolerance;                 // thesis Test 1.1
  std::vector<double> scaling_tolerances{0.001, 0.01, 0.1};  // Tables 4, 5
  std::vector<double> fraction_tolerances{0.0,   0.0001, 0.002, 0.004,
                                          0.006, 0.008,  0.01};            // Tables 6-9
  std::vector<double> error_tolerances{0.002, 0.004, 0.006, 0.008, 0.01};  // Tables 10, 11
  // trade: per scene, the level nearest this many lights (the hall, where every light reaches
  // everything, at fewer: its rt and ast frames take minutes at 1,024).
  std::map<std::string, std::uint64_t> trade_lights{
      {"building", 1024}, {"maze", 765}, {"hall", 256}};
  std::uint64_t trade_default_lights = 1024;
  // Each method's trade sweep is its row's bench_tolerances (lev::method_table); a quick run
  // takes the first, middle and last of them.
  // control: the (scene, light count) renders where every method's error is set against its
  // certified bound: where lev's per-light tolerance holds, and the hall, where it does not.
  std::vector<std::pair<std::string, std::uint64_t>> control_renders{
      {"building", 4096}, {"maze", 3069}, {"hall", 4096}, {"hall", 16384}};
  std::uint64_t scaling_base_lights = 1024;  // the scaling target compares with this count
  // converge: the renders where the methods' passes are followed to this many, their
  // errors taken after 1, 2, 3, 4, 6, 8, ... passes (snapshot_pass_counts); the equal-time
  // comparison at these shares of rt's time, and the error a method must reach (avg and max) to
  // count as converged.
  std::vector<std::pair<std::string, std::uint64_t>> converge_renders{
      {"building", 4096}, {"maze", 3069}, {"hall", 4096}, {"hall", 16384}};
  // The methods followed, with their tolerances: the deterministic ones a user would otherwise
  // pick (lev, lev_est) and the sampling ones, lev_mc also at 0.1, where fewer lights get exact
  // rays and more are drawn (the better choice on the hall at equal time). A name this build's
  // method table lacks is skipped; ast and lev_bounded are left out, as one pass of theirs costs
  // about as much as rt's.
  std::vector<std::pair<std::string, double>> converge_methods{
      {"lev", 0.01}, {"lev_est", 0.01}, {"lev_mc", 0.01}, {"lev_mc", 0.1}, {"light_tree", 0.01}};
  // targets: the (scene, light count) renders where each error target's fastest
  // method and setting is found: the thesis scenes and the classes of many dim lights, the lamp
  // street twice (instanced and bare, whose lev times the section compares).
  std::vector<std::pair<std::string, std::uint64_t>> target_renders{
      {"building", 16384}, {"maze", 12285},    {"hall", 4096},    {"hall", 16384},
      {"stage", 4608},     {"carpark", 16384}, {"street", 16384}, {"street_bare", 16384}};
  double target_max_pct = 2.0;      // first target: max pixel error below this
  double target_avg_pct = 0.5;      // second target: average below this ...
  double target_avg_max_pct = 5.0;  // ... and max below this
  // Rounds of the search between grid settings (target_refinement.h); each halves the gap in
  // log scale that it searches (a half decade: 0.01 .. 0.003 -> 0.0055 -> 0.0041 or 0.0074).
  int target_search_rounds = 2;
  int converge_passes = 256;
  std::vector<double> converge_budgets_of_rt{0.01, 0.1};
  double converge_target_avg_pct = 1.0;
  double converge_target_max_pct = 10.0;
};

SuiteConfig thesis_suite(bool quick);

// Every scene model the suite's experiments render, in the order they first appear.
std::vector<std::string> suite_scene_names(const SuiteConfig& config);
// Keeps only the renders of the named scene models in every experiment (`levrt bench --scenes`).
void restrict_to_scenes(SuiteConfig& config, const std::vector<std::string>& names);

struct MeasureRequest {
  std::string scene;
  int level = 0;
  lev::Method method = lev::Method::lev;
  double tolerance = lev::kDefaultTolerance;
  int stride = 1;  // RenderSettings::pixel_stride
  int runs = 1;    // 1 for counts and images (deterministic); config.runs for timings, which take
                   // more runs (up to 9) when they are quick
  // Also compute the certified error bound (RenderSettings::compute_error_bound); it costs time,
  // so a render with it is a measurement of its own.
  bool error_bound = false;
  // Lets a deterministic method shade with rt's loop where the probe says so
  // (lev::MethodChoice::rt_fallback): what a user gets. Off, the method's own selection, which
  // the thesis' experiments measure.
  bool rt_fallback = false;
  // A later round of a comparison (the targets experiment's search between settings): rt is
  // measured again, in turns with that round's renders, so it is a measurement of its own.
  int round = 0;
};

struct Measurement {
  MeasureRequest request;  // runs = how many were made
  std::uint64_t lights = 0;
  bool planned_only = false;  // the planning pass: no figures
  double seconds = kNaN;      // median wall time of the whole render: set-up and passes
  std::vector<double> run_seconds;
  // Median CPU time of the process (every thread, user and system, as /bin/time sums it, which
  // is how the thesis timed) over each whole render: what the comparisons use, because the
  // machine's other load moves it far less than the wall time.
  double cpu_seconds = kNaN;
  std::vector<double> run_cpu_seconds;
  // The share of those spent making the render state (selector, extent volumes, the rt
  // fallback's probe): the same whatever the pixels rendered, so a subsampled render scales only
  // the rest to the frame.
  double setup_seconds = kNaN;
  double setup_cpu_seconds = kNaN;
  std::vector<double> run_setup_seconds;
  std::vector<double> run_setup_cpu_seconds;
  std::uint64_t pixels = 0;  // pixels rendered
  std::uint64_t full_pixels = 0;
  renderer::FramebufferTotals totals;
  bool rt_fallback_used = false;  // the render shaded with rt's loop (request.rt_fallback)
  std::size_t hierarchy_bytes = 0;
  std::vector<std::uint8_t> rgb;  // the rendered pixels, 8-bit RGB, for pixel errors
  // With request.error_bound: each rendered pixel's certified bound (percent of 765), in rgb's
  // order.
  std::vector<double> error_bound_pct;

  // The median times with their passes scaled to every pixel of the frame, the set-up once
  // (the identity without a subsample).
  double full_frame_seconds() const;
  double full_frame_cpu_seconds() const;
  double lights_tested_avg() const;
  double nodes_visited_avg() const;
  double shadow_rays_avg() const;
};

// A progressive render followed pass by pass (BenchRun::measure_progress): what it looked like
// and what it had cost after some of its passes.
struct PassSnapshot {
  int passes = 0;
  double seconds = kNaN;            // wall time of the passes so far
  double cpu_seconds = kNaN;        // CPU time of the process over the passes so far
  double std_error_avg_pct = kNaN;  // the framebuffer's own noise estimate (renderer/pixel_noise)
  std::vector<std::uint8_t> rgb;    // the rendered pixels, 8-bit RGB
};

struct ProgressMeasurement {
  MeasureRequest request;  // runs is 1: the passes themselves are the repetition
  std::uint64_t lights = 0;
  bool planned_only = false;
  std::uint64_t pixels = 0;  // pixels rendered per pass
  std::uint64_t full_pixels = 0;
  std::vector<PassSnapshot> snapshots;  // in the order of the pass counts asked for
  // Making the render state, before the first pass (Measurement's set-up): counted once.
  double setup_seconds = kNaN;
  double setup_cpu_seconds = kNaN;

  // The set-up and a snapshot's passes, scaled to every pixel of the frame.
  double full_frame_seconds(const PassSnapshot& snapshot) const;
  double full_frame_cpu_seconds(const PassSnapshot& snapshot) const;
};

struct PixelErrors {
  double average_pct = kNaN;
  double max_pct = kNaN;
};
// Thesis 5.4.2.4 against the reference on the same pixels; NaN when they do not match.
PixelErrors pixel_errors(const std::vector<std::uint8_t>& image,
                         const std::vector<std::uint8_t>& reference);
PixelErrors pixel_errors(const Measurement& image, const Measurement& reference);

// The share of the pixels (percent) whose error against the reference is within the image's
// certified bound (renderer::within_error_bound); NaN when the pixels or bounds do not match.
double bound_holds_pct(const Measurement& image, const Measurement& reference);

// The middle value (the upper one of an even count); NaN for none.
double median(std::vector<double> values);

// "about 12 s", "about 25 min".
std::string duration_text(double seconds);

// "all" or "1/16" for a stride.
std::string pixels_text(int stride);

class BenchRun {
 public:
  BenchRun(SuiteConfig config, int threads);

  const SuiteConfig& config() const { return config_; }
  int threads() const { return threads_; }
  bool planning() const { return planning_; }
  // Ends the planning pass: from now on measurements render.
  void start_running();
  void begin_experiment(const std::string& name);
  // The files the suite will write (names in the output folder), noted while planning, so that
  // one the output folder cannot take is refused before any render.
  void plan_output(const std::string& file) { planned_outputs_.push_back(file); }
  const std::vector<std::string>& planned_outputs() const { return planned_outputs_; }
  // The renders and jobs the planning pass counted for an experiment (0: it renders nothing).
  int planned_jobs(const std::string& experiment) const {
    const auto found = jobs_planned_.find(experiment);
    return found == jobs_planned_.end() ? 0 : found->second;
  }

  // The suite's scenes present in this build (the table may not have them all yet).
  std::vector<std::string> available_scenes() const;
  std::vector<std::string> missing_scenes() const;
  // Levels of `scene` whose light count lies in [lo, hi].
  std::vector<int> levels(const std::string& scene, std::uint64_t lo, std::uint64_t hi) const;
  std::uint64_t light_count(const std::string& scene, int level) const;
  // The pixel stride a measurement uses: methods that look at every light (rt, ast) subsample
  // above config.subsample_above lights (thesis sizes), and any method whose full frame would take
  // more than config.max_full_frame_seconds (the maze and the hall, where rays are dearer or most
  // lights reach every point; lev at tolerance 0). The probe render tells.
  int stride_for(const std::string& scene, int level, lev::Method method, double tolerance);
  // lev's lights tested per shading point, from the probe.
  double lev_tests_per_point(const std::string& scene, int level, double tolerance);

  // Renders (or, while planning, only counts) the request; cached by what it measured, so asking
  // again with no more runs than before returns the earlier measurement.
  const Measurement& measure(const MeasureRequest& request);
  // Several requests, their runs interleaved (run k of each before run k+1 of any), so that the
  // ratios between them see the same machine load.
  std::vector<const Measurement*> measure_together(const std::vector<MeasureRequest>& requests);
  // Renders each request (runs ignored) pass after pass up to the last of pass_counts (ascending),
  // every pass at the pixel centres (RenderSettings::jitter_pixels off, so a sampling method's
  // passes converge to the one-pass reference), pass k of every request before pass k + 1 of
  // any, and keeps a snapshot after each count in pass_counts. A method that does not sample
  // repeats its image every pass, so it stops at the first snapshot whose full-frame CPU time
  // (ProgressMeasurement::full_frame_cpu_seconds) exceeds
  // deterministic_cpu_seconds (NaN: never): more passes would only add time. Not cached. While
  // planning it only counts (snapshots empty, planned_only).
  std::vector<ProgressMeasurement> measure_progress(const std::vector<MeasureRequest>& requests,
                                                    const std::vector<int>& pass_counts,
                                                    double deterministic_cpu_seconds = kNaN);

  // The loaded scene (built on first use; the levels of one scene model are kept together).
  LoadedScene& scene(const std::string& name, int level);

  // A job that is not a render: while planning only its predicted seconds count; otherwise it
  // runs and reports progress. Returns whether it ran.
  bool run_job(const std::string& what, double predicted_seconds,
               const std::function<void()>& body);

  // What a measurement will take, all its runs, from its probe.
  double predicted_seconds(const MeasureRequest& request);

 private:
  // The scene, level, method choice (lev::used_settings: what its method reads), stride, error
  // bound and round: what a measurement measured.
  using Key = std::tuple<std::string, int, lev::Method, double, double, int, bool, int, bool, int>;
  static constexpr int kProbeStride = 8;
  static bool is_probe(const MeasureRequest& r) { return r.stride == kProbeStride && r.runs == 1; }
  Key key_of(const MeasureRequest& request) const;
  renderer::RenderSettings render_settings_for(const MeasureRequest& request) const;
  // A render of one pixel in every kProbeStride^2, made once (also while planning): what the
  // plan, the subsample policy and lev_tests_per_point go by.
  const Measurement& probe(const std::string& scene, int level, lev::Method method,
                           double tolerance);
  // Renders what is not cached yet (in turns), whatever the pass.
  std::vector<const Measurement*> render(const std::vector<MeasureRequest>& requests);
  void report(const std::string& what, double predicted_seconds);

  SuiteConfig config_;
  int threads_;
  bool planning_ = true;
  std::map<Key, Measurement> cache_;
  std::map<Key, int> planned_runs_;
  // What the planning pass hands back for every request: no figures (planned_only), only the
  // request and its light count, which experiments need to lay out their tables.
  Measurement planned_measurement_;
  std::map<int, std::unique_ptr<LoadedScene>> loaded_;  // by level, all of loaded_name_
  std::string loaded_name_;
  std::string experiment_;
  std::map<std::string, int> jobs_planned_, jobs_done_;
  double seconds_planned_ = 0.0, seconds_done_ = 0.0;
  int probes_ = 0;
  std::vector<std::string> planned_outputs_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace app::bench
