#include "golden/tof_lockin/model.h"

namespace rangesim::golden {

const GoldenModel& tof_lockin_golden_model() {
  static const GoldenModel model{"tof-lockin",
                                 &evaluate_tof_lockin,
                                 &published_figures_tof_lockin,
                                 &frame_timing_tof_lockin,
                                 &tof_lockin_table_column(),
                                 &evaluate_tof_lockin_streamed};
  return model;
}

}  // namespace rangesim::golden
