#pragma once
// Shared set-up of the tof-spad clock-level tests: the preset with overrides.
#include <cstdint>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "core/params.h"
#include "core/preset.h"
#include "core/tof_spad/config.h"
#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::systemc::spad::test {

// Noise key of the statistical tests: 1, or RANGESIM_TEST_SEED to re-run them on other draws.
inline std::uint64_t test_seed() {
  const char* s = std::getenv("RANGESIM_TEST_SEED");
  return s ? std::strtoull(s, nullptr, 10) : 1;
}

inline ParamSet preset() { return load_preset_file(std::string(RANGESIM_SOURCE_DIR) + "/presets/tof-spad.toml"); }

// The preset with a shorter integration and fewer rows (timing tests stay fast).
inline ParamSet small_preset(double integration_s, long long rows) {
  ParamSet p = preset();
  const ParamSchema& s = schema_for("tof-spad", "test");
  p.set_real("histogram.integration_time_s", integration_s, "test", s);
  p.set_integer("array.rows", rows, "test", s);
  return p;
}

inline RateSource flat(double signal_Hz, double background_Hz, double round_trip_s) {
  return [=](int, int) { return PixelRates{signal_Hz, background_Hz, round_trip_s}; };
}

// Two histogram memories equal field by field (each field its own failure message).
inline void expect_same_histogram(const GroupHistogram& a, const GroupHistogram& b) {
  EXPECT_EQ(a.events, b.events);
  EXPECT_EQ(a.armed, b.armed);
  EXPECT_EQ(a.starts, b.starts);
  EXPECT_EQ(a.overflows, b.overflows);
  EXPECT_EQ(a.lost_busy, b.lost_busy);
  EXPECT_EQ(a.avalanches, b.avalanches);
  EXPECT_EQ(a.photons, b.photons);
}

}  // namespace rangesim::systemc::spad::test
