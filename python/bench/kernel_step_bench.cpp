// The cost of one kernel step from C++ (docs/python.md, "Call overhead"): the loops
// python/bench/kernel_step_bench.py runs through the Python module, here in plain C++ on the
// same kernels made from the same presets. Prints JSON {step: {"ns_per_step", "steps"}}.
//   rangesim-kernel-step-bench STEPS BLOCK=PRESET ...
// Each timed block is made from the preset given for it; the Python side passes the preset
// rangesim.kernels.blocks() lists first for the block, so both time the same kernel.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/ls_conventional/config.h"
#include "core/preset.h"
#include "core/tof_lockin/config.h"
#include "core/tof_spad/config.h"
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_conventional/multisampling_sequencer_kernel.h"
#include "systemc/tof_lockin/column_adc_kernel.h"
#include "systemc/tof_lockin/lockin_gate_generator_kernel.h"
#include "systemc/tof_spad/sensor_kernel.h"
#include "systemc/tof_spad/tdc_kernel.h"

// libsystemc.so defines main() and refers to sc_main; this program has its own main().
extern "C" int sc_main(int, char*[]) { return 1; }

namespace {

using namespace rangesim;
using Clock = std::chrono::steady_clock;

std::uint64_t g_sink = 0;  // outputs folded in, so that no loop is optimised away

// ns per step of `run(steps)`, best of three.
double time_steps(long long steps, const std::function<void(long long)>& run) {
  double best = 1e300;
  for (int rep = 0; rep < 3; ++rep) {
    const auto t0 = Clock::now();
    run(steps);
    best = std::min(best, std::chrono::duration<double, std::nano>(Clock::now() - t0).count() / steps);
  }
  return best;
}

// The preset each block is made from, from BLOCK=PRESET arguments.
std::map<std::string, std::string> g_presets;

ParamSet preset_for(const std::string& block) {
  const auto it = g_presets.find(block);
  if (it == g_presets.end()) {
    std::fprintf(stderr, "rangesim-kernel-step-bench: no preset for block %s: give %s=PRESET\n", block.c_str(),
                 block.c_str());
    std::exit(2);
  }
  return load_preset(it->second);
}

}  // namespace

int main(int argc, char** argv) {
  const long long steps = argc > 1 ? std::atoll(argv[1]) : 0;
  if (steps < 1) {
    std::fprintf(stderr, "usage: rangesim-kernel-step-bench STEPS BLOCK=PRESET ... (STEPS >= 1)\n");
    return 2;
  }
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::fprintf(stderr, "rangesim-kernel-step-bench: %s: allowed BLOCK=PRESET\n", a.c_str());
      return 2;
    }
    g_presets[a.substr(0, eq)] = a.substr(eq + 1);
  }
  std::vector<std::pair<std::string, double>> out;

  // address_search.tick: operations back to back on one row (start again as soon as idle).
  const LsConventionalConfig lc = ls_conventional_from_params(preset_for("address_search"));
  systemc::ActivationRow row(lc.search.columns);
  row.set(40), row.set(48);
  out.emplace_back("address_search.tick", time_steps(steps, [&](long long n) {
                     systemc::AddressSearchKernel k(lc.search, lc.timing.search_cycles);
                     for (long long i = 0; i < n; ++i) {
                       k.tick(false, k.idle(), row);
                       g_sink += k.pins().addr_bit;
                     }
                   }));
  const LsConventionalConfig sc = ls_conventional_from_params(preset_for("multisampling_sequencer"));
  out.emplace_back("multisampling_sequencer.tick", time_steps(steps, [&](long long n) {
                     systemc::MultisamplingSequencerKernel k(sc.timing, sc.multisampling.samplings);
                     for (long long i = 0; i < n; ++i) {
                       k.tick(false);
                       g_sink += k.pins().sampling;
                     }
                   }));

  const TofLockinConfig tl = tof_lockin_from_params(preset_for("lockin_gate_generator"));
  out.emplace_back("lockin_gate_generator.advance", time_steps(steps, [&](long long n) {
                     systemc::lockin::LockinGateGeneratorKernel g(tl);
                     g.start();
                     for (long long i = 0; i < n; ++i) {
                       if (g.done()) g.start();
                       g_sink += g.advance(1) + g.tx1();
                     }
                   }));
  const systemc::lockin::ColumnAdcKernel adc(tof_lockin_from_params(preset_for("column_adc")));
  out.emplace_back("column_adc.code", time_steps(steps, [&](long long n) {
                     for (long long i = 0; i < n; ++i)
                       g_sink += static_cast<std::uint64_t>(adc.code(static_cast<double>(i & 1023) * 1e-3));
                   }));

  // tdc.hit: one hit per laser cycle, cycling through the bins; a new integration when the
  // laser cycles run out.
  const TofSpadConfig ts = tof_spad_from_params(preset_for("tdc"));
  const systemc::spad::TofSpadKernel sk(ts, 1, ts.tdc.columns_per_tdc, systemc::spad::TofSpadKernelOptions{});
  const auto make_tdc = [&] {
    return systemc::spad::TdcGroupKernel(sk.phase_bins(), sk.codes(), sk.block_event_bins(), sk.block_overflow_bins(),
                                         sk.laser_cycles(), ts.tdc.columns_per_tdc);
  };
  out.emplace_back("tdc.hit", time_steps(steps, [&](long long n) {
                     auto tdc = make_tdc();
                     long long cycle = 0;
                     for (long long i = 0; i < n; ++i) {
                       if (cycle == sk.laser_cycles()) tdc = make_tdc(), cycle = 0;
                       const auto h = tdc.hit(static_cast<int>(i % ts.tdc.columns_per_tdc), cycle++,
                                              static_cast<int>(i % sk.phase_bins()));
                       g_sink += static_cast<std::uint64_t>(h.code);
                     }
                   }));

  std::string json = "{";
  for (std::size_t i = 0; i < out.size(); ++i)
    json += fmt::format("{}\n  \"{}\": {{\"ns_per_step\": {:.3f}, \"steps\": {}}}", i ? "," : "", out[i].first,
                        out[i].second, steps);
  fmt::print("{}\n}}\n", json);
  std::fprintf(stderr, "(checksum %llu)\n", static_cast<unsigned long long>(g_sink));
  return 0;
}
