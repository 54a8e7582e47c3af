#pragma once
// The outputs of `rangesim sweep` from its rows (every variant, in variant order): sweep.csv,
// sweep.json, the Pareto plot of range-map rate against worst accuracy with the front marked,
// and one line plot per varied key. The same rows give the same bytes, however they were
// computed (one process, --resume, --shard + merge).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/output_dir.h"
#include "app/sweep/sweep_run.h"

namespace rangesim::app::sweep {

struct SweepHeader {
  std::string sensor, preset;         // sensor id and the preset file
  std::vector<std::string> settings;  // --set before the variants
  std::vector<std::string> keys;      // the varied keys, in --vary order
  bool zip = false;
  std::string pareto_accuracy = "accuracy_min_m";  // the accuracy axis of the Pareto front: _min_ or _max_
  VariantChecks checks = {};                       // Monte Carlo and co-simulation columns, when run
};

// Rows on the Pareto front: no other valid row has both a higher (or equal) range-map rate and a
// lower (or equal) accuracy figure `accuracy` (accuracy_min_m or accuracy_max_m), one strictly.
std::vector<bool> pareto_front(const std::vector<SweepRow>& rows, const std::string& accuracy);

std::string sweep_csv(const SweepHeader& h, const std::vector<SweepRow>& rows);
nlohmann::json sweep_json(const SweepHeader& h, const std::vector<SweepRow>& rows);
// Stages pareto.{png,svg} and <key>.{png,svg}; "" or a warning (gnuplot missing or failed).
std::string render_sweep_plots(OutputDir& out, const SweepHeader& h, const std::vector<SweepRow>& rows);
// The terminal table.
std::string sweep_text(const SweepHeader& h, const std::vector<SweepRow>& rows);

}  // namespace rangesim::app::sweep
