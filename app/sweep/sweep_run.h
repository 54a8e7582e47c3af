#pragma once
// One row of `rangesim sweep` per architecture variant: the variant's clock-schedule rates and
// its evaluate summary, or the reason it is invalid (app/sweep/cmd_sweep.cpp). Rows round-trip
// exactly through JSON, so a journal, a shard or a merge gives output byte-identical to one run.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/params.h"

namespace rangesim::app::sweep {

struct SweepRow {
  long long index = 0;                  // variant number, from 0, in --vary order
  std::vector<std::string> assignment;  // "KEY=VALUE" of the varied keys
  bool valid = false;
  std::string reason;      // why not valid (the preset checks' message)
  nlohmann::json figures;  // frame_access_rate_Hz, range_maps_per_s, ranges, SBR', accuracy
};

// The figures of a row, in column order (sweep.csv, sweep.json), with their units in the names.
const std::vector<std::string>& figure_names();

// Evaluates one variant: the preset `base` with the variant's assignments applied.
SweepRow run_variant(const ParamSet& base, long long index, const std::vector<std::string>& assignment);

nlohmann::json row_json(const SweepRow& r);
SweepRow row_from_json(const nlohmann::json& j);

}  // namespace rangesim::app::sweep
