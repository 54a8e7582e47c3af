#pragma once
// The NumPy peers of `rangesim bench` (docs/bench.md): what a scientist would write instead of
// rangesim, vectorised NumPy scripts of the same physics (app/bench/peers/), run as child processes
// beside rangesim at the same operating point and compared at equal error. Each figure is
// rangesim's speed / NumPy's speed, whole processes (CPU time, start-up included), with both
// errors. Without NumPy (Debian python3-numpy) the figures are null with the reason.
#include <string>

#include <nlohmann/json.hpp>

namespace rangesim::app::bench {

// Keys: numpy_peer_lockin_mc, numpy_peer_ls_conventional, each {value, target, ...details}.
nlohmann::json bench_numpy_peers(bool quick, const std::string& scratch_dir);

}  // namespace rangesim::app::bench
