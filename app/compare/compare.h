#pragma once
// `rangesim compare`: the chosen sensors (default: every registered one) on one physical scene and
// one pair of physical axes, background illuminance in lux at the target x mean source power in W
// (app/physical_axes.h). Each sensor's golden model evaluates the grid in its own unit through its
// radiometry; compare puts the results side by side: the thesis Fig. 1.4-style map (SBR' against
// background illuminance, one region per sensor), the detectable background range in lux at the
// scene's source power, the accuracy against background at the scene's distance, the frame rate
// and thesis Table 5.1 in physical units. Data here; files in compare_output.cpp.
#include <string>
#include <vector>

#include "app/physical_axes.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::app {

struct CompareOptions {
  std::vector<std::string> sensors;  // preset ids or paths ("" -> every registered sensor)
  std::string scene;                 // --scene ("" = the default sunlit-wall scene)
  std::string background_lux = "0.1:1e7:41";  // --background-lux LO:HI:N
  std::string signal_power = "1e-4:10:26";    // --signal-power LO:HI:N
  int profile_points = 141;                   // background points of the fixed-power profile
  std::string out;                            // --out DIR ("" -> rangesim-out/compare)
  bool force = false;
  bool json = false;
  bool no_plots = false;
};

struct CompareSensor {
  std::string sensor;       // preset id
  std::string preset;       // as given (id or path)
  std::string title;        // one line (core/sensor_registry.h)
  std::string sbr_definition;  // "total" (eq. 3.11) or "ratio" (eq. 3.23 / 4.11): its Table 5.1 column's
  PhysicalAxes axes;
  double scene_lux = 0;     // the scene's ambient illuminance
  double scene_power_W = 0; // the scene's source power
  double scene_signal = 0;  // ... in the native unit at the scene's distance
  double scene_background = 0;
  std::string scene_detect;  // the golden classification at the scene's light
  double scene_accuracy_m = golden::kNaN;
  golden::EvalResult grid;     // lux x W grid (native axes; divide by axes.native_per_*)
  golden::EvalResult profile;  // the scene's source power x a dense lux axis
  double frame_rate_Hz = 0;    // range maps per second (golden clock schedule)
  double accuracy_distance_m = 0;  // where the accuracy figures are taken
  // Detectable background at the scene's source power, lux (NaN: none); *_grid: the edge is the axis end.
  double bg_lo_lux = golden::kNaN, bg_hi_lux = golden::kNaN;
  bool bg_lo_grid = false, bg_hi_grid = false;
  double sbr_of(const golden::EvalPoint& p) const {
    return sbr_definition == "total" ? p.sbr_total_dB : p.sbr_ratio_dB;
  }
};

struct CompareResult {
  std::string scene_file, scene_name, scene_description;
  double scene_distance_m = 0;
  std::vector<CompareSensor> sensors;
  double wall_time_s = 0;
};

CompareResult run_compare_data(const CompareOptions& opt);
int run_compare(const CompareOptions& opt);

}  // namespace rangesim::app
