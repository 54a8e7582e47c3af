// Placeholder schema; replaced by the full schema of presets/tof-lockin.toml.
#include "core/schemas.h"

namespace rangesim {

const ParamSchema& tof_lockin_schema() {
  static const ParamSchema schema{"tof-lockin", {}};
  return schema;
}

}  // namespace rangesim
