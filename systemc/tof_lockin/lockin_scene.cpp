#include "systemc/tof_lockin/lockin_scene.h"

#include "golden/tof_lockin/pulse_timing.h"
#include "systemc/tof_lockin/nonideal_stimulus.h"

namespace rangesim::systemc::lockin {

const char* shape_name(LockinScene::Shape s) {
  return s == LockinScene::Shape::Plane ? "plane" : s == LockinScene::Shape::Step ? "step" : "depth_map";
}

double LockinScene::distance_at(int r, int c, int array_columns) const {
  if (shape == Shape::DepthMap) return depth_map_m[static_cast<std::size_t>(r) * map_columns + c];
  if (shape == Shape::Step && c < step_column_fraction * array_columns) return near_distance_m;
  return distance_m;
}

std::vector<LockinPixelStimulus> LockinScene::stimulus(const TofLockinConfig& cfg) const {
  const int R = window_rows(cfg), C = window_columns(cfg);
  std::vector<LockinPixelStimulus> st;
  st.reserve(static_cast<std::size_t>(R) * C);
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) {
      const double d = distance_at(r, c, C);
      const double k = reference_distance_m / d;
      st.push_back({signal_photocurrent_A * k * k, background_photocurrent_A, golden::round_trip_delay_s(d)});
    }
  apply_nonideal(cfg, st, R, C);  // multipath, point spread and crosstalk, the chip's fixed pattern
  return st;
}

}  // namespace rangesim::systemc::lockin
