// Proof of the exact path's row extents (systemc/ls_conventional/pixel_array_kernel.h extent()):
// the event-skipping readout reads each row's lowest and highest activated column, which the exact
// path computes from the first firings drawn at the reset, without making the row's bits. At every
// sampling of every row they must equal the first and last set bit of the row as the latch holds it
// (row(), made on demand from the same draws), under every noise configuration, with and without
// the certain intervals, for several counts of samplings (the unrolled 2, 4, 8 and the general
// loop), tracking and fixed thresholds, and on the plane map. LsConventionalSensorKernel's
// EventSkippingEqualsTicking then shows the bits themselves equal to the ticked latch. And the
// frame's uniforms made in one batch (systemc/common/keyed_uniforms.h) are each pixel's own.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "systemc/common/keyed_uniforms.h"
#include "systemc/common/random_stream.h"
#include "systemc/ls_conventional/scene_optics.h"
#include "tests/skipping/exact_activation_helpers.h"
#include "tests/systemc/sensor_test_helpers.h"

using namespace exact_test;

namespace {

// Every row at every sampling of `frames` frame accesses: extent() == the bits' first and last.
// Returns how many (row, sampling) pairs had an activation, so a test cannot pass on empty rows.
long long check_extents(const LsConventionalConfig& c, const rs::PixelArrayOptions& o, rs::StimulusSource src,
                        int frames, const std::string& what) {
  rs::PixelArrayKernel px(c, o, std::move(src));
  long long lit = 0;
  for (int f = 0; f < frames; ++f) {
    px.reset_frame(static_cast<std::uint64_t>(f));
    for (int r = 0; r < px.rows(); ++r) {
      EXPECT_EQ(px.extent(r), rs::ActivationExtent{}) << what;
      EXPECT_FALSE(px.row(r).any()) << what;
    }
    for (int k = 1; k <= c.multisampling.samplings; ++k) {
      px.sample(k);
      for (int r = 0; r < px.rows(); ++r) {
        const rs::ActivationExtent e = px.extent(r);
        const rs::ActivationRow& bits = px.row(r);
        if (e.first != bits.first() || e.last != bits.last()) {
          ADD_FAILURE() << what << ": frame " << f << " sampling " << k << " row " << r << ": extent [" << e.first
                        << ", " << e.last << "], bits [" << bits.first() << ", " << bits.last() << "]";
          return lit;
        }
        lit += e.first >= 0;
      }
    }
  }
  return lit;
}

}  // namespace

TEST(RowExtents, EqualTheLatchedBitsOnRandomRows) {
  long long lit = 0;
  for (const int samplings : {2, 3, 4, 8}) {
    for (const rs::PixelNoiseConfig noise :
         {rs::PixelNoiseConfig{}, rs::PixelNoiseConfig{true, false, false}, rs::PixelNoiseConfig{false, true, true},
          rs::PixelNoiseConfig{true, true, false}, rs::PixelNoiseConfig::none()}) {
      for (const bool intervals : {true, false}) {
        for (const bool fixed : {false, true}) {
          LsConventionalConfig c = rs::test::small_config(12, 64, samplings);
          c.simulation.certain_intervals = intervals;
          if (fixed) c.comparator.threshold_mode = rangesim::ThresholdMode::Fixed;
          rs::PixelArrayOptions o;
          o.noise = noise;
          o.seed = 23;
          const std::string what = "N=" + std::to_string(samplings) + " shot " + std::to_string(noise.shot) +
                                   " ktc " + std::to_string(noise.reset_ktc) + " read " +
                                   std::to_string(noise.read) + " intervals " + std::to_string(intervals) +
                                   " fixed " + std::to_string(fixed);
          lit += check_extents(c, o, rs::test::RandomStimulus{5, 0.005, 1.5, 1e-4, 0.2, 64}, 25, what);
        }
      }
    }
  }
  EXPECT_GT(lit, 20000);
  RecordProperty("lit_row_samplings", std::to_string(lit));
}

