// Placeholder schema; replaced by the full schema of presets/ls-demodulation.toml.
#include "core/schemas.h"

namespace rangesim {

const ParamSchema& ls_demodulation_schema() {
  static const ParamSchema schema{"ls-demodulation", {}};
  return schema;
}

}  // namespace rangesim
