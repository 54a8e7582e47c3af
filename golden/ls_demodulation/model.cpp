#include "golden/ls_demodulation/model.h"

namespace rangesim::golden {

const GoldenModel& ls_demodulation_golden_model() {
  static const GoldenModel model{"ls-demodulation",
                                 &evaluate_ls_demodulation,
                                 &published_figures_ls_demodulation,
                                 &frame_timing_ls_demodulation,
                                 &ls_demodulation_table_column(),
                                 &evaluate_ls_demodulation_streamed};
  return model;
}

}  // namespace rangesim::golden
