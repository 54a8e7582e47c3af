// Placeholder schema; replaced by the full schema of presets/tof-spad.toml.
#include "core/schemas.h"

namespace rangesim {

const ParamSchema& tof_spad_schema() {
  static const ParamSchema schema{"tof-spad", {}};
  return schema;
}

}  // namespace rangesim
