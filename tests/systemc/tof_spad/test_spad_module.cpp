// The sc_module around the kernel: same frames, histograms, word stream and cycle counts as the
// bare kernel; measured time == golden frame timing; bounded run with zero SC_ERRORs.
#include <gtest/gtest.h>

#include <systemc>

#include "golden/common/evaluate_sensor.h"
#include "spad_clock_helpers.h"
#include "systemc/tof_spad/sensor.h"
#include "golden/tof_spad/model.h"

namespace rangesim::systemc::spad {
namespace {

TEST(SpadModule, OutputsIdenticalToKernelAndTimingExact) {
  const ParamSet p = test::small_preset(2e-4, 3);
  const TofSpadConfig cfg = tof_spad_from_params(p);
  const TofSpadKernel k(cfg, 3, static_cast<int>(p.integer("array.columns")), {});
  const PixelSelection sel{{0, 2}, 5, 2};
  const RateSource rates = [](int row, int col) {
    return PixelRates{2e6 + 1e5 * col, 5e5, (10 + row + 0.3 * col) * 1e-9};
  };
  const SystemcRun kr = run_tof_spad_kernel(k, sel, rates, 2);
  const SystemcRun sr = run_tof_spad_systemc(k, sel, rates, 2);
  EXPECT_EQ(sr.sc_errors, 0);
  ASSERT_EQ(sr.frames.size(), kr.frames.size());
  const golden::FrameTiming gt = golden::frame_timing_tof_spad(p);
  for (size_t f = 0; f < kr.frames.size(); ++f) {
    const FrameResult &a = kr.frames[f], &b = sr.frames[f];
    EXPECT_EQ(a.cycles, b.cycles);
    EXPECT_EQ(b.cycles, gt.frame_cycles);
    EXPECT_EQ(a.phase_cycles, b.phase_cycles);
    EXPECT_EQ(b.phase_cycles[0], gt.phases[0].cycles);
    EXPECT_EQ(b.phase_cycles[1], gt.phases[1].cycles);
    EXPECT_EQ(a.avalanches, b.avalanches);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    ASSERT_EQ(a.pixels.size(), 2u * 2u * 4u);
    for (size_t i = 0; i < a.pixels.size(); ++i) {
      EXPECT_EQ(a.pixels[i].row, b.pixels[i].row);
      EXPECT_EQ(a.pixels[i].column, b.pixels[i].column);
      EXPECT_EQ(a.pixels[i].events, b.pixels[i].events);
      EXPECT_EQ(a.pixels[i].armed, b.pixels[i].armed);
      ASSERT_EQ(a.pixels[i].time_s.has_value(), b.pixels[i].time_s.has_value());
      if (a.pixels[i].time_s) {
        EXPECT_EQ(*a.pixels[i].time_s, *b.pixels[i].time_s);
      }
    }
  }
  EXPECT_EQ(kr.words, sr.words);
  EXPECT_EQ(kr.measured_cycles, sr.measured_cycles);
  EXPECT_EQ(sr.measured_cycles, 2 * gt.frame_cycles);
  // Frames differ (frame is part of the stream key).
  EXPECT_NE(kr.frames[0].pixels[0].events, kr.frames[1].pixels[0].events);
  EXPECT_EQ(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR), 0);
}

// Negative test of the comparison: a fault injected into the kernel side (another noise key, or
// a TDC with one more busy bin) is seen in the histograms / word stream.
TEST(SpadModule, ComparisonDetectsInjectedFault) {
  const ParamSet p = test::small_preset(2e-4, 2);
  TofSpadConfig cfg = tof_spad_from_params(p);
  const TofSpadKernel good(cfg, 2, 8, {});
  TofSpadKernelOptions other_seed;
  other_seed.seed = 2;
  const TofSpadKernel reseeded(cfg, 2, 8, other_seed);
  cfg.tdc.busy_time_s += cfg.tdc.lsb_s;
  const TofSpadKernel slower_tdc(cfg, 2, 8, {});
  const PixelSelection sel{{1}, 0, 2};
  const RateSource rates = test::flat(3e6, 3e6, 12e-9);
  const SystemcRun sr = run_tof_spad_systemc(good, sel, rates, 1);
  EXPECT_EQ(sr.sc_errors, 0);
  EXPECT_EQ(run_tof_spad_kernel(good, sel, rates, 1).words, sr.words);
  EXPECT_NE(run_tof_spad_kernel(reseeded, sel, rates, 1).words, sr.words);
  EXPECT_NE(run_tof_spad_kernel(slower_tdc, sel, rates, 1).words, sr.words);
}

}  // namespace
}  // namespace rangesim::systemc::spad
