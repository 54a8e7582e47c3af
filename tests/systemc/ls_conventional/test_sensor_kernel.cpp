// The composed ls-conventional sensor kernel (plain C++, no elaboration): cycle counts equal
// golden::frame_timing frame by frame, event skipping and sparse pixels change nothing, the
// noise-free centre equals the golden noise-free estimate exactly, and with noise the centre's
// mean and variance over many frames agree with golden::position_moments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "golden/ls_conventional/frame_timing.h"
#include "golden/ls_conventional/multisampling.h"
#include "golden/common/position_noise.h"
#include "golden/common/row_model.h"
#include "tests/systemc/sensor_test_helpers.h"
#include "systemc/ls_conventional/centre_processor_kernel.h"
#include "systemc/ls_conventional/sensor.h"
#include "systemc/ls_conventional/sensor_kernel.h"

namespace rs = rangesim::systemc;
namespace golden = rangesim::golden;
using rangesim::FrameTimingConfig;
using rangesim::LsConventionalConfig;
using rs::test::near_threshold;
using rs::test::RandomStimulus;
using rs::test::small_config;

namespace {

rs::SensorKernelOptions options(bool skip, bool noise = true, bool sparse = true, std::uint64_t seed = 3) {
  rs::SensorKernelOptions o;
  o.event_skipping = skip;
  o.pixel.noise = noise ? rs::PixelNoiseConfig{} : rs::PixelNoiseConfig::none();
  o.pixel.sparse = sparse;
  o.pixel.seed = seed;
  return o;
}

std::vector<rs::FrameResult> run(const LsConventionalConfig& c, const rs::SensorKernelOptions& o, int frames,
                                 rs::StimulusSource src, std::vector<std::string>* errors = nullptr) {
  rs::LsConventionalSensorKernel k(c, o, std::move(src));
  k.reset();
  auto r = k.run_frames(frames);
  if (errors) *errors = k.errors();
  return r;
}

// Configs with the given timing; columns chosen to fit the address width.
LsConventionalConfig with_timing(const FrameTimingConfig& t, int samplings) {
  const int columns = std::min(96, 1 << t.address_bits);
  LsConventionalConfig c = small_config(6, columns, samplings);
  c.timing = t;
  c.search.address_bits = t.address_bits;
  return c;
}

std::vector<FrameTimingConfig> timing_variants() {
  std::vector<FrameTimingConfig> v{FrameTimingConfig{}};
  FrameTimingConfig t;
  t.reset_cycles = 1;
  t.latch_cycles = 3;
  t.search_cycles = 1;
  t.address_bits = 5;
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

TEST(LsConventionalSensorKernel, MeasuredFrameTimingEqualsGoldenCycleForCycle) {
  for (const FrameTimingConfig& t : timing_variants()) {
    for (int N = 1; N <= 8; ++N) {
      const LsConventionalConfig c = with_timing(t, N);
      const golden::FrameTiming g = golden::frame_timing(c.timing, N);
      for (bool skip : {false, true}) {
        std::vector<std::string> errors;
        RandomStimulus stim;
        stim.columns = c.pixel.columns;
        const auto frames = run(c, options(skip), 3, stim, &errors);
        EXPECT_TRUE(errors.empty()) << errors.front();
        ASSERT_EQ(frames.size(), 3U);
        for (std::size_t f = 0; f < frames.size(); ++f) {
          const rs::FrameResult& fr = frames[f];
          EXPECT_EQ(fr.frame, f);
          EXPECT_EQ(fr.cycles, g.frame_cycles) << "N = " << N << (skip ? " skip" : " tick");
          EXPECT_EQ(fr.end_cycle, static_cast<long long>(f + 1) * g.frame_cycles);
          for (std::size_t i = 0; i < g.phases.size(); ++i) {
            EXPECT_EQ(g.phases[i].name, rs::readout_phase_name(static_cast<rs::ReadoutPhase>(i)));
            EXPECT_EQ(fr.phase_cycles[i], g.phases[i].cycles) << g.phases[i].name << ", N = " << N;
          }
        }
      }
    }
  }
}

TEST(LsConventionalSensorKernel, TickingEveryCycleCountsEveryCycle) {
  const LsConventionalConfig c = small_config();
  rs::LsConventionalSensorKernel k(c, options(false), RandomStimulus{});
  k.reset();
  k.run_frames(2);
  EXPECT_EQ(k.ticks(), k.cycle());
  EXPECT_EQ(k.cycle(), 2 * golden::frame_timing(c.timing, 4).frame_cycles);
  rs::LsConventionalSensorKernel s(c, options(true), RandomStimulus{});
  s.reset();
  s.run_frames(2);
  EXPECT_EQ(s.ticks(), 0);  // nothing ticked: every cycle skipped or evaluated in closed form
  EXPECT_EQ(s.cycle(), k.cycle());
}

TEST(LsConventionalSensorKernel, EventSkippingEqualsTicking) {
  for (int N : {1, 2, 4, 7}) {
    for (bool noise : {false, true}) {
      const LsConventionalConfig c = small_config(20, 96, N);
      const auto ticked = run(c, options(false, noise), 6, RandomStimulus{});
      const auto skipped = run(c, options(true, noise), 6, RandomStimulus{});
      ASSERT_EQ(ticked.size(), skipped.size());
      int detected = 0;
      for (std::size_t f = 0; f < ticked.size(); ++f) {
        EXPECT_TRUE(ticked[f] == skipped[f]) << "frame " << f << ", N = " << N;
        detected += ticked[f].rows_detected();
      }
      EXPECT_GT(detected, 0);
    }
  }
}

TEST(LsConventionalSensorKernel, EventSkippingEqualsTickingWithTheSpotOnTheEdgeColumns) {
  // The spot centred on column 0 or the last column, strong or near the threshold: activation
  // extents that start at column 0 (found with left = 0) or end at the last, which the skipping
  // kernel's centre processors take from the extents of every sampling at the frame's end.
  const LsConventionalConfig c = small_config(16, 96, 4);
  for (const double signal_V : {0.6, 0.02}) {
    for (const bool noise : {false, true}) {
      const rs::StimulusSource edges = [signal_V](std::uint64_t, rs::FrameStimulus& out) {
        for (std::size_t r = 0; r < out.rows.size(); ++r) {
          out.rows[r].signal_V = signal_V;
          out.rows[r].background_V = 0.01;
          out.rows[r].centre_px = r % 2 ? 0.0 : 95.0;
        }
      };
      const auto ticked = run(c, options(false, noise), 4, edges);
      const auto skipped = run(c, options(true, noise), 4, edges);
      ASSERT_EQ(ticked.size(), skipped.size());
      int at_zero = 0;
      for (std::size_t f = 0; f < ticked.size(); ++f) {
        EXPECT_TRUE(ticked[f] == skipped[f]) << "frame " << f << ", signal " << signal_V << ", noise " << noise;
        for (const auto& e : skipped[f].extents) at_zero += e.first == 0 ? 1 : 0;
      }
      if (signal_V > 0.1) {
        EXPECT_GT(at_zero, 0);  // the case this test is for happened
      }
    }
  }
}

TEST(LsConventionalSensorKernel, SparsePixelsEqualDensePixels) {
  const LsConventionalConfig c = small_config(30, 96, 4);
  for (bool noise : {false, true}) {
    RandomStimulus stim;
    stim.bg_hi = 0.2;  // some rows where the background alone comes close to the threshold
    const auto dense = run(c, options(true, noise, false), 5, stim);
    const auto sparse = run(c, options(true, noise, true), 5, stim);
    for (std::size_t f = 0; f < dense.size(); ++f) EXPECT_TRUE(dense[f] == sparse[f]) << "frame " << f;
  }
}

TEST(LsConventionalSensorKernel, SameSeedSameBitsOtherSeedOtherBits) {
  const LsConventionalConfig c = small_config(40, 96, 4);
  const RandomStimulus stim = near_threshold(0.02);
  const auto a = run(c, options(true, true, true, 11), 3, stim);
  const auto b = run(c, options(true, true, true, 11), 3, stim);
  const auto d = run(c, options(true, true, true, 12), 3, stim);
  bool differs = false;
  for (std::size_t f = 0; f < a.size(); ++f) {
    EXPECT_TRUE(a[f] == b[f]);
    differs = differs || !(a[f] == d[f]);
  }
  EXPECT_TRUE(differs);
}

TEST(LsConventionalSensorKernel, NoiseFreeCentreEqualsGoldenEstimateExactly) {
  // The full preset array, samplings 1..8, random positions and levels on every row.
  int compared = 0, detected = 0;
  for (int N = 1; N <= 8; ++N) {
    LsConventionalConfig c;  // preset defaults: 375 x 365
    c.multisampling.samplings = N;
    RandomStimulus stim;
    stim.columns = c.pixel.columns;
    stim.sig_lo = 0.002;  // below and above the 0.01 V threshold
    stim.bg_hi = 0.2;
    const auto frames = run(c, options(true, false), 2, stim);
    for (const rs::FrameResult& fr : frames) {
      rs::FrameStimulus s;
      s.rows.resize(static_cast<std::size_t>(c.pixel.rows));
      stim(fr.frame, s);
      for (std::size_t r = 0; r < s.rows.size(); ++r) {
        const rs::RowIllumination& in = s.rows[r];
        const golden::RowModel row = golden::make_row_model(c, in.signal_V, in.background_V);
        const golden::CentreEstimate e = golden::noise_free_estimate(row, in.centre_px);
        const rs::CentreProcessorPins& p = fr.rows[r];
        ++compared;
        ASSERT_EQ(p.valid, e.detected) << "N " << N << " row " << r << " sig " << in.signal_V << " bg "
                                       << in.background_V << " x0 " << in.centre_px;
        if (!e.detected) continue;
        ++detected;
        ASSERT_EQ(p.exact_centre_px(), e.centre_px) << "N " << N << " row " << r;
        ASSERT_LE(std::fabs(p.centre_px() - e.centre_px), 0.5 / (1 << rs::kCentreFractionBits) + 1e-12);
      }
    }
  }
  EXPECT_EQ(compared, 8 * 2 * 365);
  EXPECT_GT(detected, compared / 2);
  EXPECT_LT(detected, compared);
}

namespace {

struct Moments {
  double n = 0, detected = 0, mean = 0, var = 0, m4 = 0;
};

Moments simulate_moments(const LsConventionalConfig& c, const rs::RowIllumination& in, int frames, std::uint64_t seed) {
  rs::test::UniformStimulus stim{in};
  const auto results = run(c, options(true, true, true, seed), frames, stim);
  std::vector<double> xs;
  Moments m;
  for (const auto& fr : results)
    for (const auto& p : fr.rows) {
      ++m.n;
      if (p.valid) xs.push_back(p.exact_centre_px());
    }
  m.detected = static_cast<double>(xs.size());
  for (double x : xs) m.mean += x / m.detected;
  for (double x : xs) {
    const double d = x - m.mean;
    m.var += d * d / (m.detected - 1);
    m.m4 += d * d * d * d / m.detected;
  }
  return m;
}

}  // namespace

TEST(LsConventionalSensorKernel, NoisyCentreMomentsAgreeWithGoldenPositionMoments) {
  // 250 rows x 40 frames = 10,000 independent frames per operating point (streams keyed by
  // frame and row). Bounds are 5 standard errors (two-sided p ~ 6e-7 per check).
  const LsConventionalConfig c = small_config(250, 96, 4);
  struct Point {
    double sig, bg, x0;
  };
  for (const Point pt :
       {Point{0.03, 0.002, 47.3}, Point{0.0125, 0.001, 40.81}, Point{0.2, 0.02, 50.5}, Point{0.011, 0.0005, 44.07}}) {
    const golden::RowModel row = golden::make_row_model(c, pt.sig, pt.bg);
    const golden::PositionMoments g = golden::position_moments(row, pt.x0);
    const Moments m = simulate_moments(c, {pt.sig, pt.bg, pt.x0}, 40, 21);
    SCOPED_TRACE("sig " + std::to_string(pt.sig) + " bg " + std::to_string(pt.bg) + " x0 " + std::to_string(pt.x0));
    const double p_hat = m.detected / m.n;
    EXPECT_NEAR(p_hat, g.p_detect, 5 * std::sqrt(g.p_detect * (1 - g.p_detect) / m.n) + 1e-12);
    ASSERT_GT(m.detected, 100);
    EXPECT_NEAR(m.mean, g.mean_px, 5 * std::sqrt(g.var_px2 / m.detected) + 1e-9);
    const double var_se = std::sqrt(std::max(0.0, m.m4 - m.var * m.var) / m.detected);
    EXPECT_NEAR(m.var, g.var_px2, 5 * var_se + 1e-9);
    std::printf(
        "  sig %.4g V bg %.4g V x0 %.2f: p_detect %.5f (golden %.5f), mean %.5f (golden %.5f), "
        "var %.5f +- %.5f (golden %.5f)\n",
        pt.sig, pt.bg, pt.x0, p_hat, g.p_detect, m.mean, g.mean_px, m.var, var_se, g.var_px2);
  }
}

TEST(LsConventionalSensorKernel, CycleBudgetIsEnforced) {
  rs::LsConventionalSensorKernel k(small_config(), options(true), RandomStimulus{});
  k.reset();
  EXPECT_THROW(k.run_frames(3, 50), std::runtime_error);
  rs::SensorRunOptions run;
  run.frames = 2;
  run.cycle_budget = 150;  // less than two frame accesses of 100 cycles
  EXPECT_THROW(rs::run_sensor_kernel(small_config(), options(true), RandomStimulus{}, run), std::runtime_error);
}

TEST(LsConventionalSensorKernel, FrameExtentsOffLeavesThePinsAlone) {
  // SensorKernelOptions::frame_extents off (simulate's range map): the same frames (pins, cycles),
  // no extents; on: one extent per row. Event skipping and ticking, one thread and two.
  const LsConventionalConfig c = small_config(23, 96, 4);
  const RandomStimulus stim = near_threshold();
  for (const bool skip : {true, false}) {
    for (const int threads : {1, 2}) {
      rs::SensorRunOptions run;
      run.frames = 12;
      run.threads = threads;
      rs::SensorKernelOptions with = options(skip, true), without = options(skip, true);
      without.frame_extents = false;
      const auto a = rs::run_sensor_kernel(c, with, stim, run);
      const auto b = rs::run_sensor_kernel(c, without, stim, run);
      ASSERT_EQ(a.frames.size(), b.frames.size());
      for (std::size_t f = 0; f < a.frames.size(); ++f) {
        EXPECT_TRUE(a.frames[f] == b.frames[f]) << f;
        EXPECT_EQ(a.frames[f].extents.size(), static_cast<std::size_t>(c.pixel.rows)) << f;
        EXPECT_TRUE(b.frames[f].extents.empty()) << f;
      }
    }
  }
}

TEST(LsConventionalSensorKernel, RowBandsOnThreadsEqualOneThread) {
  // run_sensor_kernel splits the rows into bands, one thread each: the keyed streams make every
  // row's bits the same in any band, so the merged frames (their activation extents too) equal the
  // one-thread run's.
  const LsConventionalConfig c = small_config(23, 96, 4);
  const RandomStimulus stim = near_threshold();
  for (const bool noise : {true, false}) {
    rs::SensorRunOptions run;
    run.frames = 20;
    run.split = rs::SensorRunOptions::Split::RowBands;
    const auto one = rs::run_sensor_kernel(c, options(true, noise), stim, run);
    ASSERT_EQ(one.thread_cpu_s.size(), 1u);
    for (const int threads : {2, 3}) {
      run.threads = threads;
      const auto many = rs::run_sensor_kernel(c, options(true, noise), stim, run);
      ASSERT_EQ(many.thread_cpu_s.size(), static_cast<std::size_t>(threads));
      ASSERT_EQ(many.frames.size(), one.frames.size());
      for (std::size_t f = 0; f < one.frames.size(); ++f) {
        EXPECT_TRUE(one.frames[f] == many.frames[f]) << f;
        EXPECT_TRUE(one.frames[f].extents == many.frames[f].extents) << f;  // every band's rows joined
      }
      EXPECT_EQ(many.cycles, one.cycles);
      EXPECT_EQ(many.pixels_simulated, one.pixels_simulated);
      EXPECT_TRUE(many.errors.empty());
    }
  }
}

TEST(LsConventionalSensorKernel, FrameAccessesOnThreadsEqualOneThread) {
  // run_sensor_kernel gives each thread consecutive frame accesses, a later part starting with
  // reset_at_frame: every frame access starts from the same state and its noise is keyed by its
  // number, so the joined frames equal the one-thread run's, ticked or event-skipping, sparse or
  // dense, for frame counts that do not split evenly; the cycles, clock edges and pixels add up.
  const LsConventionalConfig c = small_config(23, 96, 4);
  const RandomStimulus stim = near_threshold();
  for (const bool skip : {true, false})
    for (const bool noise : {true, false})
      for (const bool sparse : {true, false}) {
        rs::SensorRunOptions run;
        run.frames = skip ? 13 : 5;
        const auto one = rs::run_sensor_kernel(c, options(skip, noise, sparse), stim, run);
        for (const int threads : {2, 3}) {
          run.threads = threads;
          run.split = rs::SensorRunOptions::Split::Auto;  // frame accesses: as many as threads or more
          long long last_progress = 0;
          run.progress = [&](long long done) {
            EXPECT_GE(done, last_progress);
            last_progress = done;
          };
          const auto many = rs::run_sensor_kernel(c, options(skip, noise, sparse), stim, run);
          run.progress = nullptr;
          ASSERT_EQ(many.thread_cpu_s.size(), static_cast<std::size_t>(threads));
          ASSERT_EQ(many.frames.size(), one.frames.size());
          for (std::size_t f = 0; f < one.frames.size(); ++f) {
            EXPECT_TRUE(one.frames[f] == many.frames[f]) << f;
            EXPECT_TRUE(one.frames[f].extents == many.frames[f].extents) << f;
          }
          EXPECT_EQ(many.cycles, one.cycles);
          EXPECT_EQ(many.ticks, one.ticks);
          EXPECT_EQ(many.pixels_simulated, one.pixels_simulated);
          EXPECT_EQ(many.errors, one.errors);
          EXPECT_EQ(last_progress, run.frames);
        }
      }
}

// The centre without a division (a reciprocal a count, systemc/ls_conventional/centre_processor_kernel.h)
// equals the integer division floor((sum 2^8 + n) / (2 n)) for every count a sensor can have and
// beyond the table (n > 64): random sums, runs of consecutive ones (every remainder) and the largest.
TEST(CentreProcessorKernel, CentreEqualsIntegerDivisionForEveryCount) {
  std::mt19937_64 rng(11);
  for (int n = 0; n <= 70; ++n) {
    std::vector<std::uint32_t> sums;
    for (std::uint32_t s = 0; s < 300; ++s) sums.insert(sums.end(), {s, 0xFFFFFFFFU - s, 0x80000000U + s});
    for (int i = 0; i < 3000; ++i) sums.push_back(static_cast<std::uint32_t>(rng()));
    for (const std::uint32_t sum : sums) {
      rs::CentreProcessorKernel c(9);
      c.accumulate_total(sum, n);
      const rs::CentreProcessorPins p = c.pins();
      const std::uint64_t num = (std::uint64_t{sum} << 8) + static_cast<std::uint64_t>(n);
      const std::uint32_t want = n == 0 ? 0U : static_cast<std::uint32_t>(num / (2 * static_cast<std::uint64_t>(n)));
      ASSERT_EQ(p.centre_q, want) << "n " << n << " sum " << sum;
      ASSERT_EQ(p.valid, n > 0);
    }
  }
}

TEST(CentreProcessorKernel, BitSerialDecodeEqualsClosedFormAndRoundsToNearest) {
  const rangesim::AddressSearchConfig cfg{96, 7, 2};
  rs::AddressSearchKernel search(cfg, 2);
  rs::CentreProcessorKernel ticked(7), closed(7);
  std::mt19937_64 rng(4);
  for (int frame = 0; frame < 300; ++frame) {
    ticked.tick(true, {});
    closed.clear();
    const int N = 1 + frame % 8;
    for (int k = 0; k < N; ++k) {
      rs::ActivationRow row(96);
      if (rng() % 4 != 0) {
        const int l = static_cast<int>(rng() % 96), r = l + static_cast<int>(rng() % (96 - l));
        row.set(l);
        row.set(r);
      }
      closed.accumulate(search.evaluate(row));
      search.tick(false, true, row);
      for (int cyc = 0; cyc < 2 + 14 + 1; ++cyc) {
        const rs::AddressSearchPins p = search.pins();
        ticked.tick(false, p);
        search.tick(false, false, row);
      }
    }
    ASSERT_EQ(ticked.pins(), closed.pins()) << frame;
  }
  // 7 / (2 * 3) = 1.1667 px -> 298.67 / 256 -> 299; 5 / 4 = 1.25 -> 320 exactly.
  rs::CentreProcessorKernel c(9);
  c.accumulate({true, 3, 4, 0});
  c.accumulate({true, 0, 0, 0});
  c.accumulate({true, 0, 0, 0});
  EXPECT_EQ(c.pins().centre_q, 299U);
  EXPECT_EQ(c.pins().count, 3);
  c.clear();
  EXPECT_FALSE(c.pins().valid);
  c.accumulate({true, 2, 3, 0});
  c.accumulate({false, 0, 0, 0});
  c.accumulate({true, 0, 0, 0});
  EXPECT_EQ(c.pins().centre_q, 320U);
}
