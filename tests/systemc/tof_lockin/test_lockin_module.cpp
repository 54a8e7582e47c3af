// The sc_module around the sensor kernel: outputs identical to the bare kernel,
// simulated time
// == golden frame time, bounded runs ending with zero SC_ERRORs. One
// elaboration per process (gtest_discover_tests runs each TEST in its own
// process).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <systemc>

#include "golden/common/evaluate_sensor.h"
#include "lockin_sc_test_util.h"
#include "systemc/tof_lockin/sensor.h"
#include "golden/tof_lockin/model.h"

namespace rangesim::systemc::lockin {
namespace {

std::vector<LockinPixelStimulus> stimulus() {
  std::vector<LockinPixelStimulus> st;
  for (int i = 0; i < 6; ++i) st.push_back({1e-9, 2e-10, golden::round_trip_delay_s(0.8 + 2.1 * i)});
  return st;
}

void run_and_compare(const LockinSimOptions& opt, const std::string& vcd) {
  const ParamSet params = test::edited_params(
      {{"pixel", "rows", "4"}, {"gates", "accumulations_per_frame", "6"}, {"readout", "adc_conversion_cycles", "500"}});
  const TofLockinConfig cfg = tof_lockin_from_params(params);
  const golden::FrameTiming ft = golden::frame_timing_tof_lockin(params);
  TofLockinSensor* sc = nullptr;
  const LockinScRun r = run_tof_lockin_systemc(sc, cfg, opt, 2, 3, stimulus(), 4, 1.0, vcd);
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(r.sc_errors, 0);
  EXPECT_NEAR(r.end_time_s, 4 * ft.frame_time_s, 2e-12);  // ps resolution
  TofLockinSensorKernel k(cfg, opt, 2, 3, stimulus(), 4);
  k.run();
  const TofLockinSensorKernel& m = sc->kernel();
  for (long long f = 0; f < 4; ++f)
    for (int row = 0; row < 2; ++row)
      for (int c = 0; c < 3; ++c)
        for (int t = 0; t < 2; ++t) {
          EXPECT_EQ(m.code(f, row, c, t), k.code(f, row, c, t));
          EXPECT_EQ(m.adc_input_V(f, row, c, t), k.adc_input_V(f, row, c, t));
        }
  for (long long mp = 0; mp < 2; ++mp)
    for (int c = 0; c < 3; ++c) {
      const double a = m.range_m(mp, 1, c), b = k.range_m(mp, 1, c);
      EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b)));
    }
  for (std::size_t i = 0; i < 4; ++i)
    for (int p = 0; p < kPhaseCount; ++p) {
      EXPECT_EQ(m.frame_records()[i].cycles[p], ft.phases[p].cycles);
      EXPECT_EQ(m.frame_records()[i].cycles[p], k.frame_records()[i].cycles[p]);
    }
}

TEST(LockinModule, IdenticalToKernelEventSkipping) { run_and_compare(LockinSimOptions{true, true, true, 9}, ""); }

TEST(LockinModule, IdenticalToKernelTickingWithTrace) {
  const std::string vcd = ::testing::TempDir() + "lockin_module_trace.vcd";
  run_and_compare(LockinSimOptions{true, false, false, 9}, vcd);
  std::ifstream f(vcd);
  ASSERT_TRUE(f.good());
  std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("tx1"), std::string::npos);
  EXPECT_NE(text.find("$enddefinitions"), std::string::npos);
  std::remove(vcd.c_str());
}

}  // namespace
}  // namespace rangesim::systemc::lockin

namespace rangesim::systemc::lockin {
namespace {
TEST(LockinModule, TimeLimitIsReportedAsAnError) {
  // Negative test of the bound: a limit shorter than one frame ends the run
  // with one SC_ERROR.
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "2"}});
  TofLockinSensor* sc = nullptr;
  const LockinScRun r = run_tof_lockin_systemc(sc, cfg, LockinSimOptions{false, true, true, 1}, 1, 1,
                                               test::uniform(1, 1e-9, 0, 2.0), 2, 10e-6);
  EXPECT_FALSE(r.finished);
  EXPECT_EQ(r.sc_errors, 1);
}
}  // namespace
}  // namespace rangesim::systemc::lockin
