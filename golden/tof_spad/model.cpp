#include "golden/tof_spad/model.h"

namespace rangesim::golden {

const GoldenModel& tof_spad_golden_model() {
  static const GoldenModel model{"tof-spad",
                                 &evaluate_tof_spad,
                                 &published_figures_tof_spad,
                                 &frame_timing_tof_spad,
                                 &tof_spad_table_column(),
                                 &evaluate_tof_spad_streamed};
  return model;
}

}  // namespace rangesim::golden
