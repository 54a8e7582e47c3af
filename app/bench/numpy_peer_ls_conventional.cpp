#include "app/bench/numpy_peer.h"

#include <fmt/format.h>

#include <cmath>

#include "app/bench/bench_util.h"
#include "app/sweep_journal.h"  // shell_quote
#include "core/preset.h"

namespace rangesim::app::bench {

using nlohmann::json;

FigureSpec numpy_peer_ls_conventional_figure() {
  return {"numpy_peer_ls_conventional", ">= 10",
          "NumPy peer CPU time / rangesim CPU time, full ls-conventional map, whole processes, equal error"};
}

// The full ls-conventional map on scenes/plane.toml: `simulate ls-conventional --kernel-only`
// (its outputs included, as a user runs it) against app/bench/peers/ls_conventional_map.py (which
// saves its map too).
json numpy_peer_ls_conventional(const PeerEnv& env, const std::string& scratch) {
  progress("NumPy peer: ls-conventional full map (rangesim, then NumPy)");
  const std::string scene = scene_path("plane.toml");
  const ChildRun rs =
      run_json(self_command({"simulate", "ls-conventional", "--scene", scene, "--kernel-only", "--no-plots", "--json",
                             "--force", "--out", scratch + "/numpy-peer-ls-conventional"}));
  const ChildRun np = run_json(fmt::format("{} -B {} --preset {} --scene {} --out {}", shell_quote(env.python),
                                           shell_quote(env.dir + "/ls_conventional_map.py"),
                                           shell_quote(resolve_preset("ls-conventional")), shell_quote(scene),
                                           shell_quote(scratch + "/numpy-peer-ls-conventional-map.npy")));
  const double err_rs = rs.out["range_error_rms_m"].get<double>(), err_np = np.out["rms_error_m"].get<double>();
  // Equal error: both are the rms over the ~134,000 visible points of one map with independent
  // noise; the rms of so many points varies by well under 1% from seed to seed.
  const bool agree = std::fabs(err_rs - err_np) <= 0.02 * err_rs &&
                     rs.out["points_detected"].get<long long>() == np.out["points_detected"].get<long long>();
  const double v = np.cpu_s / rs.cpu_s;
  return json{
      {"value", v},
      {"target", ">= 10"},
      {"target_met", v >= 10},
      {"rangesim_cpu_s", rs.cpu_s},
      {"rangesim_wall_s", rs.wall_s},
      {"numpy_cpu_s", np.cpu_s},
      {"numpy_wall_s", np.wall_s},
      {"rangesim_rms_error_m", err_rs},
      {"numpy_rms_error_m", err_np},
      {"rangesim_points_detected", rs.out["points_detected"]},
      {"numpy_points_detected", np.out["points_detected"]},
      {"numpy_window_px", np.out["window_px"]},
      {"errors_agree", agree},
      {"rangesim", "simulate ls-conventional --scene scenes/plane.toml --kernel-only --no-plots (whole process)"},
      {"numpy", "app/bench/peers/ls_conventional_map.py (whole process, import included)"}};
}

}  // namespace rangesim::app::bench
