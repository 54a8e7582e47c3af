#pragma once
// The analytic part of the ls-demodulation sensor interface (golden/common/evaluate_sensor.h): the entry
// points from a preset, defined in this folder.
#include <vector>

#include "golden/common/evaluate_sensor.h"

namespace rangesim::golden {

EvalResult evaluate_ls_demodulation(const ParamSet& params, ProgressFn progress);
EvalResult evaluate_ls_demodulation_streamed(const ParamSet& params, ProgressFn progress, EvalSink& sink);
std::vector<PublishedFigure> published_figures_ls_demodulation(const ParamSet& params);
FrameTiming frame_timing_ls_demodulation(const ParamSet& params);
const ThesisColumn& ls_demodulation_table_column();
const GoldenModel& ls_demodulation_golden_model();

}  // namespace rangesim::golden
