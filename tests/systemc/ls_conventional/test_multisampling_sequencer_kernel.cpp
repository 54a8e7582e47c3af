// MultisamplingSequencerKernel: the schedule counted tick by tick equals golden::frame_timing, phase
// by phase and in total, for samplings 1..8 and varied cycle parameters; event skipping
// (next_event_cycle / advance_to) visits exactly the cycles where the ticked pins change.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "golden/ls_conventional/frame_timing.h"
#include "systemc/ls_conventional/multisampling_sequencer_kernel.h"

namespace rs = rangesim::systemc;
using rangesim::FrameTimingConfig;

namespace {

std::vector<FrameTimingConfig> timing_variants() {
  std::vector<FrameTimingConfig> v;
  v.push_back(FrameTimingConfig{});  // the preset: 4 / 1 / 2 / 9 x 2 / 12
  FrameTimingConfig t;
  t.reset_cycles = 1;
  t.latch_cycles = 3;
  t.search_cycles = 1;
  t.address_bits = 4;
  t.output_cycles = 1;
  v.push_back(t);
  t = FrameTimingConfig{};
  t.reset_cycles = 7;
  t.latch_cycles = 2;
  t.search_cycles = 5;
  t.address_bits = 11;
  t.output_cycles = 30;
  v.push_back(t);
  return v;
}

}  // namespace

TEST(MultisamplingSequencerKernel, TickedScheduleEqualsGoldenFrameTiming) {
  for (const FrameTimingConfig& t : timing_variants()) {
    for (int N = 1; N <= 8; ++N) {
      rs::MultisamplingSequencerKernel k(t, N);
      k.tick(true);
      const rangesim::golden::FrameTiming g = rangesim::golden::frame_timing(t, N);
      ASSERT_EQ(k.frame_cycles(), g.frame_cycles);
      for (int frame = 0; frame < 3; ++frame) {
        std::array<long long, rs::kReadoutPhases> counted{};
        long long cycles = 0, latches = 0, starts = 0, done = 0;
        int last_sampling = 0;
        for (;;) {
          const rs::MultisamplingSequencerPins p = k.pins();
          ASSERT_EQ(p.frame, static_cast<std::uint64_t>(frame));
          ++counted[static_cast<std::size_t>(p.phase)];
          ++cycles;
          latches += p.latch;
          starts += p.search_start;
          if (p.sampling != 0 && p.sampling != last_sampling) {
            EXPECT_EQ(p.sampling, last_sampling + 1);  // samplings in order, each once
            last_sampling = p.sampling;
          }
          k.tick(false);
          if (p.frame_done) {
            ++done;
            break;
          }
          ASSERT_LT(cycles, 10 * g.frame_cycles) << "frame_done never came";
        }
        EXPECT_EQ(cycles, g.frame_cycles) << "N = " << N;
        EXPECT_EQ(done, 1);
        EXPECT_EQ(starts, N);
        EXPECT_EQ(latches, static_cast<long long>(N) * t.latch_cycles);
        EXPECT_EQ(last_sampling, N);
        for (const auto& phase : g.phases) {
          bool found = false;
          for (int i = 0; i < rs::kReadoutPhases; ++i) {
            if (phase.name != rs::readout_phase_name(static_cast<rs::ReadoutPhase>(i))) continue;
            EXPECT_EQ(counted[static_cast<std::size_t>(i)], phase.cycles) << phase.name << ", N = " << N;
            found = true;
          }
          EXPECT_TRUE(found) << phase.name;
        }
      }
    }
  }
}

TEST(MultisamplingSequencerKernel, EventSkippingVisitsExactlyThePinChanges) {
  for (const FrameTimingConfig& t : timing_variants()) {
    for (int N : {1, 3, 8}) {
      rs::MultisamplingSequencerKernel ticked(t, N), skipped(t, N);
      ticked.tick(true);
      skipped.tick(true);
      const long long end = 3 * ticked.frame_cycles();
      rs::MultisamplingSequencerPins prev = ticked.pins();
      while (skipped.cycle() < end) {
        const long long next = skipped.next_event_cycle();
        ASSERT_GT(next, skipped.cycle());
        // Every cycle strictly between is identical to the interval's first cycle.
        while (ticked.cycle() + 1 < next) {
          ticked.tick(false);
          ASSERT_EQ(ticked.pins(), prev) << "pins changed at cycle " << ticked.cycle() << " without an event";
        }
        ticked.tick(false);
        skipped.advance_to(next);
        ASSERT_EQ(ticked.cycle(), skipped.cycle());
        ASSERT_EQ(ticked.pins(), skipped.pins());
        ASSERT_EQ(skipped.pins(), skipped.pins_at(skipped.cycle()));
        prev = ticked.pins();
      }
    }
  }
}

TEST(MultisamplingSequencerKernel, JumpsBetweenEventsKeepTheEventCursor) {
  // advance_to a cycle that is not the next event (a jump to a frame access, or anywhere), then on
  // by events: the pins are pins_at's at every stop, across frame accesses and after ticks.
  for (const FrameTimingConfig& t : timing_variants()) {
    for (int N : {1, 4}) {
      rs::MultisamplingSequencerKernel k(t, N);
      k.tick(true);
      const long long F = k.frame_cycles();
      for (long long jump : {F / 3, 2 * F + 1, 5 * F, 5 * F + F - 1, 7 * F + 2}) {
        if (jump <= k.cycle()) continue;
        k.advance_to(jump);
        ASSERT_EQ(k.pins(), k.pins_at(jump)) << "jump to " << jump;
        for (int e = 0; e < 3 * static_cast<int>(F); ++e) {
          const long long next = k.next_event_cycle();
          ASSERT_GT(next, k.cycle());
          k.advance_to(next);
          ASSERT_EQ(k.pins(), k.pins_at(next)) << "event at " << next << " after a jump to " << jump;
          if (next > jump + 2 * F) break;
        }
        k.tick(false);
        ASSERT_EQ(k.pins(), k.pins_at(k.cycle()));
      }
    }
  }
}

TEST(MultisamplingSequencerKernel, ResetHoldsCycleZeroAndRejectsBadSchedules) {
  rs::MultisamplingSequencerKernel k(FrameTimingConfig{}, 4);
  k.tick(false);
  k.tick(false);
  k.tick(true);
  k.tick(true);
  EXPECT_EQ(k.cycle(), 0);
  EXPECT_TRUE(k.pins().pix_reset);
  EXPECT_EQ(k.pins().frame, 0U);
  FrameTimingConfig bad;
  bad.latch_cycles = 0;
  EXPECT_THROW(rs::MultisamplingSequencerKernel(bad, 4), std::invalid_argument);
  EXPECT_THROW(rs::MultisamplingSequencerKernel(FrameTimingConfig{}, 0), std::invalid_argument);
}
