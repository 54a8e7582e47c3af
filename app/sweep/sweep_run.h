#pragma once
// One row of `rangesim sweep` per architecture variant: the variant's clock-schedule rates and
// its evaluate summary, or the reason it is invalid (app/sweep/cmd_sweep.cpp). Rows round-trip
// exactly through JSON, so a journal, a shard or a merge gives output byte-identical to one run.
#include <nlohmann/json.hpp>
#include <cstdint>
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

// What a sweep measures beyond the clock schedule and the golden evaluation.
struct VariantChecks {
  long long trials = 0;        // > 0: Monte Carlo on the clock-level kernels at every detectable point
  std::uint64_t seed = 1;      // key of the Monte Carlo streams
  int threads = 1;             // Monte Carlo worker threads
  bool cosim = false;          // the variant's RTL against its clock-level model (verilated at run time)
  unsigned long long cosim_cycles = 20000;
  std::vector<std::string> settings;  // --set of the sweep, before the variant's keys (for the cosim child)
};

// The figures of a row, in column order (sweep.csv, sweep.json), with their units in the names;
// the Monte Carlo and co-simulation columns only when the sweep runs them.
std::vector<std::string> figure_names(const VariantChecks& checks);

// Evaluates one variant: the preset `base` with the variant's assignments applied.
SweepRow run_variant(const ParamSet& base, long long index, const std::vector<std::string>& assignment,
                     const VariantChecks& checks);

nlohmann::json row_json(const SweepRow& r, const VariantChecks& checks);
SweepRow row_from_json(const nlohmann::json& j, const VariantChecks& checks);

}  // namespace rangesim::app::sweep
