#pragma once
// The analytic part of the tof-lockin sensor interface (golden/common/evaluate_sensor.h): the entry
// points from a preset, defined in this folder.
#include <vector>

#include "golden/common/evaluate_sensor.h"

namespace rangesim::golden {

EvalResult evaluate_tof_lockin(const ParamSet& params, ProgressFn progress);
EvalResult evaluate_tof_lockin_streamed(const ParamSet& params, ProgressFn progress, EvalSink& sink);
std::vector<PublishedFigure> published_figures_tof_lockin(const ParamSet& params);
FrameTiming frame_timing_tof_lockin(const ParamSet& params);
const ThesisColumn& tof_lockin_table_column();
const GoldenModel& tof_lockin_golden_model();

}  // namespace rangesim::golden
