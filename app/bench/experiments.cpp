#include "app/bench/experiments.h"

#include "app/bench/experiment_support.h"

namespace app::bench {

const std::vector<ExperimentInfo>& experiments() {
  static const std::vector<ExperimentInfo> table = {
      {"speed", "Tables 1, 2", "time of every method per light count, and their ratios", run_speed},
      {"memory", "Table 3", "hierarchy bytes with and without instancing; ast's bookkeeping",
       run_memory},
      {"scaling", "Tables 4, 5", "lev time per light count at three tolerances", run_scaling},
      {"fraction", "Tables 6-9", "lights tested per point against tolerance", run_fraction},
      {"error", "Tables 10, 11", "pixel error of lev against rt per tolerance and light count",
       run_error},
      {"work", "Tables 12-15", "lights tested and volumes checked per point", run_work},
      {"trade", "new", "time against pixel error per method and scene", run_trade},
      {"control", "new",
       "every method's pixel error against its certified bound, and time, per tolerance",
       run_control},
      {"converge", "new",
       "error against time as passes accumulate, per method; the equal-time comparison",
       run_converge},
      {"targets", "new",
       "per scene, the fastest method and setting that meets each error target, and its speedup",
       run_targets},
      {"limit", "new", "levrt's render against a bare Embree loop on the same rays", run_limit},
  };
  return table;
}

}  // namespace app::bench
