// tof-spad: the per-clock TDC path (TofSpadKernelOptions::event_skipping = false,
// simulate_group_ticked) gives the same histograms, armed counts, overflows, busy losses and
// avalanche counts as the event-driven path, bit for bit, over light levels from sparse hits to
// heavy pile-up (the TDC mostly busy), with every noise source on and off.
#include <gtest/gtest.h>

#include "../systemc/tof_spad/spad_clock_helpers.h"

namespace rangesim::systemc::spad {
namespace {

TEST(SpadTick, PerClockTdcEqualsEventDriven) {
  const TofSpadConfig cfg = tof_spad_from_params(test::small_preset(20e-6, 4));  // 800 laser cycles
  struct Light {
    double signal_Hz, background_Hz, distance_m;
  };
  const Light lights[] = {{2e4, 1e5, 2.0}, {5e6, 2e6, 1.0}, {1e8, 5e7, 3.0}, {0, 3e7, 1.5}, {3e7, 0, 0.4}};
  long long compared_events = 0, compared_lost = 0;
  for (bool noise : {true, false})
    for (const Light& l : lights)
      for (std::uint64_t seed : {1ULL, 7ULL}) {
        TofSpadKernelOptions ev, tk;
        ev.seed = tk.seed = seed;
        if (!noise) ev.noise = tk.noise = SpadNoise::none();
        tk.event_skipping = false;
        const TofSpadKernel a(cfg, 4, 8, ev), b(cfg, 4, 8, tk);
        const RateSource rates = test::flat(l.signal_Hz, l.background_Hz, 2 * l.distance_m / 299792458.0);
        for (int group = 0; group < 2; ++group) {
          SCOPED_TRACE(::testing::Message() << "signal " << l.signal_Hz << " bg " << l.background_Hz << " seed " << seed
                                            << " noise " << noise << " group " << group);
          const GroupHistogram ga = a.simulate_group(3, 1, group, rates);
          const GroupHistogram gb = b.simulate_group(3, 1, group, rates);
          test::expect_same_histogram(ga, gb);
          for (const auto& e : ga.events)
            for (long long n : e) compared_events += n;
          compared_lost += ga.lost_busy;
        }
      }
  // The cases really exercise hits and a busy TDC.
  EXPECT_GT(compared_events, 1000);
  EXPECT_GT(compared_lost, 100);
}

TEST(SpadTick, WholeFrameEqualsEventDriven) {
  const TofSpadConfig cfg = tof_spad_from_params(test::small_preset(10e-6, 2));
  TofSpadKernelOptions tk;
  tk.event_skipping = false;
  const TofSpadKernel a(cfg, 2, 8, TofSpadKernelOptions{}), b(cfg, 2, 8, tk);
  PixelSelection sel;
  sel.rows = {0, 1};
  sel.first_group = 0, sel.groups = 2;
  const RateSource rates = test::flat(2e7, 1e7, 2 * 2.0 / 299792458.0);
  const FrameResult fa = a.run_frame(0, sel, rates), fb = b.run_frame(0, sel, rates);
  EXPECT_EQ(fa.cycles, fb.cycles);
  EXPECT_EQ(fa.phase_cycles, fb.phase_cycles);
  ASSERT_EQ(fa.pixels.size(), fb.pixels.size());
  for (std::size_t i = 0; i < fa.pixels.size(); ++i) {
    EXPECT_EQ(fa.pixels[i].events, fb.pixels[i].events);
    EXPECT_EQ(fa.pixels[i].time_s.has_value(), fb.pixels[i].time_s.has_value());
    if (fa.pixels[i].time_s && fb.pixels[i].time_s) EXPECT_EQ(*fa.pixels[i].time_s, *fb.pixels[i].time_s);
  }
}

}  // namespace
}  // namespace rangesim::systemc::spad
