#include "golden/common/evaluate_sensor.h"

#include <stdexcept>

#include "core/sensor_list.h"

namespace rangesim::golden {

// Each sensor's model, defined in golden/<sensor>/model.cpp.
#define RANGESIM_DECLARE(s) const GoldenModel& s##_golden_model();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE

namespace {

std::vector<GoldenModel>& registry() {
  static std::vector<GoldenModel> list = {
#define RANGESIM_ENTRY(s) s##_golden_model(),
      RANGESIM_FOR_EACH_SENSOR(RANGESIM_ENTRY)
#undef RANGESIM_ENTRY
  };
  return list;
}

const GoldenModel& model_of(const ParamSet& params) {
  const GoldenModel* m = golden_model(params.sensor_id());
  if (!m) throw std::logic_error("no golden model for sensor " + params.sensor_id());
  return *m;
}

}  // namespace

const GoldenModel* golden_model(const std::string& sensor_id) {
  for (const auto& m : registry())
    if (m.sensor == sensor_id) return &m;
  return nullptr;
}

void register_golden_model(const GoldenModel& model) {
  if (golden_model(model.sensor))
    throw std::invalid_argument("register_golden_model: " + model.sensor + " has a model already");
  registry().push_back(model);
}

EvalResult evaluate_sensor(const ParamSet& params, ProgressFn progress) {
  return model_of(params).evaluate(params, progress);
}

EvalResult evaluate_sensor_streamed(const ParamSet& params, EvalSink& sink, ProgressFn progress) {
  const GoldenModel& m = model_of(params);
  if (m.evaluate_streamed) return m.evaluate_streamed(params, progress, sink);
  EvalResult r = m.evaluate(params, progress);
  sink.begin(r);
  const std::size_t ns = r.signal.values.size();
  for (std::size_t ib = 0; ib < r.background.values.size(); ++ib)
    sink.row(ib, std::vector<EvalPoint>(r.points.begin() + static_cast<std::ptrdiff_t>(ib * ns),
                                        r.points.begin() + static_cast<std::ptrdiff_t>((ib + 1) * ns)));
  r.points.clear();
  return r;
}

std::vector<PublishedFigure> published_figures(const ParamSet& params) {
  return model_of(params).published_figures(params);
}

FrameTiming frame_timing_for(const ParamSet& params) { return model_of(params).frame_timing(params); }

}  // namespace rangesim::golden
