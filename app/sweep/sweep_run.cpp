#include "app/sweep/sweep_run.h"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/preset.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "app/montecarlo/mc_sweep.h"
#include "systemc/common/montecarlo.h"
#if RANGESIM_SWEEP_HAS_RTL
#include "tb/common/rtl_build.h"
#endif

namespace rangesim::app::sweep {

std::vector<std::string> figure_names(const VariantChecks& checks) {
  std::vector<std::string> names = {"frame_access_rate_Hz", "range_maps_per_s", "signal_range_dB", "background_range_dB",
                                    "sbr_min_dB",           "sbr_max_dB",       "sbr_ratio_min_dB", "sbr_ratio_max_dB",
                                    "accuracy_min_m",       "accuracy_max_m",   "points_detectable", "points_total"};
  if (checks.trials > 0)
    for (const char* n : {"mc_accuracy_min_m", "mc_accuracy_min_lo_m", "mc_accuracy_min_hi_m", "mc_accuracy_max_m",
                          "mc_accuracy_max_lo_m", "mc_accuracy_max_hi_m", "mc_points"})
      names.push_back(n);
  if (checks.cosim)
    for (const char* n : {"cosim_transactions", "cosim_mismatches", "cosim_golden_checks"}) names.push_back(n);
  return names;
}

namespace {

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// Monte Carlo accuracy (rms error with its 95% CI) at every detectable grid point of the variant,
// on the clock-level kernels (app/montecarlo/mc_sweep.h): the best and the worst point.
void add_monte_carlo(SweepRow& r, const ParamSet& p, const golden::EvalResult& ev, const VariantChecks& checks) {
  const std::unique_ptr<rangesim::mc::McModel> model = rangesim::mc::make_mc_model(p);
  std::vector<mc::McSweepPoint> points;
  for (std::size_t i = 0; i < ev.points.size(); ++i)
    if (ev.points[i].detect == "detectable")
      points.push_back({static_cast<long long>(i), ev.points[i].signal, ev.points[i].background});
  mc::McSweepOptions o;
  o.trials = checks.trials;
  o.max_trials = checks.trials;
  o.seed = checks.seed;
  o.threads = checks.threads;
  const mc::McSweepResult res = mc::run_mc_sweep(*model, points, o, nullptr);
  if (!res.complete) throw std::runtime_error("sweep --trials: the Monte Carlo run stopped");
  const double m = model->metres_per_unit();
  const mc::McInterval* lo = nullptr;
  const mc::McInterval* hi = nullptr;
  for (const auto& s : res.stats) {
    if (!s || !std::isfinite(s->rms.value)) continue;
    if (!lo || s->rms.value < lo->value) lo = &s->rms;
    if (!hi || s->rms.value > hi->value) hi = &s->rms;
  }
  const auto put = [&](const char* name, const mc::McInterval* x) {
    r.figures[fmt::format("mc_accuracy_{}_m", name)] = number(x ? x->value * m : NAN);
    r.figures[fmt::format("mc_accuracy_{}_lo_m", name)] = number(x ? x->lo * m : NAN);
    r.figures[fmt::format("mc_accuracy_{}_hi_m", name)] = number(x ? x->hi * m : NAN);
  };
  put("min", lo);
  put("max", hi);
  r.figures["mc_points"] = points.size();
}

// The variant's RTL (verilated at run time for its Verilog parameters, cached) against its
// clock-level model: `rangesim cosim <preset> --set ...` for this variant.
void add_cosim(SweepRow& r, const ParamSet& base, const std::vector<std::string>& assignment,
               const VariantChecks& checks) {
#if RANGESIM_SWEEP_HAS_RTL
  std::vector<std::string> settings = checks.settings;
  settings.insert(settings.end(), assignment.begin(), assignment.end());
  ParamSet p = base;
  apply_settings(p, assignment);
  const tb::PresetCosim* pc = nullptr;
  for (const auto& c : tb::preset_cosims())
    if (c.sensor == p.sensor_id()) pc = &c;
  if (!pc) throw UserError(fmt::format("--cosim: sensor {} has no RTL co-simulation at a preset's own parameters",
                                       p.sensor_id()));
  const std::string exe = tb::rtl_cosim_executable(pc->spec(p));
  tb::CosimOptions o;
  o.cycles = checks.cosim_cycles;
  o.seed = checks.seed;
  tb::CosimReport rep;
  tb::RtlCoverage cov;
  tb::run_rtl_cosim(exe, base.origin(), settings, o, rep, cov);
  r.figures["cosim_transactions"] = rep.transactions;
  r.figures["cosim_mismatches"] = rep.mismatches;
  r.figures["cosim_golden_checks"] = rep.golden_checks;
#else
  (void)r, (void)base, (void)assignment, (void)checks;
  throw UserError("--cosim: this rangesim was built without the RTL (RANGESIM_WITH_RTL=OFF, or no Verilator)");
#endif
}

}  // namespace

SweepRow run_variant(const ParamSet& base, long long index, const std::vector<std::string>& assignment,
                     const VariantChecks& checks) {
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
  // The points are kept only for the Monte Carlo trials: a variant's grid is otherwise streamed.
  golden::DiscardPoints discard;
  const golden::EvalResult ev =
      checks.trials > 0 ? golden::evaluate_sensor(p) : golden::evaluate_sensor_streamed(p, discard);
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
               {"points_total", ev.grid_points()}};
  if (checks.trials > 0) add_monte_carlo(r, p, ev, checks);
  if (checks.cosim) add_cosim(r, base, assignment, checks);
  return r;
}

nlohmann::json row_json(const SweepRow& r, const VariantChecks& checks) {
  nlohmann::json j = {{"variant", r.index}, {"set", r.assignment}, {"valid", r.valid}};
  if (!r.valid) j["reason"] = r.reason;
  for (const auto& name : figure_names(checks)) j[name] = r.valid ? r.figures.at(name) : nlohmann::json(nullptr);
  return j;
}

SweepRow row_from_json(const nlohmann::json& j, const VariantChecks& checks) {
  SweepRow r;
  r.index = j.at("variant").get<long long>();
  r.assignment = j.at("set").get<std::vector<std::string>>();
  r.valid = j.at("valid").get<bool>();
  if (!r.valid) r.reason = j.at("reason").get<std::string>();
  if (r.valid)
    for (const auto& name : figure_names(checks)) r.figures[name] = j.at(name);
  return r;
}

}  // namespace rangesim::app::sweep
