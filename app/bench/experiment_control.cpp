// control: every method's pixel error against its certified error bound (renderer/error_bound.h),
// with its time, per tolerance. The bound is what a user sees without rendering
// rt; this experiment renders rt to show how tight it is and that it holds on every pixel.
#include "app/bench/experiment_support.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "lev/methods.h"
#include "renderer/error_bound.h"

namespace app::bench {
namespace {

// How loose the bound is: the average bound over the average true error. Without error (rt, or a
// method exact here) the ratio says nothing: "-" when the bound is 0 too, "inf" when it is not.
Cell bound_over_error_cell(double bound_pct, double error_pct) {
  if (error_pct > 0.0) return ratio_cell(bound_pct / error_pct);
  return text_cell(bound_pct > 0.0 ? "inf" : "-");
}

}  // namespace

Section run_control(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = per_method_columns({{"error_bound_avg_pct", "avg bound (%)"},
                                      {"error_bound_max_pct", "max bound (%)"},
                                      {"bound_holds_pct", "bound holds (% of px)"},
                                      {"pixels", "px"},
                                      {"bound_over_error", "avg bound / avg error"}});
  std::vector<NamedChart> charts;
  double fewest_held_pct = 100.0;
  bool measured = false;
  for (const auto& [scene, wanted_lights] : c.control_renders) {
    const std::optional<ReferencedScene> where = referenced_scene(run, scene, wanted_lights);
    if (!where) continue;  // not in this build's scene table: the section says so
    const auto [level, lights, stride] = *where;
    const lev::Method rt = lev::reference_method();
    std::vector<MeasureRequest> requests{{scene, level, rt, 0.0, stride, c.runs, true}};
    for (const lev::MethodInfo& m : lev::method_table()) {
      for (double t : swept_tolerances(run, m))
        requests.push_back({scene, level, m.id, t, stride, c.runs, true});
    }
    const std::vector<const Measurement*> done = run.measure_together(requests);
    const Measurement& reference = *done.front();
    const double rt_seconds = reference.full_frame_cpu_seconds();

    Chart chart;
    chart.title =
        scene + ", " + format_count(lights) + " lights: time against average error (dashed: rt)";
    chart.x_label = "average pixel error against rt (%, 0 drawn at 1e-4)";
    chart.y_label = "CPU seconds per frame";
    chart.log_x = chart.log_y = true;
    Series current;
    for (std::size_t i = 0; i < requests.size(); ++i) {
      const MeasureRequest& r = requests[i];
      const Measurement& m = *done[i];
      const lev::MethodInfo& info = lev::method_info(r.method);
      const PixelErrors e = pixel_errors(m, reference);
      const renderer::PixelErrorStats bound = renderer::error_bound_stats(m.totals);
      const double held = bound_holds_pct(m, reference);
      const double seconds = m.full_frame_cpu_seconds();
      if (!m.planned_only) {
        measured = true;
        // NaN (pixels that do not line up) counts as failing.
        fewest_held_pct = std::isnan(held) ? 0.0 : std::min(fewest_held_pct, held);
      }
      table.rows.push_back({text_cell(scene), count_cell(lights), text_cell(info.name),
                            text_cell(info.uses_tolerance ? tolerance_text(r.tolerance) : "-"),
                            number_cell(seconds, 3), number_cell(m.full_frame_seconds(), 3),
                            ratio_cell(rt_seconds / seconds), number_cell(e.average_pct, 4),
                            number_cell(e.max_pct, 3), number_cell(bound.average_pct, 4),
                            number_cell(bound.max_pct, 3), number_cell(held, 2),
                            text_cell(pixels_text(stride)),
                            bound_over_error_cell(bound.average_pct, e.average_pct)});
      if (info.is_reference) {
        chart.series.push_back({info.name, {0.0}, {rt_seconds}, true});
        continue;
      }
      if (current.label != info.name) {
        if (!current.label.empty()) chart.series.push_back(current);
        current = Series{info.name, {}, {}};
      }
      current.x.push_back(error_on_log_axis(e.average_pct));
      current.y.push_back(seconds);
    }
    if (!current.label.empty()) chart.series.push_back(current);
    // The reference line last, so the methods keep their colours across the scenes' charts.
    std::rotate(chart.series.begin(), chart.series.begin() + 1, chart.series.end());
    charts.push_back({"control_" + scene + "_" + std::to_string(lights) + ".png", chart});
  }

  SectionText text;
  text.heading = "control: pixel error against the certified error bound, per method (new)";
  text.intro =
      "Every method of the method table at each of its bench tolerances, on the scenes and light "
      "counts where lev's per-light tolerance holds (building, maze) and where many culled lights "
      "add up (the hall). Each render also computes its certified per-pixel error bound "
      "(renderer/error_bound.h), which the times include; CPU seconds, median of at least " +
      std::to_string(c.runs) +
      " runs, every render of a scene made in turns. Errors are against rt on the same pixels "
      "(px: rt's subsample, taken by every method of the scene). The bound holds at a pixel when "
      "its error is at most its bound plus one 8-bit step per channel (the rounding of the two "
      "images); it must hold on every pixel. The bound assumes no shadows (every culled light "
      "counts as if seen), so where walls hide the culled lights (the building) it stays far "
      "above the true error; avg bound / avg error says how far.\n\n";
  std::vector<HeadlineRow> headline{
      {"control: pixels within the certified error bound, every method, scene and tolerance",
       "100%", "-", measured ? format_fixed(fewest_held_pct, 2) + "% (fewest)" : "n/a",
       status(measured, fewest_held_pct >= 100.0)}};
  return write_section(run, out_dir, "control", text, table, charts, std::move(headline));
}

}  // namespace app::bench
