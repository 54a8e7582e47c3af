#include "golden/ls_conventional/model.h"

namespace rangesim::golden {

const GoldenModel& ls_conventional_golden_model() {
  static const GoldenModel model{"ls-conventional",
                                 &evaluate_ls_conventional,
                                 &published_figures_ls_conventional,
                                 &frame_timing_ls_conventional,
                                 &ls_conventional_table_column(),
                                 &evaluate_ls_conventional_streamed};
  return model;
}

}  // namespace rangesim::golden
