// Published figures of tof-lockin (thesis 4.1.1, 4.1.3, Table 5.1 [12], docs/tof-lockin.md): each
// reproduced one is asserted within its tolerance, each other one is pinned at our value with
// the reason it differs (also in its `note` and in docs/tof-lockin.md).
#include <gtest/gtest.h>

#include <map>

#include "golden/common/evaluate_sensor.h"
#include "lockin_test_util.h"

namespace rangesim::golden {

namespace {

const std::map<std::string, PublishedFigure>& figures() {
  static const std::map<std::string, PublishedFigure> m = [] {
    std::map<std::string, PublishedFigure> out;
    for (auto& f : published_figures(test::lockin_params())) out.emplace(f.id, f);
    return out;
  }();
  return m;
}

const PublishedFigure& fig(const std::string& id) {
  const auto it = figures().find(id);
  if (it == figures().end()) throw std::runtime_error("no published figure " + id);
  return it->second;
}

}  // namespace

TEST(LockinPublished, EveryFigureIsWellFormed) {
  EXPECT_EQ(figures().size(), 22u);
  for (const auto& [id, f] : figures()) {
    EXPECT_EQ(f.sensor, "tof-lockin");
    EXPECT_FALSE(f.note.empty()) << id;
    EXPECT_GT(f.tolerance, 0.0) << id;
    if (!f.reproduced()) {
      EXPECT_NE(f.note.find("not reproduced"), std::string::npos) << id;
    }
  }
}

// Resolution figures of thesis 4.1.1, with the read noise calibrated to all eleven at once
// (0.7 mV); 25 % tolerance: no single shot + floor model meets all of them closer (doc).
TEST(LockinPublished, ResolutionFiguresReproducedWithin25Percent) {
  for (const char* id : {"resolution_t0_100ns_1p4V", "resolution_delay_1ns_0p7V", "resolution_delay_50ns_0p7V",
                         "resolution_delay_100ns_0p7V", "averaging_0p25V_1frame", "averaging_0p25V_25frames",
                         "averaging_1p3V_1frame", "averaging_1p3V_25frames", "pulse_width_10ns", "pulse_width_40ns",
                         "pulse_width_100ns", "resolution_1p4V_10frames"}) {
    const PublishedFigure& f = fig(id);
    EXPECT_DOUBLE_EQ(f.tolerance, 0.25) << id;
    EXPECT_TRUE(f.reproduced()) << id << ": published " << f.published << ", ours " << f.ours;
  }
  // Where each sits (pins the calibration): 2.35 -> 1.85 cm is the largest miss below, 3.45 ->
  // 4.13 cm the largest above.
  EXPECT_NEAR(fig("resolution_t0_100ns_1p4V").ours, 0.01854, 0.0001);
  EXPECT_NEAR(fig("resolution_delay_1ns_0p7V").ours, 0.02956, 0.0001);
  EXPECT_NEAR(fig("resolution_delay_50ns_0p7V").ours, 0.0413, 0.0001);
  EXPECT_NEAR(fig("pulse_width_10ns").ours, 0.00312, 0.00002);
}

TEST(LockinPublished, ExactFiguresReproduced) {
  EXPECT_TRUE(fig("averaging_gain_25frames").reproduced()) << fig("averaging_gain_25frames").ours;
  EXPECT_TRUE(fig("max_range_t0_100ns").reproduced());
  EXPECT_NEAR(fig("max_range_t0_100ns").ours, 14.9896, 1e-4);
  EXPECT_TRUE(fig("frame_rate_30fps").reproduced()) << fig("frame_rate_30fps").ours;
  // The thesis's 12.6 mm is pure signal shot noise at 1.4 V, 1 m, 10 fF.
  EXPECT_TRUE(fig("accuracy_best_as_shot_noise").reproduced()) << fig("accuracy_best_as_shot_noise").ours;
}

TEST(LockinPublished, Table51FiguresPinnedWhereNotReproduced) {
  // Signal range: the range-noise bound (5 % of c T0 / 2) moves the lower edge from 0.0100 to
  // 0.0510 nA (-14.1 dB; the SNR-3 rule alone gave 0.0116 nA, -1.3 dB).
  EXPECT_FALSE(fig("table51_signal_dB").reproduced());
  EXPECT_NEAR(fig("table51_signal_dB").ours, 29.36, 0.01);
  // Background range: the lower edge is the grid (10 fA), the upper one saturation at 10 fF.
  EXPECT_FALSE(fig("table51_background_dB").reproduced());
  EXPECT_NEAR(fig("table51_background_dB").ours, 103.86, 0.01);
  // SBR' (ratio style, the one that can be negative like Table 5.1's -62 dB) follows the grid.
  EXPECT_FALSE(fig("table51_sbr_max_dB").reproduced());
  EXPECT_NEAR(fig("table51_sbr_max_dB").ours, 103.52, 0.01);
  EXPECT_FALSE(fig("table51_sbr_min_dB").reproduced());
  EXPECT_NEAR(fig("table51_sbr_min_dB").ours, -19.32, 0.01);
  // Accuracy over the grid includes kTC / read noise and the ambient frame.
  EXPECT_FALSE(fig("table51_accuracy_best").reproduced());
  EXPECT_NEAR(fig("table51_accuracy_best").ours, 0.0306, 0.0001);
  EXPECT_FALSE(fig("table51_accuracy_worst").reproduced());
  EXPECT_NEAR(fig("table51_accuracy_worst").ours, 0.757, 0.001);
}

}  // namespace rangesim::golden
