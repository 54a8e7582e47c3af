#pragma once
// The variants of `rangesim sweep`: each `--vary KEY=SPEC` gives a key and its values, either a
// list `v1,v2,...` or a range `LO:HI:N` (linear) / `LO:HI:N:log` (log-spaced); the variants are
// the cross product of the keys' values (first --vary outermost), or with --zip the i-th value
// of every key together (all lists of one length). A variant is a list of KEY=VALUE assignments,
// applied after the preset like --set.
#include <string>
#include <vector>

#include "core/params.h"

namespace rangesim::app::sweep {

struct VaryAxis {
  std::string key;                  // schema key
  std::vector<std::string> values;  // as text, ready for ParamSet::set_from_text
};

// Parses one --vary argument against the sensor's schema; UserError (exit 2) naming the flag,
// the key and the allowed form or range. Integer keys take the nearest integers of a range,
// each once.
VaryAxis parse_vary(const std::string& spec, const ParamSchema& schema);

// The variants, each a list of "KEY=VALUE". UserError when --zip axes differ in length or the
// product exceeds `max_variants`.
std::vector<std::vector<std::string>> variants(const std::vector<VaryAxis>& axes, bool zip, long long max_variants);

}  // namespace rangesim::app::sweep
