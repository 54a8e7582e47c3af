// The golden dead-time / TDC-sharing treatment against the event-level kernel: detections per
// laser cycle (all columns of a TDC group) and the armed fraction (mean over the codes of the
// cycles armed at the code's start), at 1 MHz signal from 1 kHz to 1 GHz background, preset dead
// time (50 ns), busy time (100 ns) and 4 columns per TDC. Prints the validation table.
//
// The golden model carries the TDC's blocking exactly (arming-phase chain) but the free-running
// SPADs only through their stationary live fraction 1 / (1 + m tau), a mean-field treatment: the
// SPADs' states when the TDC re-arms are correlated with the hit that stopped it (and a 1 MHz echo
// at a fixed phase every 25 ns with a 50 ns dead time is correlated with itself). Measured
// (2026-11-25, this test): golden gives 2.7-4.6 % fewer detections per cycle from 1 kHz to 100 MHz
// background and 9.6 % fewer at 1 GHz; the armed fraction is 1.1-1.4 % too high up to 100 kHz,
// 3.3 % at 1 MHz, 16-26 % at 10-100 MHz and ~5x at 1 GHz. The 0.5 % an exact (renewal or Markov)
// model must reach is NOT met; the bounds below pin the gap so that a change in either model
// shows up, and tighten to 0.5 % when the exact model replaces the mean field. ~2 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/physics.h"
#include "golden/tof_spad/point_model.h"
#include "spad_clock_helpers.h"

namespace rangesim::systemc::spad {
namespace {

struct Row {
  double background_Hz, det_golden, det_kernel, det_se, armed_golden, armed_kernel;
};

Row measure(const TofSpadConfig& cfg, double signal_Hz, double background_Hz, double distance_m) {
  TofSpadKernelOptions opt;
  opt.seed = test::test_seed();
  opt.noise.afterpulse = false;  // the golden histogram bounds afterpulses, does not model them
  const TofSpadKernel k(cfg, 1, cfg.tdc.columns_per_tdc, opt);
  const golden::spad::SpadModel model(cfg);
  const golden::spad::PileUpHistogram h = model.histogram(signal_Hz, background_Hz, distance_m);
  const GroupHistogram gh =
      k.simulate_group(0, 0, 0, test::flat(signal_Hz, background_Hz, 2 * distance_m / phys::kSpeedOfLight_m_per_s));
  const double cycles = static_cast<double>(k.laser_cycles());
  double events = 0, armed = 0, armed_g = 0;
  for (const auto& ev : gh.events)
    for (long long e : ev) events += static_cast<double>(e);
  for (int i = 0; i < k.codes(); ++i) {
    armed += static_cast<double>(gh.armed[static_cast<std::size_t>(i)]);
    armed_g += h.armed_prob[static_cast<std::size_t>(i)];
  }
  Row r;
  r.background_Hz = background_Hz;
  r.det_golden = h.group_events_per_cycle;
  r.det_kernel = events / cycles;
  r.det_se = std::sqrt(std::max(events, 1.0)) / cycles;  // Poisson-like; the cycles are weakly correlated
  r.armed_golden = armed_g / k.codes();
  r.armed_kernel = armed / (cycles * k.codes());
  return r;
}

TEST(SpadDeadTimeValidation, MeanFieldGapAgainstKernel) {
  TofSpadConfig cfg = tof_spad_from_params(test::preset());
  cfg.histogram.integration_time_s = 10e-3;  // 400 000 laser cycles
  std::printf("| background (counts/s) | detections/cycle golden | kernel (+- 1 se) | diff | armed golden | "
              "armed kernel | diff |\n|---|---|---|---|---|---|---|\n");
  for (double bg : {1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9}) {
    const Row r = measure(cfg, 1e6, bg, 2.5);
    const double dd = r.det_golden / r.det_kernel - 1, da = r.armed_golden / r.armed_kernel - 1;
    std::printf("| %.0e | %.5f | %.5f +- %.5f | %+.2f%% | %.4f | %.4f | %+.2f%% |\n", bg, r.det_golden, r.det_kernel,
                r.det_se, 100 * dd, r.armed_golden, r.armed_kernel, 100 * da);
    SCOPED_TRACE(bg);
    // The mean field undercounts the detections and overstates the armed fraction everywhere.
    EXPECT_LT(dd, -0.015);
    EXPECT_GT(dd, bg < 5e8 ? -0.06 : -0.12);
    EXPECT_GT(da, 0.005);
    EXPECT_LT(da, bg < 5e6 ? 0.05 : bg < 5e8 ? 0.35 : 6.0);
    // Golden's detections follow the kernel's trend (the comparison is between like quantities).
    EXPECT_GT(r.det_kernel, 3 * r.det_se);
  }
}

}  // namespace
}  // namespace rangesim::systemc::spad
