// A fifth sensor registered at run time goes through the same command code as the shipped four:
// `list`, `show`, `evaluate` and `frame-rate` reach it only through the registries
// (core/sensor_registry.h, golden/common/evaluate_sensor.h), so nothing in app/ or golden/ had to
// learn its id. The toy sensor is a pixel that detects when signal / background > its threshold,
// with an accuracy that falls as 1 / signal, and a two-phase clock schedule.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "core/preset.h"
#include "core/sensor_registry.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"

namespace {

using namespace rangesim;
namespace fs = std::filesystem;

const ParamSchema& toy_schema() {
  using K = ParamKind;
  static const ParamSchema schema{
      "toy-sensor",
      {
          {"pixel.threshold_ratio", K::Real, "", 0, 1e6, true, "detects when signal / background exceeds this"},
          {"pixel.noise_m", K::Real, "m", 0, 1, false, "range noise at unit signal"},
          {"timing.clock_Hz", K::Real, "Hz", 0, 1e10, true, "readout clock"},
          {"timing.integration_cycles", K::Integer, "", 1, 1e9, false, "cycles of integration per frame"},
          {"timing.readout_cycles", K::Integer, "", 1, 1e9, false, "cycles of readout per frame"},
          {"evaluation.signal_min_W", K::Real, "W", 0, 1, true, "lowest signal of the grid"},
          {"evaluation.signal_max_W", K::Real, "W", 0, 1, true, "highest signal of the grid"},
          {"evaluation.signal_points", K::Integer, "", 1, 10000, false, "log-spaced signal points"},
          {"evaluation.background_min_W", K::Real, "W", 0, 1, true, "lowest background of the grid"},
          {"evaluation.background_max_W", K::Real, "W", 0, 1, true, "highest background of the grid"},
          {"evaluation.background_points", K::Integer, "", 1, 10000, false, "log-spaced background points"},
      }};
  return schema;
}

void toy_validate(const ParamSet& p) {
  if (p.real("evaluation.signal_min_W") > p.real("evaluation.signal_max_W"))
    throw UserError(p.origin() + ": evaluation.signal_min_W > evaluation.signal_max_W; allowed: min <= max");
}

golden::EvalResult toy_evaluate(const ParamSet& p, golden::ProgressFn progress) {
  golden::EvalResult r;
  r.sensor = p.sensor_id();
  r.signal = {"signal", "W",
              golden::log_spaced(p.real("evaluation.signal_min_W"), p.real("evaluation.signal_max_W"),
                                 static_cast<int>(p.integer("evaluation.signal_points")))};
  r.background = {"background", "W",
                  golden::log_spaced(p.real("evaluation.background_min_W"), p.real("evaluation.background_max_W"),
                                     static_cast<int>(p.integer("evaluation.background_points")))};
  r.reasons = {{"detectable", "range is reported"}, {"below_threshold", "signal / background below the threshold"}};
  r.distance_m = 1.0;
  const int total = static_cast<int>(r.signal.values.size() * r.background.values.size());
  for (double b : r.background.values)
    for (double s : r.signal.values) {
      golden::EvalPoint q;
      q.signal = s, q.background = b;
      const bool ok = s / b > p.real("pixel.threshold_ratio");
      q.detect = ok ? "detectable" : "below_threshold";
      q.sbr_total_dB = 20 * std::log10((s + b) / b);
      q.sbr_ratio_dB = 20 * std::log10(s / b);
      if (ok) q.accuracy_m = p.real("pixel.noise_m") / s;
      r.points.push_back(q);
      if (progress) progress(static_cast<int>(r.points.size()), total);
    }
  golden::summarise_points(r);
  return r;
}

std::vector<golden::PublishedFigure> toy_published(const ParamSet&) { return {}; }

golden::FrameTiming toy_frame_timing(const ParamSet& p) {
  golden::FrameTiming t;
  const double clock = p.real("timing.clock_Hz");
  for (const char* phase : {"integration", "readout"}) {
    const long long cycles = p.integer(std::string("timing.") + phase + "_cycles");
    t.phases.push_back({phase, cycles, cycles / clock});
    t.frame_cycles += cycles;
  }
  t.clock_Hz = clock;
  t.frame_time_s = t.frame_cycles / clock;
  t.frame_access_rate_Hz = 1 / t.frame_time_s;
  t.frames_per_range_map = 1;
  t.range_map_time_s = t.frame_time_s;
  t.range_maps_per_s = t.frame_access_rate_Hz;
  return t;
}

// Registers the toy sensor once per process and writes its preset.
class FifthSensor : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    register_sensor({"toy-sensor", "toy: threshold on signal / background", "[toy]", &toy_schema, &toy_validate});
    golden::register_golden_model({"toy-sensor", &toy_evaluate, &toy_published, &toy_frame_timing, nullptr});
    dir_ = fs::path(::testing::TempDir()) / ("fifth_sensor_" + std::to_string(::getpid()));
    fs::remove_all(dir_);  // a run of its own: evaluate refuses another run's results
    fs::create_directories(dir_);
    std::ofstream(dir_ / "toy-sensor.toml") << R"([sensor]
id = "toy-sensor"
[pixel]
threshold_ratio = { value = 2.0, source = "assumed: test" }
noise_m = { value = 1e-3, source = "assumed: test" }
[timing]
clock_Hz = { value = 1e6, source = "assumed: test" }
integration_cycles = { value = 900, source = "assumed: test" }
readout_cycles = { value = 100, source = "assumed: test" }
[evaluation]
signal_min_W = { value = 1e-3, source = "assumed: test" }
signal_max_W = { value = 1.0, source = "assumed: test" }
signal_points = { value = 4, source = "assumed: test" }
background_min_W = { value = 1e-3, source = "assumed: test" }
background_max_W = { value = 1e-1, source = "assumed: test" }
background_points = { value = 3, source = "assumed: test" }
)";
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static std::string preset() { return (dir_ / "toy-sensor.toml").string(); }
  static fs::path dir_;
};
fs::path FifthSensor::dir_;

