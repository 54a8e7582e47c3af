// The four shipped presets load, match their schemas, say where every number comes from, and
// their derived numbers follow from the others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <regex>
#include <set>

#include "core/physics.h"
#include "core/preset.h"
#include "core/schemas.h"
#include "core/user_error.h"
#include "tests/core/preset_test_util.h"

namespace rangesim {
namespace {

using test::preset_ids;
using test::source_preset_path;

using phys::kSpeedOfLight_m_per_s;
constexpr double kPi = 3.14159265358979323846;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

class PresetTest : public ::testing::TestWithParam<std::string> {};

std::string param_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string s = info.param;
  std::replace(s.begin(), s.end(), '-', '_');
  return s;
}

INSTANTIATE_TEST_SUITE_P(AllSensors, PresetTest, ::testing::ValuesIn(preset_ids()), param_name);

TEST_P(PresetTest, ResolvesToTheSourceTree) {
  namespace fs = std::filesystem;
  EXPECT_TRUE(fs::equivalent(resolve_preset(GetParam()), source_preset_path(GetParam())));
}

TEST_P(PresetTest, LoadsWithEverySchemaKeyAndASource) {
  const ParamSet set = load_preset(GetParam());
  EXPECT_EQ(set.sensor_id(), GetParam());
  const ParamSchema& schema = schema_for(GetParam(), "test");
  ASSERT_FALSE(schema.params.empty()) << "schema of " << GetParam() << " is empty";
  EXPECT_EQ(set.values().size(), schema.params.size());
  const std::regex status("^(published|derived|assumed|recalled): .+");
  for (const auto& spec : schema.params) {
    SCOPED_TRACE(spec.key);
    ASSERT_TRUE(set.has(spec.key));
    const ParamValue& v = set.at(spec.key);
    EXPECT_EQ(v.kind, spec.kind);
    EXPECT_FALSE(v.source.empty());
    EXPECT_TRUE(std::regex_search(v.source, status))
        << "source must start with published:/derived:/assumed:/recalled:, got: " << v.source;
    if (spec.kind == ParamKind::Real || spec.kind == ParamKind::Integer) {
      EXPECT_TRUE(std::isfinite(v.number));
    }
  }
}

TEST_P(PresetTest, SchemaIsWellFormed) {
  const ParamSchema& schema = schema_for(GetParam(), "test");
  EXPECT_EQ(schema.sensor_id, GetParam());
  std::set<std::string> keys;
  for (const auto& spec : schema.params) {
    SCOPED_TRACE(spec.key);
    EXPECT_TRUE(keys.insert(spec.key).second) << "duplicate key";
    const auto dot = spec.key.find('.');
    ASSERT_NE(dot, std::string::npos) << "key must be section.name";
    EXPECT_EQ(spec.key.find('.', dot + 1), std::string::npos) << "one level of sections only";
    EXPECT_GT(dot, 0u);
    EXPECT_LT(dot + 1, spec.key.size());
    EXPECT_FALSE(spec.description.empty());
    EXPECT_EQ(spec.description.find('\n'), std::string::npos) << "description must be one line";
    EXPECT_EQ(schema.find(spec.key), &spec);
    if (spec.kind == ParamKind::Real || spec.kind == ParamKind::Integer) {
      EXPECT_LE(spec.min, spec.max);
      if (spec.min_exclusive) {
        EXPECT_LT(spec.min, spec.max);
      }
    }
    // The unit is the key's suffix (SI units in key names).
    if (!spec.unit.empty()) {
      EXPECT_TRUE(ends_with(lower(spec.key), "_" + lower(spec.unit))) << "unit " << spec.unit;
    }
    // Capacitances, bit counts and times cannot be zero or negative.
    if (ends_with(spec.key, "_F")) {
      EXPECT_EQ(spec.unit, "F");
      EXPECT_EQ(spec.min, 0.0);
      EXPECT_TRUE(spec.min_exclusive) << "a capacitance must be > 0";
    }
    if (ends_with(spec.key, "bits")) {
      EXPECT_EQ(spec.kind, ParamKind::Integer);
      EXPECT_TRUE(spec.min >= 1 || (spec.min >= 0 && spec.min_exclusive)) << "bits must be >= 1";
    }
    if (ends_with(spec.key, "_s")) {
      EXPECT_EQ(spec.unit, "s");
      EXPECT_GE(spec.min, 0.0);
    }
    for (const char* positive : {"integration_time_s", "time_constant_s", "pulse_width_s", "pulse_fwhm_s",
                                 "dead_time_s", "busy_time_s", "lsb_s", "full_range_s"}) {
      if (ends_with(spec.key, positive)) {
        EXPECT_TRUE(spec.min_exclusive) << "this time must be > 0";
      }
    }
  }
}

TEST_P(PresetTest, GridBoundsAreOrdered) {
  const ParamSet set = load_preset(GetParam());
  const std::regex min_key("^(.*)_min_([A-Za-z]+)$");
  int pairs = 0;
  for (const auto& [key, value] : set.values()) {
    std::smatch m;
    if (!std::regex_match(key, m, min_key)) continue;
    const std::string max_key = m[1].str() + "_max_" + m[2].str();
    ASSERT_TRUE(set.has(max_key)) << key << " has no matching " << max_key;
    EXPECT_LE(value.number, set.real(max_key)) << key << " > " << max_key;
    ++pairs;
    // A single-point value between the bounds, e.g. distance_m in [distance_min_m, distance_max_m].
    const std::string point_key = m[1].str() + "_" + m[2].str();
    if (set.has(point_key)) {
      EXPECT_GE(set.real(point_key), value.number) << point_key;
      EXPECT_LE(set.real(point_key), set.real(max_key)) << point_key;
    }
  }
  EXPECT_GE(pairs, 2) << "expected at least signal and background bounds";
}

TEST(Sensors, ListAndSchemasAgree) {
  ASSERT_EQ(sensors().size(), preset_ids().size());
  for (size_t i = 0; i < sensors().size(); ++i) {
    EXPECT_EQ(sensors()[i].id, preset_ids()[i]);
    EXPECT_EQ(find_sensor(preset_ids()[i]), &sensors()[i]);
    EXPECT_EQ(schema_for(preset_ids()[i], "test").sensor_id, preset_ids()[i]);
  }
  EXPECT_EQ(find_sensor("tof-nope"), nullptr);
}

TEST(Sensors, UnknownIdInSchemaForNamesTheIdAndTheChoices) {
  const std::string msg = test::user_error_of([] { schema_for("tof-nope", "somewhere.toml"); });
  EXPECT_NE(msg.find("somewhere.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tof-nope"), std::string::npos) << msg;
  for (const auto& id : preset_ids()) EXPECT_NE(msg.find(id), std::string::npos) << msg;
}

// ---- Derived numbers follow from the ones they are derived from. ----

TEST(LsDemodulationPreset, PublishedValues) {
  const ParamSet p = load_preset("ls-demodulation");
  EXPECT_DOUBLE_EQ(p.real("suppression.lpf_time_constant_s"), 1.2e-3);
  EXPECT_DOUBLE_EQ(p.real("correlator.capacitance_plus_F"), 37e-15);
  EXPECT_DOUBLE_EQ(p.real("correlator.capacitance_minus_F"), 37e-15);
  EXPECT_DOUBLE_EQ(p.real("pixel.integration_time_s"), 50e-6);
  EXPECT_DOUBLE_EQ(p.real("suppression.mirror_gain"), 1.0);
  EXPECT_DOUBLE_EQ(p.real("log_converter.gain"), 1.0);
  EXPECT_EQ(p.integer("comparator.adc_bits"), 1);
  EXPECT_DOUBLE_EQ(p.real("optics.distance_min_m"), 0.8);
  EXPECT_DOUBLE_EQ(p.real("optics.distance_max_m"), 1.2);
  // The correlation frequency is not published: its source must say so.
  EXPECT_EQ(p.at("modulation.frequency_Hz").source.rfind("assumed:", 0), 0u);
}

TEST(LsDemodulationPreset, DerivedValuesAreConsistent) {
  const ParamSet p = load_preset("ls-demodulation");
  // N = f0 x integration time (eq. 2.13).
  EXPECT_EQ(p.integer("correlator.cycles"),
            std::llround(p.real("modulation.frequency_Hz") * p.real("pixel.integration_time_s")));
  // Correlation frequency well above the LPF corner, so the LPF passes only the background.
  EXPECT_GT(p.real("modulation.frequency_Hz"), 100.0 / (2 * kPi * p.real("suppression.lpf_time_constant_s")));
  EXPECT_GE(1LL << p.integer("readout.address_bits"), p.integer("pixel.columns"));
  // Frame schedule reproduces the published 2000 fps within 1%.
  const double frame_s = p.real("pixel.integration_time_s") +
                         p.integer("pixel.rows") * p.integer("readout.row_cycles") / p.real("readout.clock_Hz");
  EXPECT_NEAR(1.0 / frame_s, 2000.0, 20.0);
  // Top of the signal grid = 1.5 V on C1 over the integration time.
  EXPECT_NEAR(p.real("evaluation.signal_max_A"),
              1.5 * p.real("correlator.capacitance_plus_F") / p.real("pixel.integration_time_s"), 1e-12);
}

TEST(TofLockinPreset, PublishedValues) {
  const ParamSet p = load_preset("tof-lockin");
  EXPECT_DOUBLE_EQ(p.real("source.pulse_width_s"), 100e-9);
  EXPECT_DOUBLE_EQ(p.real("source.duty_cycle"), 0.1);
  EXPECT_DOUBLE_EQ(p.real("source.wavelength_m"), 870e-9);
  EXPECT_DOUBLE_EQ(p.real("pixel.fd1_capacitance_F"), 10e-15);
  EXPECT_DOUBLE_EQ(p.real("pixel.fd2_capacitance_F"), 10e-15);
  EXPECT_DOUBLE_EQ(p.real("evaluation.signal_min_A"), 0.01e-9);
  EXPECT_DOUBLE_EQ(p.real("evaluation.signal_max_A"), 1.5e-9);
  // Table 5.1 disagrees with Table 4.1 on C_FD; the source note must record it.
  EXPECT_NE(p.at("pixel.fd1_capacitance_F").source.find("40 fF"), std::string::npos);
}

TEST(TofLockinPreset, DerivedValuesAreConsistent) {
  const ParamSet p = load_preset("tof-lockin");
  const double t0 = p.real("source.pulse_width_s");
  const double n = static_cast<double>(p.integer("gates.accumulations_per_frame"));
  // Unambiguous range c T0 / 2 covers the distance grid.
  EXPECT_LE(p.real("evaluation.distance_max_m"), kSpeedOfLight_m_per_s * t0 / 2);
  // Accumulation: N repetition periods of T0 / duty make the 50 us of Table 4.1.
  EXPECT_NEAR(n * t0 / p.real("source.duty_cycle"), 50e-6, 1e-12);
  // Detection threshold = charge of the smallest signal on C_FD.
  EXPECT_NEAR(p.real("readout.detection_threshold_V"),
              p.real("evaluation.signal_min_A") * t0 * n / p.real("pixel.fd1_capacitance_F"), 1e-9);
  // The largest signal (plus offset) fits in the FD swing.
  EXPECT_LT(
      p.real("evaluation.signal_max_A") * t0 * n / p.real("pixel.fd1_capacitance_F") + p.real("pixel.offset_voltage_V"),
      p.real("pixel.saturation_voltage_V"));
  // Frame schedule reproduces the published 30 fps within 1%.
  const double frame_s =
      n * t0 / p.real("source.duty_cycle") +
      p.integer("pixel.rows") *
          static_cast<double>(p.integer("readout.adc_conversion_cycles") + p.integer("readout.output_cycles_per_row")) /
          p.real("readout.clock_Hz");
  EXPECT_NEAR(1.0 / frame_s, 30.0, 0.3);
  EXPECT_EQ(p.integer("readout.output_cycles_per_row"), 2 * p.integer("pixel.columns"));
  EXPECT_EQ(p.integer("readout.adc_conversion_cycles"), 1LL << p.integer("readout.adc_bits"));
  // Gate edges fall on the gate clock grid.
  const double cycles_per_t0 = t0 * p.real("gates.clock_Hz");
  EXPECT_NEAR(cycles_per_t0, std::round(cycles_per_t0), 1e-9);
}

TEST(TofSpadPreset, TdcLsbResolvesMillimetres) {
  const ParamSet p = load_preset("tof-spad");
  const double lsb_depth_m = kSpeedOfLight_m_per_s * p.real("tdc.lsb_s") / 2;
  // Table 4.2's "90 ns" would be 13.5 m per LSB; the preset must resolve the cm scale.
  EXPECT_LT(lsb_depth_m, 0.05);
  EXPECT_NE(p.at("tdc.lsb_s").source.find("90 ns"), std::string::npos) << "source must explain the 90 ns entry";
  EXPECT_NE(p.at("tdc.lsb_s").source.find("200 ps"), std::string::npos) << "source must mention the 200 ps of the text";
}

TEST(TofSpadPreset, DerivedValuesAreConsistent) {
  const ParamSet p = load_preset("tof-spad");
  const double lsb = p.real("tdc.lsb_s");
  const double codes = std::ldexp(1.0, static_cast<int>(p.integer("tdc.bits")));
  EXPECT_LE(p.real("tdc.full_range_s"), lsb * codes * (1 + 1e-12));
  EXPECT_NEAR(p.real("tdc.full_range_s"), lsb * codes, 1e-15);
  EXPECT_EQ(p.integer("array.columns") % p.integer("tdc.columns_per_tdc"), 0);
  // The distance grid lies inside both the laser's unambiguous range and the TDC window.
  const double d_max = p.real("evaluation.distance_max_m");
  EXPECT_LT(d_max, kSpeedOfLight_m_per_s / (2 * p.real("laser.repetition_rate_Hz")));
  EXPECT_LT(d_max, kSpeedOfLight_m_per_s * p.real("tdc.full_range_s") / 2);
  // The peak window holds the IRF (at least +-2 sigma).
  const double laser_sigma = p.real("laser.pulse_fwhm_s") * p.real("laser.sigma_per_fwhm");
  const double irf_sigma = std::hypot(laser_sigma, p.real("spad.jitter_sigma_s"));
  EXPECT_GE(p.integer("histogram.peak_window_bins") * lsb, 4 * irf_sigma);
  EXPECT_DOUBLE_EQ(p.real("histogram.integration_time_s"), 50e-3);
  EXPECT_TRUE(p.boolean("histogram.coates_correction"));
}

TEST(AllPresets, SigmaPerFwhmIsTheExactGaussianFactor) {
  const double exact = 1.0 / (2.0 * std::sqrt(2.0 * std::log(2.0)));
  EXPECT_NEAR(phys::kGaussSigmaPerFwhm, exact, 1e-15);
  EXPECT_NEAR(load_preset("ls-conventional").real("spot.sigma_per_fwhm"), exact, 1e-15);
  EXPECT_NEAR(load_preset("ls-demodulation").real("spot.sigma_per_fwhm"), exact, 1e-15);
  EXPECT_NEAR(load_preset("tof-spad").real("laser.sigma_per_fwhm"), exact, 1e-15);
}

}  // namespace
}  // namespace rangesim
