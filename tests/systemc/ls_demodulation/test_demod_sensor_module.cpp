// The sc_module around the ls-demodulation sensor kernel: outputs identical to the bare kernel,
// simulated time == schedule, bounded run, zero SC_ERRORs. One elaboration per process.
#include <gtest/gtest.h>

#include <systemc>

#include "systemc/ls_demodulation/sensor.h"
#include "tests/systemc/ls_demodulation/demod_test_helpers.h"

namespace rangesim::systemc {
namespace {

// Module against the bare kernel in the same mode (ticking: every clock edge; event skipping:
// the method sleeps to the kernel's next edge): identical to the bit, same simulated time.
class DemodSensorModule : public ::testing::TestWithParam<bool> {};

TEST_P(DemodSensorModule, OutputsEqualBareKernelWithZeroErrors) {
  auto c = test::small_config(4, 24);
  c.grid.detections = 2;
  DemodKernelOptions o;
  o.seed = 3;
  o.keep_analogue = true;
  o.event_skipping = GetParam();
  const auto src = test::spot_source(c, 5e-11, 1e-9, 9.0, 0.3, 1.1);
  const long long frames = 3;
  const auto sc = run_demod_systemc(c, o, src, frames);
  EXPECT_EQ(sc.sc_errors, 0);
  EXPECT_EQ(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR), 0u);
  const auto kt = run_demod_kernel(c, o, src, frames);
  ASSERT_EQ(sc.frames.size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(sc.cycles, kt.cycles);
  EXPECT_DOUBLE_EQ(sc.simulated_time_s, kt.simulated_time_s);
  // Measured from sc_time: exactly frames x schedule (a skipped or doubled edge shows here).
  EXPECT_EQ(sc.cycles, frames * DemodSensorKernel(c, o).frame_cycles());
  EXPECT_NEAR(sc.simulated_time_s, static_cast<double>(sc.cycles) / c.readout.clock_Hz, 1e-12);
  for (std::size_t f = 0; f < sc.frames.size(); ++f) {
    EXPECT_EQ(sc.frames[f].cycles, kt.frames[f].cycles);
    EXPECT_EQ(sc.frames[f].end_cycle, kt.frames[f].end_cycle);
    EXPECT_EQ(sc.frames[f].phase_cycles, kt.frames[f].phase_cycles);
    EXPECT_EQ(sc.frames[f].rows, kt.frames[f].rows);
    EXPECT_EQ(sc.frames[f].activations, kt.frames[f].activations);
    EXPECT_EQ(sc.frames[f].diff_V, kt.frames[f].diff_V);  // same ticks, same arithmetic
  }
}

INSTANTIATE_TEST_SUITE_P(Harness, DemodSensorModule, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "EventSkipping" : "Ticking"; });

}  // namespace
}  // namespace rangesim::systemc
