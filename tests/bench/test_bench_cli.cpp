// `rangesim bench --quick --json` and the skipping switches of `rangesim simulate`, run as a
// user would. The bench's speed targets are reported, not tested; its identity checks are.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "run_command.h"

namespace {

namespace fs = std::filesystem;

std::string rangesim(const std::string& args) { return fmt::format("'{}' {}", RANGESIM_BIN, args); }
std::string scene(const std::string& f) { return std::string(RANGESIM_SCENES) + "/" + f; }

TEST(Bench, QuickJsonHasEveryFigureAndItsChecksPass) {
  const std::string dir = make_temp_dir() + "/bench";
  const CommandResult r = run_command(rangesim("bench --quick --json --out '" + dir + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);  // stdout is the JSON and nothing else
  for (const char* key : {"sparse_vs_dense", "model_vs_rtl", "floor_ratio", "systemc_vs_kernel", "mc_vs_bare_rng",
                          "aggregated_vs_per_clock_lockin", "aggregated_vs_per_clock_spad",
                          "aggregated_vs_per_clock_demod", "sparse_vs_dense_spad", "threads2_vs_1", "realtime_factor",
                          "output_share", "numpy_peer_ls_conventional", "numpy_peer_lockin_mc"}) {
    ASSERT_TRUE(j.contains(key)) << key;
    EXPECT_TRUE(j[key].is_number() || j[key].is_null()) << key;
    EXPECT_TRUE(j["targets"].contains(key)) << key;
    // Every target has its met flag: a bool where there is a value, null without one.
    ASSERT_TRUE(j["met"].contains(key)) << key;
    EXPECT_EQ(j["met"][key].is_boolean(), j[key].is_number()) << key;
    if (j[key].is_null()) EXPECT_TRUE(j["details"][key].contains("note")) << key << ": a missing figure says why";
  }
  for (const char* key : {"sparse_vs_dense", "model_vs_rtl", "floor_ratio", "systemc_vs_kernel",
                          "aggregated_vs_per_clock_lockin", "aggregated_vs_per_clock_spad",
                          "aggregated_vs_per_clock_demod", "sparse_vs_dense_spad", "realtime_factor", "output_share"}) {
    ASSERT_TRUE(j[key].is_number()) << key << " is measured by the bench itself";
    EXPECT_GT(j[key].get<double>(), 0.0) << key;
  }
  // The identity checks inside the bench.
  EXPECT_TRUE(j["checks_passed"].get<bool>()) << j["checks"].dump();
  for (const char* check :
       {"sparse_equals_dense", "rtl_equals_model", "systemc_equals_kernel",
        "ls_conventional_tick_equals_event_skipping", "ls_conventional_two_threads_equal_one",
        "lockin_aggregated_statistically_identical", "spad_aggregated_statistically_identical",
        "spad_per_clock_equals_per_cycle", "spad_sparse_cycles_identical", "spad_sparse_lit_pixels_identical",
        "spad_sparse_background_statistically_identical", "demod_aggregated_statistically_identical"}) {
    ASSERT_TRUE(j["checks"].contains(check)) << check;
    EXPECT_TRUE(j["checks"][check].get<bool>()) << check;
  }
  EXPECT_TRUE(j["details"]["sparse_vs_dense"]["bit_identical"].get<bool>());
  // The floor counts only uncertain pixel-samplings: some, and fewer than the lit ones.
  EXPECT_GT(j["details"]["floor_ratio"]["uncertain_samplings"].get<long long>(), 0);
  EXPECT_LT(j["details"]["floor_ratio"]["uncertain_samplings"].get<long long>(),
            j["details"]["floor_ratio"]["lit_pixel_samplings"].get<long long>());
  // The NumPy peer, where NumPy is installed, at equal error.
  if (j["numpy_peer_lockin_mc"].is_number())
    EXPECT_TRUE(j["details"]["numpy_peer_lockin_mc"]["errors_agree"].get<bool>())
        << j["details"]["numpy_peer_lockin_mc"];
  // The full readout RTL: quick = 15 frame accesses, every row's centre and thousands of streams.
  EXPECT_GT(j["details"]["model_vs_rtl"]["streams_compared"].get<long long>(), 1000);
  EXPECT_EQ(j["details"]["model_vs_rtl"]["centres_compared"].get<long long>(), 15 * 365);
  EXPECT_EQ(j["details"]["model_vs_rtl"]["mismatches"].get<long long>(), 0);
  // The Pareto table covers all four sensors and all three harnesses.
  std::set<std::string> sensors, harnesses;
  for (const auto& row : j["pareto"])
    sensors.insert(row["sensor"].get<std::string>()), harnesses.insert(row["harness"].get<std::string>());
  EXPECT_EQ(sensors.size(), 4u);
  EXPECT_EQ(harnesses, (std::set<std::string>{"kernel", "systemc", "rtl"}));
  for (const char* f : {"bench.json", "figures.md", "pareto.md", "pareto.csv"})
    EXPECT_TRUE(fs::exists(dir + "/" + f)) << f;
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().rfind(".staging", 0), std::string::npos) << "staging left behind";
}

TEST(Bench, UnwritableOutIsBadInputAndNothingRuns) {
  const CommandResult r = run_command(rangesim("bench --quick --out /proc/rangesim-bench"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

nlohmann::json simulate(const std::string& args, int expect = 0) {
  const std::string dir = make_temp_dir() + "/sim";
  const CommandResult r = run_command(rangesim("simulate " + args + " --json --no-plots --out '" + dir + "'"));
  EXPECT_EQ(r.exit_code, expect) << args << "\n" << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json{{"err", r.err}};
}

TEST(SkippingSwitches, NoSparseIsDenseWithIdenticalMap) {
  const std::string s = "ls-conventional --scene '" + scene("plane.toml") + "' --kernel-only --frames 3";
  const auto a = simulate(s), b = simulate(s + " --no-sparse");
  EXPECT_TRUE(a["sparse"].get<bool>());
  EXPECT_FALSE(b["sparse"].get<bool>());
  EXPECT_EQ(a["range_error_rms_m"], b["range_error_rms_m"]);
  EXPECT_EQ(a["cycles"], b["cycles"]);
}

TEST(SkippingSwitches, NoEventSkipTicksWithIdenticalResult) {
  const std::string s = "ls-conventional --scene '" + scene("plane.toml") + "' --kernel-only --frames 3";
  const auto a = simulate(s), b = simulate(s + " --no-event-skip");
  EXPECT_TRUE(a["event_skipping"].get<bool>());
  EXPECT_FALSE(b["event_skipping"].get<bool>());
  EXPECT_EQ(a["range_error_rms_m"], b["range_error_rms_m"]);
  EXPECT_EQ(a["cycles"], b["cycles"]);
}

// tof-lockin with --no-aggregate takes ~10 s per frame of the example scene; the switch's effect
// is proved at kernel level (LockinAggregation.*, LockinSkipping.*). Here: refused where
// there is nothing to switch off.
TEST(SkippingSwitches, NoAggregateIsRefusedWithoutAnAggregatedPath) {
  const auto e = simulate("ls-conventional --scene '" + scene("plane.toml") + "' --kernel-only --no-aggregate", 2);
  EXPECT_NE(e["err"].get<std::string>().find("--no-aggregate"), std::string::npos);
}

// ls-demodulation: the switch through the binary. Noise-free, aggregated and per-period windows
// give the same decisions (so positions and error) and cycles (DemodAggregation.* for D and noise).
TEST(SkippingSwitches, DemodNoAggregateStepsPeriodsWithTheSameResult) {
  const std::string s =
      "ls-demodulation --scene '" + scene("ls-demodulation-plane.toml") + "' --kernel-only --noise-free --frames ";
  const auto a = simulate(s + "3"), b = simulate(s + "3 --no-aggregate"), t = simulate(s + "1 --tick");
  EXPECT_EQ(a["aggregation"]["path"], "aggregated");
  EXPECT_EQ(b["aggregation"]["path"], "per_period");
  EXPECT_EQ(t["aggregation"]["path"], "per_period");  // ticking implies per period
  EXPECT_EQ(a["cycles"], b["cycles"]);
  EXPECT_EQ(a["range_error_rms_m"], b["range_error_rms_m"]);
  EXPECT_EQ(a["points_detected"], b["points_detected"]);
}

// tof-spad: the preset's dead time, afterpulses, jitter and busy time make its laser cycles
// dependent, so the default run reports the per-cycle path and says why, and --no-aggregate gives
// the same output (the aggregated path itself: SpadAggregation.*).
TEST(SkippingSwitches, SpadPresetRunsPerCycleAndNoAggregateChangesNothing) {
  const std::string s = "tof-spad --scene '" + scene("tof-spad-plane.toml") + "' --kernel-only";
  const auto a = simulate(s), b = simulate(s + " --no-aggregate");
  EXPECT_TRUE(a["aggregation"]["requested"].get<bool>());
  EXPECT_FALSE(b["aggregation"]["requested"].get<bool>());
  EXPECT_EQ(a["aggregation"]["path"], "per_cycle");
  EXPECT_EQ(b["aggregation"]["path"], "per_cycle");
  EXPECT_NE(a["aggregation"]["blocker"].get<std::string>().find("afterpulses"), std::string::npos);
  EXPECT_GT(a["aggregation"]["groups_per_cycle"].get<long long>(), 0);
  EXPECT_EQ(a["range_error_rms_m"], b["range_error_rms_m"]);
  EXPECT_EQ(a["avalanches_simulated"], b["avalanches_simulated"]);
}

// tof-spad background-only pixels (outside the [beam] spot of tof-spad-spot.toml): with the
// preset's dependent cycles they run per cycle and the summary says why; their spurious
// detections stay out of the range error. Noise-free they have no arrivals, so the class's
// (empty) histograms are exact: sparse and --dense (the whole array, one by one) give the same
// range error over the lit pixels and no background detection.
TEST(SkippingSwitches, SpadBackgroundOnlyPixelsOfABeamSpot) {
  const std::string s = "tof-spad --scene '" + scene("tof-spad-spot.toml") + "' --kernel-only";
  const auto a = simulate(s);
  EXPECT_TRUE(a["sparse"].get<bool>());
  EXPECT_EQ(a["background_only"]["points"].get<long long>(), 16 * 32 - 8 * 8);
  EXPECT_EQ(a["background_only"]["groups_per_cycle"].get<long long>(), (16 * 32 - 8 * 8) / 4);
  EXPECT_EQ(a["background_only"]["groups_class"].get<long long>(), 0);
  EXPECT_NE(a["background_only"]["blocker"].get<std::string>().find("afterpulses"), std::string::npos);
  EXPECT_LT(a["range_error_rms_m"].get<double>(), 0.05);  // lit pixels only
  const auto q = simulate(s + " --noise-free"), d = simulate(s + " --noise-free --dense");
  EXPECT_EQ(q["background_only"]["groups_class"].get<long long>(), (16 * 32 - 8 * 8) / 4);
  EXPECT_EQ(d["background_only"]["groups_class"].get<long long>(), 0);
  EXPECT_EQ(d["background_only"]["points"].get<long long>(), 128 * 128 - 8 * 8);
  EXPECT_EQ(q["range_error_rms_m"], d["range_error_rms_m"]);
  EXPECT_EQ(q["cycles"], d["cycles"]);
  EXPECT_EQ(q["background_only"]["detections"].get<long long>(), 0);
  EXPECT_EQ(d["background_only"]["detections"].get<long long>(), 0);
}

// --time-step (tof-lockin's numerical pulse/gate overlap): out-of-range values are exit 2 naming
// the flag and the allowed range, other sensors refuse it; a coarse step is visibly wrong and a
// fine one gives the exact run's noise-free range error (monotone convergence with a rise time:
// LockinTimeStep.*).
TEST(TimeStep, BadValuesAreRefusedWithTheAllowedRange) {
  const std::string s = "tof-lockin --scene '" + scene("tof-lockin-plane.toml") + "' --kernel-only --time-step ";
  for (const char* v : {"-1", "nan", "1e-6", "1e-13"}) {
    const auto e = simulate(s + v, 2);
    const std::string err = e["err"].get<std::string>();
    EXPECT_NE(err.find("--time-step"), std::string::npos) << v << ": " << err;
    EXPECT_NE(err.find("allowed"), std::string::npos) << v << ": " << err;
    // A number out of the flag's own range is refused as it is parsed ([0, 1] s); one inside it,
    // by the sensor, with the range its pulse allows.
    if (std::string(v) == "1e-6" || std::string(v) == "1e-13")
      EXPECT_NE(err.find("1e-12 <= S <= 1e-07"), std::string::npos) << v << ": " << err;
  }
  const auto e = simulate("ls-conventional --scene '" + scene("plane.toml") + "' --kernel-only --time-step 1e-9", 2);
  EXPECT_NE(e["err"].get<std::string>().find("--time-step"), std::string::npos);
}

TEST(TimeStep, FineStepMeetsTheExactNoiseFreeRun) {
  const std::string s = "tof-lockin --scene '" + scene("tof-lockin-plane.toml") + "' --kernel-only --noise-free";
  const auto exact = simulate(s), coarse = simulate(s + " --time-step 5e-8"), fine = simulate(s + " --time-step 1e-9");
  EXPECT_EQ(exact["time_step_s"].get<double>(), 0.0);
  EXPECT_EQ(fine["time_step_s"].get<double>(), 1e-9);
  const double e0 = exact["range_error_rms_m"].get<double>();
  EXPECT_GT(coarse["range_error_rms_m"].get<double>(), e0 + 1.0);  // whole 50 ns steps of charge misplaced
  EXPECT_NEAR(fine["range_error_rms_m"].get<double>(), e0, 5e-3);
}

}  // namespace
