#include "app/sweep/sweep_run.h"

#include <cmath>

#include "core/preset.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::app::sweep {

const std::vector<std::string>& figure_names() {
  static const std::vector<std::string> names = {"frame_access_rate_Hz", "range_maps_per_s",  "signal_range_dB",
                                                 "background_range_dB",  "sbr_min_dB",        "sbr_max_dB",
                                                 "sbr_ratio_min_dB",     "sbr_ratio_max_dB",  "accuracy_min_m",
                                                 "accuracy_max_m",       "points_detectable", "points_total"};
  return names;
}

namespace {
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
}  // namespace

SweepRow run_variant(const ParamSet& base, long long index, const std::vector<std::string>& assignment) {
  SweepRow r;
  r.index = index;
  r.assignment = assignment;
  ParamSet p = base;
  try {
    apply_settings(p, assignment);  // the variant's keys, with the preset's checks
  } catch (const UserError& e) {
    r.reason = e.what();
    return r;
  }
  const golden::FrameTiming t = golden::frame_timing_for(p);
  const golden::EvalResult ev = golden::evaluate_sensor(p);
  r.valid = true;
  r.figures = {{"frame_access_rate_Hz", number(t.frame_access_rate_Hz)},
               {"range_maps_per_s", number(t.range_maps_per_s)},
               {"signal_range_dB", number(ev.signal_range.range_dB)},
               {"background_range_dB", number(ev.background_range.range_dB)},
               {"sbr_min_dB", number(ev.sbr_min_dB)},
               {"sbr_max_dB", number(ev.sbr_max_dB)},
               {"sbr_ratio_min_dB", number(ev.sbr_ratio_min_dB)},
               {"sbr_ratio_max_dB", number(ev.sbr_ratio_max_dB)},
               {"accuracy_min_m", number(ev.accuracy_min_m)},
               {"accuracy_max_m", number(ev.accuracy_max_m)},
               {"points_detectable", ev.points_detectable},
               {"points_total", ev.points.size()}};
  return r;
}

nlohmann::json row_json(const SweepRow& r) {
  nlohmann::json j = {{"variant", r.index}, {"set", r.assignment}, {"valid", r.valid}};
  if (!r.valid) j["reason"] = r.reason;
  for (const auto& name : figure_names()) j[name] = r.valid ? r.figures.at(name) : nlohmann::json(nullptr);
  return j;
}

SweepRow row_from_json(const nlohmann::json& j) {
  SweepRow r;
  r.index = j.at("variant").get<long long>();
  r.assignment = j.at("set").get<std::vector<std::string>>();
  r.valid = j.at("valid").get<bool>();
  if (!r.valid) r.reason = j.at("reason").get<std::string>();
  if (r.valid)
    for (const auto& name : figure_names()) r.figures[name] = j.at(name);
  return r;
}

}  // namespace rangesim::app::sweep
