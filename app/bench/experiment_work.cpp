// work: thesis Tables 12-15, from the scaling runs.
#include "app/bench/experiment_support.h"

#include <string>
#include <vector>

#include "app/bench/thesis_data.h"

namespace app::bench {

Section run_work(BenchRun& run, const std::string& out_dir) {
  const SuiteConfig& c = run.config();
  Table table;
  table.columns = per_tolerance_columns({{"lights_tested_avg", "lights tested/pt"},
                                         {"nodes_visited_avg", "volumes checked/pt"},
                                         {"shadow_rays_avg", "shadow rays/pt"},
                                         {"thesis_lights_tested", "thesis: lights/pt"},
                                         {"thesis_nodes_visited", "thesis: volumes/pt"}});
  std::vector<NamedChart> charts;
  for (const ScalingPlan& p : scaling_plan(run)) {
    Chart tested, nodes;
    tested.title = scene_label(p.scene) + ": lights tested per shading point";
    nodes.title = scene_label(p.scene) + ": extent volumes checked per shading point";
    tested.x_label = nodes.x_label = "lights";
    tested.y_label = "lights tested per point";
    nodes.y_label = "volumes checked per point";
    tested.log_x = tested.log_y = nodes.log_x = nodes.log_y = true;
    for (double t : c.scaling_tolerances) {
      Series st{"tolerance " + tolerance_text(t), {}, {}}, sn = st;
      for (int level : p.levels) {
        const std::uint64_t lights = run.light_count(p.scene, level);
        const Measurement& m = scaling_measure(run, p.scene, level, t);
        table.rows.push_back(
            {text_cell(p.scene), count_cell(lights), text_cell(tolerance_text(t)),
             text_cell(pixels_text(m.request.stride)), number_cell(m.lights_tested_avg(), 1),
             number_cell(m.nodes_visited_avg(), 1), number_cell(m.shadow_rays_avg(), 1),
             number_cell(thesis_lookup(thesis_work_tested(p.scene), lights, t), 0),
             number_cell(thesis_lookup(thesis_work_nodes(p.scene), lights, t), 0)});
        st.x.push_back(static_cast<double>(lights));
        st.y.push_back(m.lights_tested_avg());
        sn.x.push_back(static_cast<double>(lights));
        sn.y.push_back(m.nodes_visited_avg());
      }
      tested.series.push_back(st);
      nodes.series.push_back(sn);
    }
    charts.push_back({"work_lights_" + p.scene + ".png", tested});
    charts.push_back({"work_volumes_" + p.scene + ".png", nodes});
  }
  SectionText text;
  text.heading =
      "work: lights tested and extent volumes checked per shading point (thesis Tables "
      "12-15)";
  text.intro =
      "From the scaling runs. *Lights tested* are the lights the walk returns (each gets a shadow "
      "ray unless it "
      "is behind the surface: *shadow rays*). *Volumes checked* counts every box test of the walk "
      "(a union "
      "tests its children's boxes before descending) and every light's exact irradiance test.\n\n";
  return write_section(run, out_dir, "work", text, table, charts);
}

}  // namespace app::bench
