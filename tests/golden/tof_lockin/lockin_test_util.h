#pragma once
// Shared fixtures of the tof-lockin golden tests: the preset as a ParamSet and as a config.
#include "core/preset.h"
#include "core/tof_lockin/config.h"

namespace rangesim::golden::test {

inline const ParamSet& lockin_params() {
  static const ParamSet p = load_preset("tof-lockin");
  return p;
}

inline TofLockinConfig lockin_config() {
  static const TofLockinConfig cfg = tof_lockin_from_params(lockin_params());
  return cfg;
}

}  // namespace rangesim::golden::test
