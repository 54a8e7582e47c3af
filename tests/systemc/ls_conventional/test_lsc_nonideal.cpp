// ls-conventional's non-idealities in the pixel array (pixel_array_kernel.h, per-pixel path;
// nonideal_pattern.h): a neutral per-pixel input gives the per-sampling path's bits, the
// comparator offset, PRNU and DSNU enter each decision as the closed form says, the spread spot
// equals the shared dense blur (optical_blur.h), and with every key off nothing changes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/preset.h"
#include "golden/common/pixel.h"
#include "golden/common/quantiser.h"
#include "golden/common/spot.h"
#include "systemc/common/optical_blur.h"
#include "systemc/ls_conventional/nonideal_pattern.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"
#include "tests/systemc/sensor_test_helpers.h"

namespace rs = rangesim::systemc;
namespace golden = rangesim::golden;
using rangesim::LsConventionalConfig;
using rs::test::RandomStimulus;
using rs::test::small_config;

namespace {

// RandomStimulus with a per-pixel pattern attached.
struct PatternedStimulus {
  RandomStimulus base;
  const rs::PixelPattern* pattern = nullptr;
  void operator()(std::uint64_t frame, rs::FrameStimulus& out) const {
    base(frame, out);
    out.pattern = pattern;
  }
};

rs::PixelArrayOptions options(bool noise, bool sparse) {
  rs::PixelArrayOptions o;
  o.noise = noise ? rs::PixelNoiseConfig{} : rs::PixelNoiseConfig::none();
  o.sparse = sparse;
  o.seed = 7;
  return o;
}

// The activations of every row after each sampling of `frames` frame accesses.
std::vector<rs::ActivationRow> run(const LsConventionalConfig& c, const rs::PixelArrayOptions& o,
                                   rs::StimulusSource src, int frames, bool* per_pixel = nullptr) {
  rs::PixelArrayKernel px(c, o, std::move(src));
  std::vector<rs::ActivationRow> out;
  for (int f = 0; f < frames; ++f) {
    px.reset_frame(static_cast<std::uint64_t>(f));
    if (per_pixel) *per_pixel = px.per_pixel();
    for (int k = 1; k <= c.multisampling.samplings; ++k) {
      px.sample(k);
      for (int r = 0; r < px.rows(); ++r) out.push_back(px.row(r));
    }
  }
  return out;
}

}  // namespace

// A pattern that changes nothing (every gain exactly 1) sends every frame down the per-pixel path,
// which then must give the per-sampling path's bits (same streams, same expressions), sparse or dense.
TEST(LsConventionalNonideal, NeutralPatternGivesThePerSamplingPathsBits) {
  LsConventionalConfig c = small_config(30, 96, 4);
  c.simulation.exact_activation_sampling = false;
  rs::PixelPattern neutral;
  neutral.gain.assign(30 * 96, 1.0);
  RandomStimulus stim;
  stim.bg_hi = 0.2;
  for (bool noise : {false, true})
    for (bool sparse : {false, true}) {
      SCOPED_TRACE(std::to_string(noise) + std::to_string(sparse));
      bool per_pixel = false;
      const auto plain = run(c, options(noise, sparse), stim, 4, &per_pixel);
      EXPECT_FALSE(per_pixel);
      const auto pixelwise = run(c, options(noise, sparse), PatternedStimulus{stim, &neutral}, 4, &per_pixel);
      EXPECT_TRUE(per_pixel);
      ASSERT_EQ(plain.size(), pixelwise.size());
      int fired = 0;
      for (std::size_t i = 0; i < plain.size(); ++i) {
        EXPECT_TRUE(plain[i] == pixelwise[i]) << "row-sampling " << i;
        for (int col = 0; col < 96; ++col) fired += plain[i].test(col);
      }
      EXPECT_GT(fired, 1000);
    }
}

