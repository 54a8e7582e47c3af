#pragma once
// Shared fixtures of the golden tests: the ls-conventional preset as a config.
#include "core/ls_conventional/config.h"
#include "core/preset.h"

namespace rangesim::golden::test {

inline LsConventionalConfig preset_config() {
  static const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  return cfg;
}

}  // namespace rangesim::golden::test
