#pragma once
// output_share of `rangesim bench` (docs/bench.md): the share of `simulate`'s wall time spent
// writing its outputs, on the full ls-conventional map of scenes/plane.toml, measured on the
// rangesim binary itself as a child process.
#include <string>

#include <nlohmann/json.hpp>

namespace rangesim::app::bench {

// {value, target, target_met} plus details: the default outputs, --no-plots and --points, each
// the medians of a few whole-process runs (wall and CPU, output and process). `scratch_dir` holds
// the runs' output folders.
nlohmann::json bench_output_share(const std::string& scratch_dir);

}  // namespace rangesim::app::bench