TEST(RowExtents, EqualTheLatchedBitsOnThePlaneMap) {
  // The preset on scenes/plane.toml: rows share their shape, each with its own draws.
  const LsConventionalConfig c = preset();
  const rangesim::scene::SceneOptics optics(
      c, rangesim::scene::load_scene(std::string(RANGESIM_SOURCE_DIR) + "/scenes/plane.toml", "ls-conventional"));
  const long long lit = check_extents(
      c, rs::PixelArrayOptions{}, [&optics](std::uint64_t f, rs::FrameStimulus& s) { optics.stimulus(f, s); }, 120,
      "plane");
  EXPECT_GT(lit, 120 * 300);
}

TEST(KeyedUniforms, EqualThePixelsKeyedUniformsOneByOne) {
  // The batch (vectorised where the CPU allows) gives each pixel's own keyed_uniform bit for bit,
  // at every length (the vector loop's tail) and for rows and columns across the 32-bit range.
  std::mt19937_64 rng(11);
  // (A step takes six: four in the vector lanes and two in general-purpose registers.)
  for (const std::size_t n :
       {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{6}, std::size_t{7}, std::size_t{8}, std::size_t{9},
        std::size_t{11}, std::size_t{12}, std::size_t{1000}, std::size_t{4099}}) {
    const std::uint64_t frame_key = rs::frame_stream_key(rng(), rng());
    std::vector<std::uint64_t> rc(n);
    for (auto& x : rc) x = rs::row_column(static_cast<std::uint32_t>(rng()), static_cast<std::uint32_t>(rng()));
    std::vector<double> u(n, -1.0);
    rs::keyed_uniforms(frame_key, rc.data(), u.data(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const double one = rs::keyed_uniform(rs::pixel_key_in_frame(frame_key, static_cast<std::uint32_t>(rc[i] >> 32),
                                                                   static_cast<std::uint32_t>(rc[i])));
      ASSERT_EQ(u[i], one) << "n " << n << " i " << i;
      ASSERT_GT(u[i], 0.0);
      ASSERT_LT(u[i], 1.0);
    }
  }
}

TEST(KeyedUniforms, GridsEqualThePixelsKeyedUniformsOneByOne) {
  // A grid (rows of some columns, keys made in the loop) gives each pixel's own keyed_uniform bit for
  // bit: every row count around the step (six rows: four in the vector lanes, two in registers),
  // rows up to the 32-bit limit, and no write past it.
  std::mt19937_64 rng(12);
  for (const std::size_t rows :
       {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{4}, std::size_t{5}, std::size_t{6}, std::size_t{7},
        std::size_t{8}, std::size_t{11}, std::size_t{12}, std::size_t{13}, std::size_t{365}, std::size_t{1027}}) {
    for (const std::uint32_t row0 : {0U, 17U, 0xffffffffU - static_cast<std::uint32_t>(rows)}) {
      const std::uint64_t frame_key = rs::frame_stream_key(rng(), rng());
      std::vector<std::uint32_t> columns(3);
      for (auto& c : columns) c = static_cast<std::uint32_t>(rng());
      std::vector<double> u(columns.size() * rows + 1, -1.0);
      rs::keyed_uniforms_grid(frame_key, row0, rows, columns.data(), columns.size(), u.data());
      for (std::size_t t = 0; t < columns.size(); ++t)
        for (std::size_t i = 0; i < rows; ++i) {
          const double one =
              rs::keyed_uniform(rs::pixel_key_in_frame(frame_key, row0 + static_cast<std::uint32_t>(i), columns[t]));
          ASSERT_EQ(u[t * rows + i], one) << "rows " << rows << " row0 " << row0 << " t " << t << " i " << i;
        }
      EXPECT_EQ(u.back(), -1.0) << "rows " << rows;
    }
  }
}
