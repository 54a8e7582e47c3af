#pragma once
// Shared fixtures of the tof-lockin clock-level tests: the preset with edited
// values, uniform stimuli, and the golden expectations of one pixel.
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/preset.h"
#include "core/tof_lockin/config.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::systemc::lockin::test {

struct Edit {
  std::string section, key, value;  // [section] key = { value = <value>, ... }
};

inline std::string preset_text() {
  std::ifstream f(std::string(RANGESIM_SOURCE_DIR) + "/presets/tof-lockin.toml");
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

// The preset with edits applied (value of `key` in `[section]`), validated like
// a user preset.
inline ParamSet edited_params(const std::vector<Edit>& edits) {
  std::string t = preset_text();
  for (const Edit& e : edits) {
    const std::size_t sec = t.find("[" + e.section + "]");
    const std::size_t at = t.find("\n" + e.key + " = { value = ", sec);
    const std::size_t v0 = t.find("value = ", at) + 8;
    const std::size_t v1 = t.find(',', v0);
    t.replace(v0, v1 - v0, e.value);
  }
  return load_preset_text(t, "tof-lockin(test)");
}

inline TofLockinConfig edited_config(const std::vector<Edit>& edits) {
  return tof_lockin_from_params(edited_params(edits));
}

inline std::vector<LockinPixelStimulus> uniform(int n, double signal_A, double background_A, double distance_m) {
  return std::vector<LockinPixelStimulus>(
      static_cast<std::size_t>(n), LockinPixelStimulus{signal_A, background_A, golden::round_trip_delay_s(distance_m)});
}

}  // namespace rangesim::systemc::lockin::test
