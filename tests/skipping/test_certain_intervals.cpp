// Proof of the certain intervals (systemc/ls_conventional/certain_intervals.h, preset key
// simulation.certain_intervals): a row's certain pixels found as intervals of the distance from the
// spot centre instead of one by one.
//  - the bound: every pixel the intervals call certain gets the same first firing sampling from the
//    per-pixel rule (ExactActivation::certain_first_firing), over 3000 random row drives and pixels
//    placed at random and on every interval edge to within 1e-12 of it;
//  - no bit changes: the plane map's 375 frame accesses and random rows under every noise
//    configuration give identical frame results with the switch off (every window pixel one by one);
//  - the band is narrow: on the plane map the pixels looked at one by one are at most 1.5x those
//    whose outcome is really uncertain (drawn).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "golden/common/quantiser.h"
#include "golden/common/spot.h"
#include "scene/scene.h"
#include "systemc/ls_conventional/certain_intervals.h"
#include "systemc/ls_conventional/scene_optics.h"
#include "systemc/ls_conventional/sensor.h"
#include "tests/skipping/exact_activation_helpers.h"

using namespace exact_test;

namespace {

// Every distance worth testing for one row: random ones and each interval edge nudged both ways.
std::vector<double> probe_distances(const rs::RowCertainty& c, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 12);
  std::vector<double> d;
  for (int i = 0; i < 40; ++i) d.push_back(u(rng));
  for (const auto* v : {&c.fired_within, &c.never_beyond})
    for (double e : *v) {
      if (!(e >= 0) || e == rs::RowCertainty::kAll) continue;
      for (double rel : {-1e-9, -1e-12, 0.0, 1e-12, 1e-9}) d.push_back(e * (1 + rel));
      d.push_back(std::nextafter(e, 0.0));
      d.push_back(std::nextafter(e, 1e9));
    }
  return d;
}

// The frame results of `frames` frame accesses of the plane scene (intervals on or off).
std::vector<rs::FrameResult> plane_run(bool intervals, int frames, long long& examined, long long& drawn) {
  LsConventionalConfig c = preset();
  c.simulation.certain_intervals = intervals;
  const rangesim::scene::SceneOptics optics(
      c, rangesim::scene::load_scene(std::string(RANGESIM_SOURCE_DIR) + "/scenes/plane.toml", "ls-conventional"));
  rs::LsConventionalSensorKernel k(c, rs::SensorKernelOptions{},
                                   [&optics](std::uint64_t f, rs::FrameStimulus& s) { optics.stimulus(f, s); });
  k.reset();
  auto out = k.run_frames(frames);
  examined = k.pixels().pixels_examined();
  drawn = k.pixels().pixels_drawn();
  EXPECT_EQ(k.pixels().certain_intervals(), intervals);
  return out;
}

}  // namespace

TEST(CertainIntervals, CertainPixelsAgreeWithThePerPixelRule) {
  struct Case {
    bool shot, ktc, read;
    int samplings;
  };
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  long long checked = 0, certain = 0;
  for (const Case& k : {Case{true, true, true, 4}, Case{true, false, false, 4}, Case{false, true, true, 4},
                        Case{true, true, true, 8}}) {
    LsConventionalConfig c = preset();
    c.multisampling.samplings = k.samplings;
    rs::ExactActivation ex(model_of(c, k.shot, k.ktc, k.read));
    const double dark_V = rangesim::golden::dark_voltage_V(c.pixel), e = rangesim::golden::electrons_per_volt(c.pixel);
    rs::CertainIntervals ci(c.spot, dark_V, e, k.samplings);
    for (int trial = 0; trial < 750; ++trial) {
      const double S = 1e-3 * std::pow(1500.0, u(rng)), B = 1e-4 * std::pow(3000.0, u(rng));
      const double theta = rangesim::golden::comparator_threshold_V(c, B);
      const rs::ActivationBounds& b = ex.bounds(theta);
      rs::RowCertainty cert;
      ci.compute(S, B, b, cert);
      for (double d : probe_distances(cert, rng)) {
        const int cls = cert.classify(d);
        ++checked;
        if (cls < 0) continue;
        ++certain;
        rs::PixelDrive pd{S, rangesim::golden::spot_profile(c.spot, d), B, dark_V, 0.0};
        pd.mean_step_e = rangesim::golden::pixel_swing_V(S, pd.profile, B, dark_V, 1.0) * e / k.samplings;
        ASSERT_EQ(ex.certain_first_firing(pd, b), cls) << "S " << S << " B " << B << " d " << d;
      }
    }
  }
  EXPECT_GT(certain, checked / 2);
  RecordProperty("distances_checked", std::to_string(checked));
}

