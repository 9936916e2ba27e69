// targets: per scene, rt's time and, for two error targets, the fastest method
// and setting of the method table that meets it: its speedup over rt and its lights tested per
// point. Every row of the table is swept over its bench tolerances, in turns with rt on the same
// pixels, as control does; the whole sweep is written beside the summary. The same sweep is
// checked for monotonicity (monotonicity.h): every deterministic method's violations are printed,
// and so is every deterministic render slower than rt (time_against_rt.h), with why.
#include "app/bench/experiment_support.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/bench/monotonicity.h"
#include "app/bench/time_against_rt.h"
#include "lev/methods.h"

namespace app::bench {
namespace {

struct ErrorTarget {
  std::string name;  // in the table
  double max_pct;    // the largest pixel error allowed
  double avg_pct;    // the average allowed (infinite: no bound)
};

bool meets(const ErrorTarget& target, const PixelErrors& e) {
  return e.max_pct < target.max_pct && e.average_pct < target.avg_pct;
}

// The swept setting as the tables show it: "-" for a method swept over neither.
std::string setting_text(const lev::MethodInfo& method, double setting) {
  return method.uses_tolerance || method.uses_relative_error ? tolerance_text(setting) : "-";
}

// One render of the sweep, as the summary and the plot read it.
struct SweptRender {
  const lev::MethodInfo* method = nullptr;
  double tolerance = 0.0;
  double seconds = kNaN;
  PixelErrors errors;
  double lights_tested = kNaN;
};

// A check's paragraph for results.md ("Title: none." or "Title: 2 renders:" and a list), each
// line also printed on stderr after `tag`.
std::string findings_text(const std::string& title, const char* tag, const char* none,
                          const char* plural, const std::vector<std::string>& lines) {
  if (lines.empty()) return title + ": " + none + ".\n\n";
  std::string text = title + ": " + std::to_string(lines.size()) + " " + plural + ":\n\n";
  for (const std::string& line : lines) {
    std::cerr << tag << ": " << line << "\n";
    text += "- " + line + "\n";
  }
  return text + "\n";
}

}  // namespace

Section run_targets(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  const std::vector<ErrorTarget> targets{
      {"max < " + tolerance_text(c.target_max_pct) + " %", c.target_max_pct,
       std::numeric_limits<double>::infinity()},
      {"avg < " + tolerance_text(c.target_avg_pct) + " % and max < " +
           tolerance_text(c.target_avg_max_pct) + " %",
       c.target_avg_max_pct, c.target_avg_pct}};
  Table summary;
  summary.columns = {{"scene", "scene"},
                     {"lights", "lights"},
                     {"rt_seconds", "rt CPU s"},
                     {"target", "target"},
                     {"method", "fastest method"},
                     {"tolerance", "setting"},
                     {"seconds", "CPU s"},
                     {"speedup", "speedup over rt"},
                     {"pixel_error_avg_pct", "avg error (%)"},
                     {"pixel_error_max_pct", "max error (%)"},
                     {"lights_tested_avg", "lights tested/pt"},
                     {"pixels", "px"}};
  Table sweep;
  sweep.columns = per_method_columns({{"lights_tested_avg", "lights tested/pt"},
                                      {"rt_fallback", "shaded with rt's loop"},
                                      {"pixels", "px"}});
  Chart chart;
  chart.title = "Speedup over rt of each method's fastest setting with max error < " +
                tolerance_text(c.target_max_pct) + " %";
  chart.y_label = "speedup over rt (CPU time)";
  chart.log_y = true;
  std::vector<Series> per_method;
  for (const lev::MethodInfo& m : lev::method_table()) {
    if (!m.is_reference) per_method.push_back({m.name, {}, {}});
  }
  std::string scene_keys;
  std::vector<HeadlineRow> headline;
  std::optional<double> street_lev_seconds, bare_street_lev_seconds;
  std::vector<MonotonicityViolation> violations;
  std::vector<SlowerThanRt> slower_than_rt;
  int scene_index = 0;
  for (const auto& [scene, wanted_lights] : c.target_renders) {
    const std::optional<ReferencedScene> where = referenced_scene(run, scene, wanted_lights);
    if (!where) continue;
    const auto [level, lights, stride] = *where;
    ++scene_index;
    scene_keys += (scene_keys.empty() ? "" : ", ") + std::to_string(scene_index) + " " + scene +
                  " " + format_count(lights);
    const lev::Method rt = lev::reference_method();
    std::vector<MeasureRequest> requests{{scene, level, rt, 0.0, stride, c.runs}};
    for (const lev::MethodInfo& m : lev::method_table()) {
      for (double t : swept_tolerances(run, m)) {
        MeasureRequest& r =
            requests.emplace_back(MeasureRequest{scene, level, m.id, t, stride, c.runs});
        r.rt_fallback =
            true;  // what a user gets (issue 23: no deterministic method slower than rt)
      }
    }
    const std::vector<const Measurement*> done = run.measure_together(requests);
    const Measurement& reference = *done.front();
    const double rt_seconds = reference.full_frame_cpu_seconds();
    std::vector<SweptRender> renders;
    // Each deterministic method's sweep, loosest setting first (its bench_tolerances' order).
    std::vector<SweepPoint> sweep_points;
    const lev::MethodInfo* sweep_method = nullptr;
    const std::string scene_name = scene + " " + format_count(lights);
    const auto check_sweep = [&] {
      if (sweep_method && !sweep_method->stochastic && !run.planning()) {
        for (const MonotonicityViolation& v :
             find_monotonicity_violations(scene_name, sweep_method->name, sweep_points)) {
          violations.push_back(v);
        }
      }
      sweep_points.clear();
    };
    for (std::size_t i = 1; i < requests.size(); ++i) {
      const Measurement& m = *done[i];
      const lev::MethodInfo& info = lev::method_info(requests[i].method);
      SweptRender r{&info, requests[i].tolerance, m.full_frame_cpu_seconds(),
                    pixel_errors(m, reference), m.lights_tested_avg()};
      renders.push_back(r);
      if (!info.stochastic && !info.is_reference && !run.planning()) {
        if (const std::optional<SlowerThanRt> slower =
                check_time_against_rt(scene_name, info.name, r.tolerance, r.seconds, rt_seconds,
                                      r.lights_tested, reference.lights_tested_avg())) {
          slower_than_rt.push_back(*slower);
          slower_than_rt.back().shaded_with_rt = m.rt_fallback_used;
        }
      }
      if (sweep_method != &info) check_sweep();
      sweep_method = &info;
      sweep_points.push_back({r.tolerance, r.errors});
      sweep.rows.push_back(
          {text_cell(scene), count_cell(lights), text_cell(info.name),
           text_cell(setting_text(info, r.tolerance)), number_cell(r.seconds, 3),
           number_cell(m.full_frame_seconds(), 3), ratio_cell(rt_seconds / r.seconds),
           number_cell(r.errors.average_pct, 4), number_cell(r.errors.max_pct, 3),
           number_cell(r.lights_tested, 1), text_cell(m.rt_fallback_used ? "yes" : "no"),
           text_cell(pixels_text(stride))});
      if (info.id == lev::Method::lev && r.tolerance == c.tolerance) {
        if (scene == "street") street_lev_seconds = r.seconds;
        if (scene == "street_bare") bare_street_lev_seconds = r.seconds;
      }
    }
    check_sweep();
    for (const ErrorTarget& target : targets) {
      const SweptRender* best = nullptr;
      for (const SweptRender& r : renders) {
        if (meets(target, r.errors) && (!best || r.seconds < best->seconds)) best = &r;
      }
      if (!best) {
        summary.rows.push_back({text_cell(scene), count_cell(lights), number_cell(rt_seconds, 3),
                                text_cell(target.name), text_cell("none"), text_cell("-"),
                                number_cell(kNaN, 3), ratio_cell(kNaN), number_cell(kNaN, 4),
                                number_cell(kNaN, 3), number_cell(kNaN, 1),
                                text_cell(pixels_text(stride))});
        continue;
      }
      summary.rows.push_back(
          {text_cell(scene), count_cell(lights), number_cell(rt_seconds, 3), text_cell(target.name),
           text_cell(best->method->name), text_cell(setting_text(*best->method, best->tolerance)),
           number_cell(best->seconds, 3), ratio_cell(rt_seconds / best->seconds),
           number_cell(best->errors.average_pct, 4), number_cell(best->errors.max_pct, 3),
           number_cell(best->lights_tested, 1), text_cell(pixels_text(stride))});
    }
    // The plot: each method's fastest setting under the first target, at this scene's place.
    for (Series& s : per_method) {
      double fastest = kNaN;
      for (const SweptRender& r : renders) {
        if (s.label == r.method->name && meets(targets.front(), r.errors) &&
            !(r.seconds >= fastest)) {
          fastest = r.seconds;
        }
      }
      if (std::isnan(fastest)) continue;
      s.x.push_back(scene_index);
      s.y.push_back(rt_seconds / fastest);
    }
  }
  chart.x_label = "scene: " + scene_keys;
  chart.series = per_method;
  if (street_lev_seconds && bare_street_lev_seconds) {
    const double ratio = *street_lev_seconds / *bare_street_lev_seconds;
    headline.push_back(
        {"lamp street: lev's time, lamps instanced over the same lights written bare", "<= 1.2x",
         "-", format_ratio(ratio), status(!c.quick, ratio <= 1.2)});
  }
  if (!run.planning()) {
    headline.push_back(
        {"deterministic methods: a tighter setting never raises the avg or max "
         "error against rt (targets' sweeps)",
         "0 violations", "-", std::to_string(violations.size()) + " violations",
         status(!c.quick, violations.empty())});
    headline.push_back({"deterministic methods: at most " + format_ratio(kMaxTimeOverRt) +
                            " rt's time at every setting (targets' sweeps), or the bench says why",
                        "0 slower", "-", std::to_string(slower_than_rt.size()) + " slower",
                        status(!c.quick, slower_than_rt.empty())});
  }
  // Each check's findings: printed on stderr as they are listed in results.md.
  std::vector<std::string> violation_lines, slower_lines;
  for (const MonotonicityViolation& v : violations) violation_lines.push_back(violation_text(v));
  for (const SlowerThanRt& s : slower_than_rt) slower_lines.push_back(slower_text(s));
  const std::string checks =
      findings_text(
          "Monotonicity (every deterministic method's sweep, each tighter setting "
          "against every looser one)",
          "monotonicity", "no violation", "violations", violation_lines) +
      findings_text("Time against rt (every deterministic render of the sweeps over " +
                        format_ratio(kMaxTimeOverRt) + " rt's CPU time, made in turns with it)",
                    "slower than rt", "none", "renders", slower_lines);
  write_table(run, out_dir, "targets_sweep", sweep);
  SectionText text;
  text.before_table = checks;
  text.heading = "targets: the fastest setting that meets an error target, per scene (new)";
  text.intro =
      "Per scene, rt's time and, for two error targets against rt on the same pixels (max < " +
      tolerance_text(c.target_max_pct) + " %; avg < " + tolerance_text(c.target_avg_pct) +
      " % with max < " + tolerance_text(c.target_avg_max_pct) +
      " %), the fastest method and setting of the method table that meets it: every row swept over "
      "its bench tolerances, CPU seconds per full frame, median of at least " +
      std::to_string(c.runs) +
      " runs made in turns with rt. \"none\": no setting met the target. The whole sweep is in "
      "targets_sweep.csv. lights tested/pt counts the shadow-tested lights per shading point (a "
      "cut's size for a method that shades clusters). street and street_bare are the same town, "
      "its "
      "lamps placed as instances of one master or written bare.\n\n";
  return write_section(run, out_dir, "targets", text, summary, {{"targets_speedup.png", chart}},
                       headline);
}

}  // namespace app::bench
