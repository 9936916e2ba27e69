// targets: per scene, rt's time and, for two error targets, the fastest method
// and setting of the method table that meets it: its speedup over rt and its lights tested per
// point. Every row of the table is swept over its bench tolerances, in turns with rt on the same
// pixels, as control does, then searched between them (target_refinement.h); the whole sweep is
// written beside the summary. The same sweep is
// checked for monotonicity (monotonicity.h): every deterministic method's violations are printed,
// and so is every deterministic render slower than rt (time_against_rt.h), with why.
#include "app/bench/experiment_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/bench/monotonicity.h"
#include "app/bench/target_refinement.h"
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
  double speedup = kNaN;  // over rt in the same round
  PixelErrors errors;
  double lights_tested = kNaN;
  int round = 0;  // 0: the grid; k: the k-th round of the search between its settings
  const Measurement* measurement = nullptr;
  double rt_seconds = kNaN;  // rt's time in the same round
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
                     {"search_round", "search round"},
                     {"pixels", "px"}};
  Table sweep;
  sweep.columns = per_method_columns({{"lights_tested_avg", "lights tested/pt"},
                                      {"rt_fallback", "shaded with rt's loop"},
                                      {"search_round", "search round"},
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
    std::vector<const Measurement*> done = run.measure_together(requests);
    const Measurement& reference = *done.front();
    const double rt_seconds = reference.full_frame_cpu_seconds();
    std::vector<SweptRender> renders;
    const auto add_renders = [&](int round) {
      const double round_rt_seconds = done.front()->full_frame_cpu_seconds();
      for (std::size_t i = 1; i < requests.size(); ++i) {
        const Measurement& m = *done[i];
        const lev::MethodInfo& info = lev::method_info(requests[i].method);
        const double seconds = m.full_frame_cpu_seconds();
        renders.push_back({&info, requests[i].tolerance, seconds, round_rt_seconds / seconds,
                           pixel_errors(m, reference), m.lights_tested_avg(), round, &m,
                           round_rt_seconds});
      }
    };
    add_renders(0);
    // The search between grid settings (target_refinement.h): each round renders, in turns with
    // rt again, the settings between each method's fastest that meets a target and the next
    // looser one, where that one was faster than the best so far.
    for (int round = 1; round <= c.target_search_rounds && !run.planning(); ++round) {
      requests = {{scene, level, rt, 0.0, stride, c.runs}};
      requests.front().round = round;
      for (const ErrorTarget& target : targets) {
        std::vector<SettingResult> results;
        for (const SweptRender& r : renders) {
          results.push_back({r.method, r.tolerance, r.speedup, meets(target, r.errors)});
        }
        for (const SettingToTry& t : settings_to_try(results)) {
          bool asked = false;
          for (const MeasureRequest& q : requests) {
            asked = asked || (q.method == t.method->id && q.tolerance == t.setting);
          }
          if (asked) continue;
          MeasureRequest& q = requests.emplace_back(
              MeasureRequest{scene, level, t.method->id, t.setting, stride, c.runs});
          q.rt_fallback = true;
          q.round = round;
        }
      }
      if (requests.size() == 1) break;
      done = run.measure_together(requests);
      add_renders(round);
    }
    // Each method's renders together, loosest setting first (its bench_tolerances' order), the
    // search's settings in their places: the sweep table, the monotonicity check and the time
    // check read them so.
    std::stable_sort(renders.begin(), renders.end(),
                     [](const SweptRender& a, const SweptRender& b) {
                       if (a.method != b.method) return a.method->id < b.method->id;
                       return a.tolerance > b.tolerance;
                     });
    const std::string scene_name = scene + " " + format_count(lights);
    for (std::size_t i = 0; i < renders.size(); ++i) {
      const SweptRender& r = renders[i];
      const lev::MethodInfo& info = *r.method;
      const Measurement& m = *r.measurement;
      if (!info.stochastic && !info.is_reference && !run.planning()) {
        if (const std::optional<SlowerThanRt> slower =
                check_time_against_rt(scene_name, info.name, r.tolerance, r.seconds, r.rt_seconds,
                                      r.lights_tested, reference.lights_tested_avg())) {
          slower_than_rt.push_back(*slower);
          slower_than_rt.back().shaded_with_rt = m.rt_fallback_used;
        }
      }
      sweep.rows.push_back(
          {text_cell(scene), count_cell(lights), text_cell(info.name),
           text_cell(setting_text(info, r.tolerance)), number_cell(r.seconds, 3),
           number_cell(m.full_frame_seconds(), 3), ratio_cell(r.speedup),
           number_cell(r.errors.average_pct, 4), number_cell(r.errors.max_pct, 3),
           number_cell(r.lights_tested, 1), text_cell(m.rt_fallback_used ? "yes" : "no"),
           count_cell(static_cast<std::uint64_t>(r.round)), text_cell(pixels_text(stride))});
      if (info.id == lev::Method::lev && r.tolerance == c.tolerance && r.round == 0) {
        if (scene == "street") street_lev_seconds = r.seconds;
        if (scene == "street_bare") bare_street_lev_seconds = r.seconds;
      }
      // The end of a method's sweep: its monotonicity.
      if (i + 1 == renders.size() || renders[i + 1].method != r.method) {
        if (!info.stochastic && !run.planning()) {
          std::vector<SweepPoint> points;
          for (const SweptRender& p : renders) {
            if (p.method == r.method) points.push_back({p.tolerance, p.errors});
          }
          for (const MonotonicityViolation& v :
               find_monotonicity_violations(scene_name, info.name, points)) {
            violations.push_back(v);
          }
        }
      }
    }
    for (const ErrorTarget& target : targets) {
      const SweptRender* best = nullptr;
      for (const SweptRender& r : renders) {
        if (meets(target, r.errors) && (!best || r.speedup > best->speedup)) best = &r;
      }
      if (!best) {
        summary.rows.push_back({text_cell(scene), count_cell(lights), number_cell(rt_seconds, 3),
                                text_cell(target.name), text_cell("none"), text_cell("-"),
                                number_cell(kNaN, 3), ratio_cell(kNaN), number_cell(kNaN, 4),
                                number_cell(kNaN, 3), number_cell(kNaN, 1), count_cell(0),
                                text_cell(pixels_text(stride))});
        continue;
      }
      summary.rows.push_back(
          {text_cell(scene), count_cell(lights), number_cell(rt_seconds, 3), text_cell(target.name),
           text_cell(best->method->name), text_cell(setting_text(*best->method, best->tolerance)),
           number_cell(best->seconds, 3), ratio_cell(best->speedup),
           number_cell(best->errors.average_pct, 4), number_cell(best->errors.max_pct, 3),
           number_cell(best->lights_tested, 1), count_cell(static_cast<std::uint64_t>(best->round)),
           text_cell(pixels_text(stride))});
    }
    // The plot: each method's fastest setting under the first target, at this scene's place.
    for (Series& s : per_method) {
      double fastest = kNaN;
      for (const SweptRender& r : renders) {
        if (s.label == r.method->name && meets(targets.front(), r.errors) &&
            !(r.speedup <= fastest)) {
          fastest = r.speedup;
        }
      }
      if (std::isnan(fastest)) continue;
      s.x.push_back(scene_index);
      s.y.push_back(fastest);
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
      "its bench tolerances, then searched between them (up to " +
      std::to_string(c.target_search_rounds) +
      " rounds: the setting between a method's fastest that meets a target and the next looser one "
      "that misses it, where that one was faster than the best so far; search round 0 is the "
      "grid), CPU seconds per full frame, median of at least " +
      std::to_string(c.runs) +
      " runs made in turns with rt (measured again in each round; the speedup is over the rt of "
      "its round, rt CPU s is the first round's). \"none\": no setting met the target. The whole "
      "sweep is in "
      "targets_sweep.csv. lights tested/pt counts the shadow-tested lights per shading point (a "
      "cut's size for a method that shades clusters). street and street_bare are the same town, "
      "its "
      "lamps placed as instances of one master or written bare.\n\n";
  return write_section(run, out_dir, "targets", text, summary, {{"targets_speedup.png", chart}},
                       headline);
}

}  // namespace app::bench
