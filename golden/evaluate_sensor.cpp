#include "golden/evaluate_sensor.h"

#include <stdexcept>

#include "core/ls_conventional_config.h"

namespace rangesim::golden {

EvalResult evaluate_sensor(const ParamSet& params, ProgressFn progress) {
  const std::string& id = params.sensor_id();
  if (id == "ls-conventional") return evaluate_ls_conventional(params, progress);
  if (id == "ls-demodulation") return evaluate_ls_demodulation(params, progress);
  if (id == "tof-lockin") return evaluate_tof_lockin(params, progress);
  if (id == "tof-spad") return evaluate_tof_spad(params, progress);
  throw std::logic_error("no golden model for sensor " + id);
}

std::vector<PublishedFigure> published_figures(const ParamSet& params) {
  const std::string& id = params.sensor_id();
  if (id == "ls-conventional") return published_figures_ls_conventional(params);
  if (id == "ls-demodulation") return published_figures_ls_demodulation(params);
  if (id == "tof-lockin") return published_figures_tof_lockin(params);
  if (id == "tof-spad") return published_figures_tof_spad(params);
  throw std::logic_error("no golden model for sensor " + id);
}

FrameTiming frame_timing_for(const ParamSet& params) {
  const std::string& id = params.sensor_id();
  if (id == "ls-conventional") {
    const LsConventionalConfig cfg = ls_conventional_from_params(params);
    return frame_timing(cfg.timing, cfg.multisampling.samplings);
  }
  if (id == "ls-demodulation") return frame_timing_ls_demodulation(params);
  if (id == "tof-lockin") return frame_timing_tof_lockin(params);
  if (id == "tof-spad") return frame_timing_tof_spad(params);
  throw std::logic_error("no clock schedule for sensor " + id);
}

}  // namespace rangesim::golden
