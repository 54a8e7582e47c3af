#pragma once
// What the NumPy peers share (app/bench/bench_numpy_peers.cpp): the interpreter and scripts, the
// child runs timed as whole processes; each peer is in app/bench/numpy_peer_<sensor>.cpp.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/bench_figures.h"

namespace rangesim::app::bench {

// The interpreter with NumPy and the folder of the peer scripts; why_not says why they cannot run.
struct PeerEnv {
  std::string python, dir, why_not;
};
PeerEnv peer_env();

struct ChildRun {
  nlohmann::json out;  // the JSON the child printed
  double cpu_s = 0;    // its CPU time (getrusage RUSAGE_CHILDREN), whole process
  double wall_s = 0;
};
// Runs a command line (already quoted), stdout parsed as JSON.
ChildRun run_json(const std::string& cmd);
// This executable with `args`, quoted for the shell.
std::string self_command(const std::vector<std::string>& args);
// A figure that could not be measured, with the reason.
nlohmann::json missing(const char* target, const std::string& why);

// The peers: numpy_peer_lockin_mc and numpy_peer_ls_conventional.
FigureSpec numpy_peer_tof_lockin_figure();
nlohmann::json numpy_peer_tof_lockin(const PeerEnv& env, bool quick, const std::string& scratch);
FigureSpec numpy_peer_ls_conventional_figure();
nlohmann::json numpy_peer_ls_conventional(const PeerEnv& env, const std::string& scratch);

}  // namespace rangesim::app::bench
