// converge: how each method's image approaches the exact one as passes accumulate, against the
// time they cost. Every pass samples the pixel centres, so a deterministic method
// (lev, lev_est) renders the same image each pass and keeps its bias, while a sampling method
// (lev_mc, light_tree) draws other lights each pass and its mean converges to rt's one-pass
// image, its error falling as 1/sqrt(passes) once the noise dominates.
#include "app/bench/experiment_support.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lev/methods.h"

namespace app::bench {

namespace {

// One method's progressive render on one scene, its snapshots' errors against rt.
struct Curve {
  const lev::MethodInfo* method = nullptr;
  const ProgressMeasurement* measured = nullptr;
  std::vector<PixelErrors> errors;  // per snapshot
  std::vector<double> cpu_seconds;  // per snapshot, full frame
};

// The last snapshot whose time fits the budget (-1 when even the first does not).
int last_within(const Curve& curve, double budget_seconds) {
  int found = -1;
  for (std::size_t i = 0; i < curve.cpu_seconds.size(); ++i)
    if (curve.cpu_seconds[i] <= budget_seconds) found = static_cast<int>(i);
  return found;
}

// The first snapshot whose errors meet both targets (-1 when none does).
int first_meeting(const Curve& curve, double avg_pct, double max_pct) {
  for (std::size_t i = 0; i < curve.errors.size(); ++i)
    if (curve.errors[i].average_pct < avg_pct && curve.errors[i].max_pct < max_pct)
      return static_cast<int>(i);
  return -1;
}

constexpr double kSlopeFloorPct = 0.01;

// The log-log slope of the average error from the snapshot at a sixteenth of the passes (or the
// first) to the last: -0.5 for an unbiased method whose noise dominates, 0 for a fixed bias.
double error_slope(const Curve& curve) {
  if (curve.errors.size() < 2) return kNaN;
  const auto& snapshots = curve.measured->snapshots;
  const int last_passes = snapshots.back().passes;
  std::size_t from = 0;
  for (std::size_t i = 0; i < snapshots.size(); ++i)
    if (snapshots[i].passes * 16 <= last_passes) from = i;
  const double a = curve.errors[from].average_pct, b = curve.errors.back().average_pct;
  // Below a hundredth of a percent the error is the 8-bit rounding of a few pixels, not a trend.
  if (!(a >= kSlopeFloorPct) || !(b > 0.0)) return kNaN;
  return std::log(b / a) /
         std::log(static_cast<double>(last_passes) / static_cast<double>(snapshots[from].passes));
}

}  // namespace

// Half-octave steps (1, 2, 3, 4, 6, 8, 12, ...) up to `last`: the error at a budget is read at
// the last snapshot within it, and whole octaves made it jump by up to sqrt(2) with the noise of
// a method's time (hall, light_tree at rt/10: 16 passes in one run, 32 in the next).
std::vector<int> snapshot_pass_counts(int last) {
  std::vector<int> counts;
  for (int octave = 1; octave <= last; octave *= 2) {
    counts.push_back(octave);
    if (octave >= 2 && octave + octave / 2 <= last) counts.push_back(octave + octave / 2);
  }
  return counts;
}

namespace {

std::string budget_name(double share) {
  return "rt/" + std::to_string(std::lround(1.0 / share));
}

// A method followed at a tolerance, as the plots' legends and the intro name it.
std::string curve_label(const lev::MethodInfo& info, double tolerance) {
  return info.uses_tolerance ? std::string(info.name) + " " + tolerance_text(tolerance)
                             : std::string(info.name);
}

// "lev 0.01, lev_mc 0.1 and light_tree": the methods this build follows, from the config.
std::string followed_methods_text(const SuiteConfig& c) {
  std::vector<std::string> labels;
  for (const auto& [name, tolerance] : c.converge_methods)
    if (const std::optional<lev::Method> m = lev::parse_method(name))
      labels.push_back(curve_label(lev::method_info(*m), tolerance));
  std::string text;
  for (std::size_t i = 0; i < labels.size(); ++i)
    text += (i == 0 ? "" : i + 1 == labels.size() ? " and " : ", ") + labels[i];
  return text;
}

std::string budget_csv(double share) {
  return "rt_over_" + std::to_string(std::lround(1.0 / share));
}

}  // namespace

Section run_converge(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  const std::vector<int> pass_counts = snapshot_pass_counts(c.converge_passes);
  const int last_passes = pass_counts.back();
  const std::string last_text = std::to_string(last_passes);

  // Every snapshot, in the CSV only (converge_passes.csv).
  Table passes;
  passes.columns = {{"scene", "scene"},
                    {"lights", "lights"},
                    {"method", "method"},
                    {"tolerance", "tolerance"},
                    {"passes", "passes"},
                    {"time_cpu_s", "time (CPU s)"},
                    {"time_wall_s", "time (s)"},
                    {"speedup_over_rt", "speedup over rt"},
                    {"pixel_error_avg_pct", "avg error (%)"},
                    {"pixel_error_max_pct", "max error (%)"},
                    {"std_error_avg_pct", "noise estimate (%)"},
                    {"pixels", "px"}};
  // The equal-time summary, one row per method and scene (converge.csv and results.md).
  Table summary;
  summary.columns = {{"scene", "scene"},
                     {"lights", "lights"},
                     {"method", "method"},
                     {"tolerance", "tolerance"},
                     {"pass_cpu_s", "one pass (CPU s)"}};
  for (double share : c.converge_budgets_of_rt) {
    const std::string csv = budget_csv(share), name = budget_name(share);
    summary.columns.push_back({"passes_in_" + csv, "passes in " + name});
    summary.columns.push_back({"pixel_error_avg_pct_at_" + csv, "avg error at " + name + " (%)"});
    summary.columns.push_back({"pixel_error_max_pct_at_" + csv, "max error at " + name + " (%)"});
  }
  summary.columns.push_back({"passes", "passes made"});
  summary.columns.push_back({"pixel_error_avg_pct_at_last", "avg error, last pass (%)"});
  summary.columns.push_back({"pixel_error_max_pct_at_last", "max error, last pass (%)"});
  summary.columns.push_back({"error_slope", "log-log slope"});
  const std::string target_text = "avg < " + format_fixed(c.converge_target_avg_pct, 0) +
                                  " %, max < " + format_fixed(c.converge_target_max_pct, 0) + " %";
  summary.columns.push_back({"target_passes", "passes to " + target_text});
  summary.columns.push_back({"target_speedup_over_rt", "its speedup over rt"});
  summary.columns.push_back({"pixels", "px"});

  std::vector<NamedChart> charts;
  // Headline figures.
  double worst_unbiased_pct = 0.0;
  bool unbiased_measured = false;
  double worst_ratio_lit = 0.0, worst_ratio_hall = 0.0;  // lev_mc / light_tree at rt/10
  bool ratio_lit_measured = false, ratio_hall_measured = false;
  double slowest_hall_target = kNaN;  // lev_mc's speedup over rt reaching the targets
  bool hall_target_measured = false, hall_target_all_met = true;
  const double ratio_budget = c.converge_budgets_of_rt.back();

  for (const auto& [scene, wanted_lights] : c.converge_renders) {
    const std::optional<ReferencedScene> where = referenced_scene(run, scene, wanted_lights);
    if (!where) continue;  // not in this build's scene table: the section says so
    const int level = where->level;
    const std::uint64_t lights = where->lights;
    // A subsample for every scene (rt's too): 256 passes of every method over the whole frame
    // would take an hour, and the errors of 1/16 of the pixels tell the same story.
    const int stride = c.subsample_stride;
    const lev::Method rt = lev::reference_method();
    const MeasureRequest rt_request{scene, level, rt, 0.0, stride, c.runs};
    std::vector<MeasureRequest> requests;
    for (const auto& [name, tolerance] : c.converge_methods) {
      if (const std::optional<lev::Method> m = lev::parse_method(name))
        requests.push_back({scene, level, *m, tolerance, stride, 1});
    }
    const Measurement& reference = run.measure(rt_request);
    // A deterministic method stops once its set-up and passes cost more than rt's frame.
    const std::vector<ProgressMeasurement> progress =
        run.measure_progress(requests, pass_counts, reference.full_frame_cpu_seconds());
    const double rt_seconds = reference.full_frame_cpu_seconds();

    std::vector<Curve> curves;
    for (const ProgressMeasurement& p : progress) {
      Curve curve;
      curve.method = &lev::method_info(p.request.method);
      curve.measured = &p;
      for (const PassSnapshot& s : p.snapshots) {
        curve.errors.push_back(pixel_errors(s.rgb, reference.rgb));
        curve.cpu_seconds.push_back(p.full_frame_cpu_seconds(s));
      }
      curves.push_back(std::move(curve));
    }

    Chart avg_chart, max_chart;
    avg_chart.title = scene + ", " + format_count(lights) + " lights: average error against time";
    max_chart.title = scene + ", " + format_count(lights) + " lights: maximum error against time";
    avg_chart.x_label = max_chart.x_label = "CPU seconds per frame, all passes so far";
    avg_chart.y_label = "avg pixel error vs rt (%, 0 at 1e-4)";
    max_chart.y_label = "max pixel error vs rt (%, 0 at 1e-4)";
    avg_chart.log_x = avg_chart.log_y = max_chart.log_x = max_chart.log_y = true;
    double lowest_avg = 100.0, highest_avg = kErrorFloorPct;
    double lowest_max = 100.0, highest_max = kErrorFloorPct;

    std::map<lev::Method, double> avg_at_ratio_budget;
    double best_mc_speedup = kNaN;  // lev_mc's, at its best tolerance, reaching the targets
    for (const Curve& curve : curves) {
      const ProgressMeasurement& p = *curve.measured;
      const lev::MethodInfo& info = *curve.method;
      const std::string tolerance = info.uses_tolerance ? tolerance_text(p.request.tolerance) : "-";
      const std::string label = curve_label(info, p.request.tolerance);
      Series avg_series{label, {}, {}}, max_series{label, {}, {}};
      for (std::size_t i = 0; i < p.snapshots.size(); ++i) {
        const PassSnapshot& s = p.snapshots[i];
        const PixelErrors& e = curve.errors[i];
        const double seconds = curve.cpu_seconds[i];
        passes.rows.push_back(
            {text_cell(scene), count_cell(lights), text_cell(info.name), text_cell(tolerance),
             count_cell(static_cast<std::uint64_t>(s.passes)), number_cell(seconds, 3),
             number_cell(p.full_frame_seconds(s), 3), ratio_cell(rt_seconds / seconds),
             number_cell(e.average_pct, 4), number_cell(e.max_pct, 3),
             number_cell(s.std_error_avg_pct, 4), text_cell(pixels_text(stride))});
        avg_series.x.push_back(seconds);
        max_series.x.push_back(seconds);
        avg_series.y.push_back(error_on_log_axis(e.average_pct));
        max_series.y.push_back(error_on_log_axis(e.max_pct));
        lowest_avg = std::min(lowest_avg, error_on_log_axis(e.average_pct));
        highest_avg = std::max(highest_avg, error_on_log_axis(e.average_pct));
        lowest_max = std::min(lowest_max, error_on_log_axis(e.max_pct));
        highest_max = std::max(highest_max, error_on_log_axis(e.max_pct));
      }
      avg_chart.series.push_back(avg_series);
      max_chart.series.push_back(max_series);

      std::vector<Cell> row{
          text_cell(scene), count_cell(lights), text_cell(info.name), text_cell(tolerance),
          number_cell(curve.cpu_seconds.empty() ? kNaN : curve.cpu_seconds[0], 3)};
      for (double share : c.converge_budgets_of_rt) {
        const int at = last_within(curve, share * rt_seconds);
        const PixelErrors e = at < 0 ? PixelErrors{} : curve.errors[static_cast<std::size_t>(at)];
        row.push_back(at < 0 ? text_cell("0")
                             : count_cell(static_cast<std::uint64_t>(
                                   p.snapshots[static_cast<std::size_t>(at)].passes)));
        row.push_back(number_cell(e.average_pct, 4));
        row.push_back(number_cell(e.max_pct, 3));
        // A method at several tolerances counts with its best: a user picks the tolerance.
        if (share == ratio_budget) {
          const auto [at_budget, first] = avg_at_ratio_budget.emplace(info.id, e.average_pct);
          if (!first && (std::isnan(at_budget->second) || e.average_pct < at_budget->second))
            at_budget->second = e.average_pct;
        }
      }
      const PixelErrors last = curve.errors.empty() ? PixelErrors{} : curve.errors.back();
      row.push_back(count_cell(
          p.snapshots.empty() ? 0u : static_cast<std::uint64_t>(p.snapshots.back().passes)));
      row.push_back(number_cell(last.average_pct, 4));
      row.push_back(number_cell(last.max_pct, 3));
      row.push_back(number_cell(error_slope(curve), 2));
      const int met = first_meeting(curve, c.converge_target_avg_pct, c.converge_target_max_pct);
      const double met_speedup =
          met < 0 ? kNaN : rt_seconds / curve.cpu_seconds[static_cast<std::size_t>(met)];
      row.push_back(met < 0 ? text_cell("-")
                            : count_cell(static_cast<std::uint64_t>(
                                  p.snapshots[static_cast<std::size_t>(met)].passes)));
      row.push_back(met < 0 ? text_cell("-") : ratio_cell(met_speedup));
      row.push_back(text_cell(pixels_text(stride)));
      summary.rows.push_back(std::move(row));

      if (p.planned_only) continue;
      if (info.stochastic) {
        unbiased_measured = true;
        worst_unbiased_pct =
            std::max(worst_unbiased_pct, std::isnan(last.average_pct) ? 100.0 : last.average_pct);
      }
      if (info.id == lev::Method::lev_mc && met >= 0)
        best_mc_speedup =
            std::isnan(best_mc_speedup) ? met_speedup : std::max(best_mc_speedup, met_speedup);
    }
    if (scene == "hall" && !reference.planned_only) {
      hall_target_measured = true;
      if (std::isnan(best_mc_speedup)) {
        hall_target_all_met = false;
      } else {
        slowest_hall_target = std::isnan(slowest_hall_target)
                                  ? best_mc_speedup
                                  : std::min(slowest_hall_target, best_mc_speedup);
      }
    }
    // lev_mc (at its better tolerance) against light_tree at the largest budget.
    const auto mc = avg_at_ratio_budget.find(lev::Method::lev_mc);
    const auto tree = avg_at_ratio_budget.find(lev::Method::light_tree);
    if (!reference.planned_only && mc != avg_at_ratio_budget.end() &&
        tree != avg_at_ratio_budget.end()) {
      // A method with no pass inside the budget has no error there: it loses.
      const double ratio = std::isnan(mc->second)     ? 1e9
                           : std::isnan(tree->second) ? 0.0
                           : tree->second > 0.0       ? mc->second / tree->second
                                                      : (mc->second > 0.0 ? 1e9 : 1.0);
      if (scene == "hall") {
        ratio_hall_measured = true;
        worst_ratio_hall = std::max(worst_ratio_hall, ratio);
      } else {
        ratio_lit_measured = true;
        worst_ratio_lit = std::max(worst_ratio_lit, ratio);
      }
    }
    // rt: a vertical line at its time, over the errors drawn.
    avg_chart.series.push_back(
        {"rt (exact, one pass)", {rt_seconds, rt_seconds}, {lowest_avg, highest_avg}});
    max_chart.series.push_back(
        {"rt (exact, one pass)", {rt_seconds, rt_seconds}, {lowest_max, highest_max}});
    const std::string stem = scene + "_" + std::to_string(lights) + ".png";
    charts.push_back({"converge_avg_" + stem, avg_chart});
    charts.push_back({"converge_max_" + stem, max_chart});
  }
  write_table(run, out_dir, "converge_passes", passes);

  SectionText text;
  text.heading = "converge: error against time as passes accumulate, per method (new)";
  text.intro =
      followed_methods_text(c) + " each render up to " + last_text +
      " passes, every pass at the pixel centres (no antialiasing "
      "jitter), so that the error against rt's one-pass image is the methods' own: a "
      "deterministic method (lev, lev_est) repeats its image and keeps its bias (so it stops "
      "once its passes cost more than rt), a sampling method (lev_mc, light_tree) draws other "
      "lights each pass and its mean converges to rt. Every render takes the same subsample "
      "of the pixels (px), rt's too. The passes of all methods of a scene are made in turns; "
      "times are the process' CPU seconds of the passes so far, scaled to the whole frame. "
      "The table compares the methods at equal time, the error "
      "each reaches within a share of rt's time (0 passes: not even one fits); the log-log "
      "slope of the average error from a sixteenth of the passes to the last is -0.5 where "
      "noise dominates and 0 for a fixed bias. Every snapshot (1, 2, 3, 4, 6, 8, ... passes, with "
      "the framebuffer's own noise estimate beside the true error) is in converge_passes.csv.\n\n";
  const std::string ratio_name = budget_name(ratio_budget);
  std::vector<HeadlineRow> headline{
      {"converge: lev_mc's and light_tree's average error after " + last_text +
           " passes, every scene (unbiased)",
       "<= 0.5%", "-",
       unbiased_measured ? format_fixed(worst_unbiased_pct, 3) + "% (largest)" : "n/a",
       status(unbiased_measured && !c.quick, worst_unbiased_pct <= 0.5)},
      {"converge: lev_mc's avg error (its better tolerance) over light_tree's at " + ratio_name +
           ", building and maze",
       "<= 0.25", "-", ratio_lit_measured ? format_fixed(worst_ratio_lit, 2) + " (largest)" : "n/a",
       status(ratio_lit_measured && !c.quick, worst_ratio_lit <= 0.25)},
      {"converge: lev_mc's avg error (its better tolerance) over light_tree's at " + ratio_name +
           ", hall",
       "<= 1", "-", ratio_hall_measured ? format_fixed(worst_ratio_hall, 2) + " (largest)" : "n/a",
       status(ratio_hall_measured && !c.quick, worst_ratio_hall <= 1.0)},
      {"converge: hall, lev_mc (its better tolerance) reaches " + target_text + ", speedup over rt",
       ">= 10x", "-",
       !hall_target_measured  ? "n/a"
       : !hall_target_all_met ? "not within " + last_text + " passes"
                              : format_ratio(slowest_hall_target) + " (slowest)",
       status(hall_target_measured && !c.quick,
              hall_target_all_met && slowest_hall_target >= 10.0)}};
  return write_section(run, out_dir, "converge", text, summary, charts, std::move(headline));
}

}  // namespace app::bench