// Noise-free, every pixel's decision at every sampling is the closed form with its own gain, dark
// swing and comparator offset: A min((G (V_sig g + V_bg) + V_d) k / N, V_sat) + o >= theta.
TEST(LsConventionalNonideal, FixedPatternEntersEveryDecisionOfItsPixel) {
  LsConventionalConfig c = small_config(30, 96, 4);
  c.fixed_pattern.prnu_fraction = 0.05;
  c.fixed_pattern.dsnu_rms = 2e-12;  // 2.5 mV of dark swing rms
  c.fixed_pattern.comparator_offset_rms_V = 0.004;
  const rs::PixelPattern pat = rs::make_pixel_pattern(c, 3);
  ASSERT_EQ(pat.gain.size(), 30u * 96u);
  ASSERT_EQ(pat.dark_V.size(), 30u * 96u);
  ASSERT_EQ(pat.offset_V.size(), 30u * 96u);
  RandomStimulus stim;
  stim.sig_lo = 0.005, stim.sig_hi = 0.05, stim.bg_hi = 0.3;
  const int N = c.multisampling.samplings;
  for (bool sparse : {false, true}) {
    rs::PixelArrayKernel px(c, options(false, sparse), PatternedStimulus{stim, &pat});
    int decided_by_pattern = 0;
    for (int f = 0; f < 3; ++f) {
      px.reset_frame(static_cast<std::uint64_t>(f));
      for (int k = 1; k <= N; ++k) {
        px.sample(k);
        for (int r = 0; r < 30; ++r) {
          const rs::RowIllumination& in = px.stimulus().rows[static_cast<std::size_t>(r)];
          const double theta = golden::comparator_threshold_V(c, in.background_V);
          for (int i = 0; i < 96; ++i) {
            const std::size_t x = static_cast<std::size_t>(r * 96 + i);
            const double spot = in.signal_V > 0 ? in.signal_V * golden::spot_profile(c.spot, i - in.centre_px) : 0.0;
            const double v = pat.gain[x] * (spot + in.background_V) + pat.dark_V[x];
            const double t = static_cast<double>(k) / N;
            const bool want =
                c.pixel.source_follower_gain * std::min(v * t, c.pixel.saturation_voltage_V) + pat.offset_V[x] >= theta;
            const double nominal = (spot + in.background_V + golden::dark_voltage_V(c.pixel)) * k / N;
            decided_by_pattern += want != (std::min(nominal, c.pixel.saturation_voltage_V) >= theta);
            EXPECT_EQ(px.row(r).test(i), want) << "f " << f << " k " << k << " r " << r << " i " << i;
          }
        }
      }
    }
    EXPECT_GT(decided_by_pattern, 100);  // the pattern does change decisions here
  }
}

// The chip's pattern is keyed by the seed and the pixel only: the same every frame, another seed
// another chip, and its spreads are the keys' rms (2000 pixels: 3.2 % standard error of an rms).
TEST(LsConventionalNonideal, PatternIsTheChipsAndHasTheKeysRms) {
  LsConventionalConfig c = small_config(20, 100, 4);
  c.fixed_pattern.prnu_fraction = 0.02;
  c.fixed_pattern.dsnu_rms = 1e-13;
  c.pixel.dark_current_A = 1e-12;  // 10 rms above zero: no pixel's dark current clips
  c.fixed_pattern.comparator_offset_rms_V = 0.001;
  const rs::PixelPattern a = rs::make_pixel_pattern(c, 5), b = rs::make_pixel_pattern(c, 5),
                         d = rs::make_pixel_pattern(c, 6);
  EXPECT_EQ(a.gain, b.gain);
  EXPECT_EQ(a.offset_V, b.offset_V);
  EXPECT_NE(a.gain, d.gain);
  auto rms = [](const std::vector<double>& v, double mean) {
    double s = 0;
    for (double x : v) s += (x - mean) * (x - mean);
    return std::sqrt(s / static_cast<double>(v.size()));
  };
  const double dark_per_A = c.pixel.integration_time_s / c.pixel.pd_capacitance_F;
  EXPECT_NEAR(rms(a.gain, 1.0), 0.02, 0.02 * 0.1);
  EXPECT_NEAR(rms(a.offset_V, 0.0), 0.001, 0.001 * 0.1);
  EXPECT_NEAR(rms(a.dark_V, golden::dark_voltage_V(c.pixel)) / dark_per_A, 1e-13, 1e-14);
  for (int r = 0; r < 20; ++r) {
    double m = -1;
    for (int i = 0; i < 100; ++i) m = std::max(m, a.offset_V[static_cast<std::size_t>(r * 100 + i)]);
    EXPECT_EQ(a.max_offset_V[static_cast<std::size_t>(r)], m);
  }
}

