// rangesim simulate: runs a sensor's clock-level model on a scene (systemc/<sensor>/simulate.cpp),
// found through the simulate registry below, and renders the result (app/simulate/simulate_render);
// checks the flags that only some models take.
#include "app/cmd_simulate.h"

#include <fmt/format.h>

#include <iostream>
#include <systemc>

#include "app/cli_common.h"
#include "app/simulate/simulate_render.h"
#include "core/preset.h"
#include "core/sensor_list.h"
#include "core/user_error.h"

// libsystemc.so defines main() and refers to sc_main; rangesim has its own main(), so this
// definition only satisfies the linker and is never called. (Test binaries that link SystemC
// define their own sc_main and do not link this file.)
extern "C" int sc_main(int, char*[]) { return 1; }

namespace rangesim {
// The core part of each shipped sensor (core/<sensor>/schema.cpp): its id.
#define RANGESIM_DECLARE(s) const SensorInfo& s##_sensor_info();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE
}  // namespace rangesim

namespace rangesim::systemc {
// Each shipped sensor's scene run and its knobs, defined in systemc/<sensor>/simulate.cpp.
#define RANGESIM_DECLARE(s) const SimulateEntry& s##_simulate_entry();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE
}  // namespace rangesim::systemc

namespace rangesim::app {

std::vector<SimulateEntry>& simulate_registry() {
  static std::vector<SimulateEntry> list = {
#define RANGESIM_ENTRY(s) systemc::s##_simulate_entry(),
      RANGESIM_FOR_EACH_SENSOR(RANGESIM_ENTRY)
#undef RANGESIM_ENTRY
  };
  return list;
}

bool simulate_runs(const std::string& sensor) {
  for (const auto& e : simulate_registry())
    if (e.sensor == sensor) return true;
  return false;
}

namespace {

// SystemC displays its reports on stdout, which must stay clean JSON under --json: display them
// on stderr instead (logging, stopping and throwing are left to the default handler).
void report_to_stderr(const sc_core::sc_report& rep, const sc_core::sc_actions& actions) {
  if (actions & sc_core::SC_DISPLAY) std::cerr << sc_core::sc_report_compose_message(rep) << std::endl;
  sc_core::sc_report_handler::default_handler(rep, actions & ~sc_core::SC_DISPLAY);
}

}  // namespace

void route_systemc_reports_to_stderr() {
  // SystemC's informational reports (trace timescale, "stopped by user") are noise here; its
  // warnings and errors go to stderr (stdout carries --json).
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  sc_core::sc_report_handler::set_handler(report_to_stderr);
}

const SimulateEntry& simulate_entry_for(const ParamSet& params, const SimulateOptions& opt) {
  require_modelled(params, "simulate");
  const SimulateEntry* entry = nullptr;
  for (const auto& e : simulate_registry())
    if (e.sensor == params.sensor_id()) entry = &e;
  if (!entry)
    throw NotModelled{fmt::format("rangesim simulate: sensor '{}' has no clock-level model yet", params.sensor_id())};
  const auto allowed = [](bool SimulateEntry::*knob) {
    std::string ids;
    for (const auto& e : simulate_registry())
      if (e.*knob) ids += (ids.empty() ? "" : ", ") + e.sensor;
    return ids;
  };
  if (opt.no_aggregate && !entry->aggregation)
    throw UserError(fmt::format("--no-aggregate: {} has no aggregated path to switch off; allowed with {}",
                                params.sensor_id(), allowed(&SimulateEntry::aggregation)),
                    "no_aggregate");
  if (opt.time_step_s != 0.0 && !entry->time_step)
    throw UserError(fmt::format("--time-step: {} is exact on its clock grid and has no continuous-time integration to "
                                "step; allowed with {} (or 0)",
                                params.sensor_id(), allowed(&SimulateEntry::time_step)),
                    "time_step");
  if (!opt.trace_rows.empty() && !entry->trace_rows)
    throw UserError(fmt::format("--trace-rows: the {} waveform has no per-row blocks to choose; allowed with {}",
                                params.sensor_id(), allowed(&SimulateEntry::trace_rows)),
                    "trace_rows");
  if (!opt.trace_rows.empty() && opt.trace.empty())
    throw UserError("--trace-rows chooses what --trace writes; add --trace", "trace_rows");
  if (!opt.trace_pixels.empty() && !entry->trace_pixels)
    throw UserError(fmt::format("--trace-pixels: the {} waveform has no pixels to choose; allowed with {}",
                                params.sensor_id(), allowed(&SimulateEntry::trace_pixels)),
                    "trace_pixels");
  if (!opt.trace_pixels.empty() && opt.trace.empty())
    throw UserError("--trace-pixels chooses what --trace writes; add --trace", "trace_pixels");
  if (opt.threads) {
    if (*opt.threads < 1 || *opt.threads > 1024)
      throw UserError(fmt::format("--threads {}: allowed 1 .. 1024", *opt.threads), "threads");
    if (*opt.threads > 1 && !opt.kernel_only)
      throw UserError("--threads: the SystemC model runs on one thread; add --kernel-only (or --threads 1)", "threads");
    if (*opt.threads > 1 && !entry->threads)
      throw UserError(fmt::format("--threads {}: the {} kernel runs on one thread; allowed with {} (or 1)",
                                  *opt.threads, params.sensor_id(), allowed(&SimulateEntry::threads)),
                      "threads");
  }
  return *entry;
}

int run_simulate(const SimulateOptions& opt) {
  route_systemc_reports_to_stderr();
  const ParamSet params = load_modelled_preset(opt.sensor, "simulate", opt.settings);
  return run_and_render(opt, params, simulate_entry_for(params, opt));
}

}  // namespace rangesim::app