TEST(CertainIntervals, PlaneMapBitIdenticalToEveryWindowPixel) {
  long long examined[2], drawn[2];
  const auto off = plane_run(false, 375, examined[0], drawn[0]);
  const auto on = plane_run(true, 375, examined[1], drawn[1]);
  ASSERT_EQ(off.size(), on.size());
  for (std::size_t f = 0; f < off.size(); ++f) ASSERT_EQ(off[f], on[f]) << "frame " << f;
  EXPECT_EQ(drawn[0], drawn[1]);  // the same pixels needed a draw
  EXPECT_LT(examined[1], 1.5 * static_cast<double>(drawn[1]));
  RecordProperty("pixels_examined_with_intervals", std::to_string(examined[1]));
  RecordProperty("pixels_examined_without", std::to_string(examined[0]));
  RecordProperty("pixels_drawn", std::to_string(drawn[1]));
}

TEST(CertainIntervals, RandomRowsBitIdenticalUnderEveryNoiseConfiguration) {
  for (const rs::PixelNoiseConfig noise :
       {rs::PixelNoiseConfig{}, rs::PixelNoiseConfig{true, false, false}, rs::PixelNoiseConfig{false, true, true},
        rs::PixelNoiseConfig{true, true, false}}) {
    for (const bool fixed : {false, true}) {
      std::vector<rs::FrameResult> runs[2];
      for (int on = 0; on < 2; ++on) {
        LsConventionalConfig c = rs::test::small_config(12, 64, 4);
        c.simulation.certain_intervals = on == 1;
        if (fixed) c.comparator.threshold_mode = rangesim::ThresholdMode::Fixed;
        rs::SensorKernelOptions o;
        o.pixel.noise = noise;
        o.pixel.seed = 17;
        rs::test::RandomStimulus stim{5, 0.005, 1.5, 1e-4, 0.2, 64};
        rs::LsConventionalSensorKernel k(c, o, stim);
        k.reset();
        runs[on] = k.run_frames(30);
      }
      ASSERT_EQ(runs[0].size(), runs[1].size());
      for (std::size_t f = 0; f < runs[0].size(); ++f)
        ASSERT_EQ(runs[0][f], runs[1][f]) << "frame " << f << " shot " << noise.shot << " fixed " << fixed;
    }
  }
}

TEST(CertainIntervals, RandomRowsBitIdenticalAtEverySamplingCount) {
  // The inversions with intervals on run per sampling count (2, 4, 8 unrolled, the rest general;
  // pixel_array_exact.cpp) against prepared cuts; without intervals every window pixel is drawn one
  // by one against golden's f (4 samplings: the test above). 25 frames of 12 rows, random drives.
  for (const int samplings : {1, 2, 3, 8, 13}) {
    std::vector<rs::FrameResult> runs[2];
    long long drawn[2] = {0, 0};
    for (int on = 0; on < 2; ++on) {
      LsConventionalConfig c = rs::test::small_config(12, 64, samplings);
      c.simulation.certain_intervals = on == 1;
      rs::SensorKernelOptions o;
      o.pixel.seed = 29;
      // One background: one threshold, so its table is made and the draws meet the prepared cuts
      // (with a threshold per row they would all go to golden's f).
      rs::test::RandomStimulus stim{7, 0.005, 1.5, 0.01, 0.01, 64};
      rs::LsConventionalSensorKernel k(c, o, stim);
      k.reset();
      runs[on] = k.run_frames(25);
      drawn[on] = k.pixels().pixels_drawn();
    }
    ASSERT_EQ(runs[0].size(), runs[1].size());
    EXPECT_EQ(drawn[0], drawn[1]) << "samplings " << samplings;
    EXPECT_GT(drawn[1], 0) << "samplings " << samplings;
    for (std::size_t f = 0; f < runs[0].size(); ++f) {
      ASSERT_EQ(runs[0][f], runs[1][f]) << "frame " << f << " samplings " << samplings;
      ASSERT_EQ(runs[0][f].extents, runs[1][f].extents) << "frame " << f << " samplings " << samplings;
    }
  }
}
