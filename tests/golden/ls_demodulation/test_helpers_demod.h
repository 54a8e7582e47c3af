#pragma once
// Shared helpers of the ls-demodulation golden tests.
#include "core/ls_demodulation/config.h"
#include "core/preset.h"

namespace rangesim::test {

inline const ParamSet& demod_params() {
  static const ParamSet p = load_preset("ls-demodulation");
  return p;
}
inline LsDemodulationConfig demod_cfg() { return ls_demodulation_from_params(demod_params()); }

}  // namespace rangesim::test