// The spread spot (only the columns a spot reaches, all rows' sources, the band's receivers) is the
// shared dense blur of the full spot image, to rounding, at a step (two stripes on neighbouring rows).
TEST(LsConventionalNonideal, SpreadSpotIsTheDenseBlurOfTheSpotImage) {
  LsConventionalConfig c = small_config(40, 120, 4);
  c.blur.psf = rangesim::PsfKind::Gaussian;
  c.blur.gaussian_sigma_px = 1.3;
  c.blur.crosstalk_fraction = 0.08;
  const std::vector<rs::BlurTap> taps = rs::ls_conventional_blur_taps(c);
  ASSERT_GT(taps.size(), 9u);
  rs::FrameStimulus s;
  s.rows.resize(40);
  std::vector<double> image(40 * 120, 0.0);
  for (int r = 0; r < 40; ++r) {
    rs::RowIllumination& in = s.rows[static_cast<std::size_t>(r)];
    in.signal_V = r == 3 ? 0.0 : 0.2 + 0.01 * r;
    in.background_V = 0.01;
    in.centre_px = r < 20 ? 40.3 : 75.8;  // the step between rows 19 and 20
    if (r == 39) in.centre_px = 0.4;      // a spot at the array's edge
    for (int i = 0; i < 120; ++i)
      image[static_cast<std::size_t>(r * 120 + i)] =
          in.signal_V > 0 ? in.signal_V * golden::spot_profile(c.spot, i - in.centre_px) : 0.0;
  }
  const std::vector<double> want = rs::blur_image(image, 40, 120, taps);
  for (auto [first, count] : {std::pair{0, -1}, std::pair{15, 10}}) {
    s.first_row = first, s.row_count = count;
    rs::spread_spot(c, taps, s);
    const int last = count < 0 ? 39 : first + count - 1;
    for (int r = first; r <= last; ++r)
      for (int i = 0; i < 120; ++i) {
        const std::size_t x = static_cast<std::size_t>(r * 120 + i);
        EXPECT_NEAR(s.signal_px_V[x], want[x], 1e-15) << r << " " << i;
      }
  }
  // Row 20 sees both stripes: two maxima, one near each centre.
  s.first_row = 0, s.row_count = -1;
  rs::spread_spot(c, taps, s);
  const double* row = s.signal_px_V.data() + 20 * 120;
  EXPECT_GT(row[40], 0.01);
  EXPECT_GT(row[76], 0.1);
}

// The default preset's keys (airy at F/1.4, 850 nm, 11.25 um pitch; everything else 0) spread and
// pattern nothing, so the map takes the per-row paths, bit for bit as before the keys existed.
TEST(LsConventionalNonideal, PresetDefaultsLeaveThePerRowPaths) {
  const LsConventionalConfig c = rangesim::ls_conventional_from_params(rangesim::load_preset("ls-conventional"));
  EXPECT_FALSE(c.fixed_pattern.any());
  EXPECT_EQ(c.blur.psf, rangesim::PsfKind::Airy);
  EXPECT_NEAR(c.blur.psf_sigma_px(), 0.0444, 1e-3);
  EXPECT_TRUE(rs::ls_conventional_blur_taps(c).empty());
  EXPECT_TRUE(rs::make_pixel_pattern(c, 1).empty());
}

// Row bands (PixelArrayOptions::first_row, row_count: the rows on several threads) give the whole
// array's bits with the chip's pattern and a spread spot too: the pattern and the streams are keyed
// by the array's row, and each band spreads from every source row.
TEST(LsConventionalNonideal, RowBandsEqualTheWholeArrayWithPatternAndSpread) {
  LsConventionalConfig c = small_config(30, 96, 4);
  c.fixed_pattern.prnu_fraction = 0.02;
  c.fixed_pattern.comparator_offset_rms_V = 0.002;
  c.blur.psf = rangesim::PsfKind::Gaussian;
  c.blur.gaussian_sigma_px = 1.0;
  const rs::PixelPattern pat = rs::make_pixel_pattern(c, 9);
  const std::vector<rs::BlurTap> taps = rs::ls_conventional_blur_taps(c);
  RandomStimulus stim;
  auto source = [&](std::uint64_t f, rs::FrameStimulus& s) {
    const int first = s.first_row, count = s.row_count;
    s.first_row = 0, s.row_count = -1;
    stim(f, s);  // every row: the spread crosses rows
    s.first_row = first, s.row_count = count;
    s.pattern = &pat;
    rs::spread_spot(c, taps, s);
  };
  rs::PixelArrayOptions whole = options(true, true);
  const auto all = run(c, whole, source, 3);
  rs::PixelArrayOptions lo = whole, hi = whole;
  lo.first_row = 0, lo.row_count = 13;
  hi.first_row = 13, hi.row_count = 17;
  const auto a = run(c, lo, source, 3), b = run(c, hi, source, 3);
  // run() stores rows per sampling: whole 30 per sampling, the bands 13 and 17.
  for (std::size_t step = 0; step < 3 * 4; ++step)
    for (std::size_t r = 0; r < 30; ++r) {
      const rs::ActivationRow& want = all[step * 30 + r];
      const rs::ActivationRow& got = r < 13 ? a[step * 13 + r] : b[step * 17 + (r - 13)];
      EXPECT_TRUE(want == got) << "sampling step " << step << " row " << r;
    }
}
