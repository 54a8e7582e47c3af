#include "app/bench/numpy_peer.h"

#include <fmt/format.h>

#include <cmath>

#include "app/bench/bench_util.h"
#include "app/sweep_journal.h"  // shell_quote
#include "core/preset.h"

namespace rangesim::app::bench {

using nlohmann::json;

FigureSpec numpy_peer_tof_lockin_figure() {
  return {"numpy_peer_lockin_mc", ">= 10",
          "NumPy peer CPU time / rangesim CPU time, tof-lockin Monte Carlo point, whole processes, equal error"};
}

// tof-lockin Monte Carlo point: `evaluate tof-lockin --trials N` at one (signal, background)
// against app/bench/peers/lockin_mc.py with the same trials.
json numpy_peer_tof_lockin(const PeerEnv& env, bool quick, const std::string& scratch) {
  const long long trials = quick ? 200000 : 1000000;
  const std::string sig = "5e-10", bg = "1e-10";
  progress(fmt::format("NumPy peer: tof-lockin Monte Carlo point, {} trials (rangesim, then NumPy)", trials));
  const ChildRun rs =
      run_json(self_command({"evaluate", "tof-lockin", "--trials", std::to_string(trials), "--signal",
                             sig + ":" + sig + ":1", "--background", bg + ":" + bg + ":1", "--threads", "1",
                             "--no-plots", "--json", "--force", "--out", scratch + "/numpy-peer-lockin"}));
  const ChildRun np = run_json(fmt::format("{} -B {} --preset {} --signal {} --background {} --trials {}",
                                           shell_quote(env.python), shell_quote(env.dir + "/lockin_mc.py"),
                                           shell_quote(resolve_preset("tof-lockin")), sig, bg, trials));
  const json& mc = rs.out["monte_carlo"];
  const double err_rs = mc["accuracy_max_m"].get<double>(), hw = mc["accuracy_ci_half_width_max_m"].get<double>();
  const double err_np = np.out["rms_error_m"].get<double>();
  // Equal error: the two rms errors are estimates of the same accuracy from the same number of
  // trials; their difference is within the 95% interval of a difference (sqrt(2) x one half-width).
  const bool agree = std::fabs(err_rs - err_np) <= std::sqrt(2.0) * hw;
  const double v = np.cpu_s / rs.cpu_s;
  json j{{"value", v},
         {"target", ">= 10"},
         {"target_met", v >= 10},
         {"trials", trials},
         {"signal_A", std::stod(sig)},
         {"background_A", std::stod(bg)},
         {"rangesim_cpu_s", rs.cpu_s},
         {"rangesim_wall_s", rs.wall_s},
         {"numpy_cpu_s", np.cpu_s},
         {"numpy_wall_s", np.wall_s},
         {"rangesim_rms_error_m", err_rs},
         {"rangesim_rms_error_ci_half_width_m", hw},
         {"numpy_rms_error_m", err_np},
         {"numpy_detected", np.out["detected"]},
         {"errors_agree", agree},
         {"rangesim", "evaluate tof-lockin --trials N --threads 1 (whole process)"},
         {"numpy", "app/bench/peers/lockin_mc.py (whole process, import included)"}};
  return j;
}

}  // namespace rangesim::app::bench
