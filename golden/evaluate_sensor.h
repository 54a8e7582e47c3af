#pragma once
// One entry point per command for every sensor: the analytic evaluation and the published
// figures, dispatched on the preset's sensor id.
#include <vector>

#include "core/params.h"
#include "golden/frame_timing.h"
#include "golden/published_figure.h"
#include "golden/sensor_evaluation.h"

namespace rangesim::golden {

using ProgressFn = void (*)(int done, int total);

// Evaluates the preset's grid (`evaluation.*` keys). Throws std::logic_error for a sensor
// without a golden model.
EvalResult evaluate_sensor(const ParamSet& params, ProgressFn progress = nullptr);

// The published figures of the preset's chip with rangesim's values (preset parameters).
std::vector<PublishedFigure> published_figures(const ParamSet& params);

// Frame timing from the preset's clock schedule (`rangesim frame-rate`); the same figures the
// clock-level model must measure cycle for cycle. Throws std::logic_error without a schedule.
FrameTiming frame_timing_for(const ParamSet& params);
FrameTiming frame_timing_ls_demodulation(const ParamSet& params);
FrameTiming frame_timing_tof_lockin(const ParamSet& params);
FrameTiming frame_timing_tof_spad(const ParamSet& params);

// Per-sensor entry points (golden/<sensor>/evaluate.h).
EvalResult evaluate_ls_conventional(const ParamSet& params, ProgressFn progress);
EvalResult evaluate_ls_demodulation(const ParamSet& params, ProgressFn progress);
EvalResult evaluate_tof_lockin(const ParamSet& params, ProgressFn progress);
EvalResult evaluate_tof_spad(const ParamSet& params, ProgressFn progress);
std::vector<PublishedFigure> published_figures_ls_conventional(const ParamSet& params);
std::vector<PublishedFigure> published_figures_ls_demodulation(const ParamSet& params);
std::vector<PublishedFigure> published_figures_tof_lockin(const ParamSet& params);
std::vector<PublishedFigure> published_figures_tof_spad(const ParamSet& params);

}  // namespace rangesim::golden
