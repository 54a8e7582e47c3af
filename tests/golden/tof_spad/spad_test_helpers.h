#pragma once
// Shared fixtures of the tof-spad golden tests: the preset's config, loaded once.
#include "core/preset.h"
#include "core/tof_spad/config.h"

namespace rangesim::golden::spad::test {

inline const ParamSet& preset_params() {
  static const ParamSet p = load_preset("tof-spad");
  return p;
}

inline TofSpadConfig preset_config() { return tof_spad_from_params(preset_params()); }

}  // namespace rangesim::golden::spad::test
