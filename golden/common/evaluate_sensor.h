#pragma once
// The analytic part of the sensor interface and its registry: each sensor's golden model
// (golden/<sensor>/model.h) evaluates a preset's grid, gives the published figures of its chip
// and the frame timing of its clock schedule. Commands reach a sensor's model only through here.
#include <string>
#include <vector>

#include "core/params.h"
#include "golden/common/frame_timing.h"
#include "golden/common/published_figure.h"
#include "golden/common/sensor_evaluation.h"
#include "golden/common/table_5_1.h"

namespace rangesim::golden {

// Progress of a grid evaluation in operating points (done of total); called from the evaluating
// thread, possibly more than once with the same count. It may throw to cancel the evaluation (the
// Python module does on Ctrl-C): every model then stops handing out points, joins its threads and
// lets the exception through.
using ProgressFn = void (*)(int done, int total);

struct GoldenModel {
  std::string sensor;                                                         // preset id (core/sensor_registry.h)
  EvalResult (*evaluate)(const ParamSet& params, ProgressFn progress);        // the preset's grid (`evaluation.*`)
  std::vector<PublishedFigure> (*published_figures)(const ParamSet& params);  // with rangesim's values
  FrameTiming (*frame_timing)(const ParamSet& params);  // the clock schedule (`rangesim frame-rate`)
  const ThesisColumn* table_column = nullptr;           // the sensor's column of thesis Table 5.1, if it has one
  // The same evaluation handing each background row to the sink instead of keeping it, so memory
  // stays bounded for any grid (golden/common/grid_scan.h); nullptr: evaluate_sensor_streamed
  // feeds the sink from `evaluate`.
  EvalResult (*evaluate_streamed)(const ParamSet& params, ProgressFn progress, EvalSink& sink) = nullptr;
};

// The model of a sensor id, nullptr when it has none.
const GoldenModel* golden_model(const std::string& sensor_id);
// Adds a model (tests/core/test_fifth_sensor.cpp); the id must be new (std::invalid_argument).
void register_golden_model(const GoldenModel& model);

// The preset's sensor's model; each throws std::logic_error for a sensor without one.
EvalResult evaluate_sensor(const ParamSet& params, ProgressFn progress = nullptr);
// The evaluation with its points handed to `sink` row by row (EvalResult::points stays empty).
EvalResult evaluate_sensor_streamed(const ParamSet& params, EvalSink& sink, ProgressFn progress = nullptr);
std::vector<PublishedFigure> published_figures(const ParamSet& params);
FrameTiming frame_timing_for(const ParamSet& params);

}  // namespace rangesim::golden
