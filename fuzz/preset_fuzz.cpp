// libFuzzer target: load_preset_text() on arbitrary bytes. Bad input of any kind must end in a
// UserError; any other exception, a crash or a sanitizer report is a finding. A preset that
// loads must hold every key of its schema, each within its allowed range.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/preset.h"
#include "core/user_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const rangesim::ParamSet set = rangesim::load_preset_text(text, "fuzz.toml");
    const rangesim::ParamSchema& schema = rangesim::schema_for(set.sensor_id(), "fuzz.toml");
    for (const auto& spec : schema.params) {
      if (!set.has(spec.key)) std::abort();
      const rangesim::ParamValue& v = set.at(spec.key);
      if (v.source.empty()) std::abort();
      if (spec.kind == rangesim::ParamKind::Real || spec.kind == rangesim::ParamKind::Integer) {
        if (!std::isfinite(v.number) || v.number > spec.max || v.number < spec.min) std::abort();
        if (spec.min_exclusive && !(v.number > spec.min)) std::abort();
      }
    }
    if (set.values().size() != schema.params.size()) std::abort();
  } catch (const rangesim::UserError&) {
    // the expected answer to bad input
  }
  return 0;
}