TEST_F(FifthSensor, IsListedAfterTheShippedSensors) {
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(app::run_list({true}), 0);
  const auto j = nlohmann::json::parse(::testing::internal::GetCapturedStdout());
  ASSERT_EQ(j.size(), 5u);
  EXPECT_EQ(j[4]["id"], "toy-sensor");
  EXPECT_EQ(j[4]["thesis_ref"], "[toy]");
  EXPECT_TRUE(j[4]["golden_modelled"].get<bool>());
  EXPECT_NE(sensor_ids().find("toy-sensor"), std::string::npos);
}

TEST_F(FifthSensor, ShowPrintsItsParametersWithUnitsAndSources) {
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(app::run_show({preset(), true}), 0);
  const auto j = nlohmann::json::parse(::testing::internal::GetCapturedStdout());
  EXPECT_EQ(j["sensor"], "toy-sensor");
  EXPECT_DOUBLE_EQ(j["parameters"]["pixel.threshold_ratio"]["value"].get<double>(), 2.0);
  EXPECT_EQ(j["parameters"]["timing.clock_Hz"]["unit"], "Hz");
  EXPECT_EQ(j["parameters"]["pixel.noise_m"]["source"], "assumed: test");
}

TEST_F(FifthSensor, EvaluateWritesTheSameOutputsAsForAShippedSensor) {
  const fs::path out = dir_ / "evaluate";
  app::EvaluateOptions opt;
  opt.sensor = preset();
  opt.out = out.string();
  opt.json = true;
  opt.no_plots = true;
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(app::run_evaluate(opt), 0);
  const auto j = nlohmann::json::parse(::testing::internal::GetCapturedStdout());
  EXPECT_EQ(j["points_total"], 12);
  // Detectable where signal / background > 2: signal 1 W over all three backgrounds, 0.1 W over
  // 1 mW and 10 mW, 10 mW over 1 mW.
  EXPECT_EQ(j["points_detectable"], 6);
  EXPECT_NEAR(j["accuracy_min_m"].get<double>(), 1e-3, 1e-12);  // at 1 W
  for (const char* f : {"points.csv", "detectable_area.csv", "accuracy_mm.csv", "summary.json"})
    EXPECT_TRUE(fs::is_regular_file(out / f)) << f;
  // The grid flags reach its own keys through the schema.
  opt.signal = "0.5:0.5:1";
  opt.background = "0.1:0.1:1";
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(app::run_evaluate(opt), 0);
  const auto k = nlohmann::json::parse(::testing::internal::GetCapturedStdout());
  EXPECT_EQ(k["points_total"], 1);
  EXPECT_EQ(k["points_detectable"], 1);
}

TEST_F(FifthSensor, FrameRateComesFromItsClockSchedule) {
  ::testing::internal::CaptureStdout();
  ASSERT_EQ(app::run_frame_rate({preset(), std::nullopt, true}), 0);
  const auto j = nlohmann::json::parse(::testing::internal::GetCapturedStdout());
  EXPECT_EQ(j["frame_cycles"], 1000);
  EXPECT_DOUBLE_EQ(j["frame_access_rate_Hz"].get<double>(), 1000.0);
  EXPECT_EQ(j["phases"][0]["name"], "integration");
  // A flag the sensor has no parameter for is refused with its name.
  EXPECT_THROW(app::run_frame_rate({preset(), 2, true}), UserError);
}

TEST_F(FifthSensor, ItsIdIsKnownToPresetLoadingAndTaken) {
  EXPECT_EQ(load_preset(preset()).sensor_id(), "toy-sensor");
  EXPECT_EQ(&schema_for("toy-sensor", "test"), &toy_schema());
  EXPECT_THROW(register_sensor({"toy-sensor", "again", "", &toy_schema, &toy_validate}), std::invalid_argument);
}

}  // namespace
