#include "app/bench/bench_numpy_peers.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "app/bench/bench_figures.h"
#include "app/bench/bench_util.h"
#include "app/sweep_journal.h"  // shell_quote
#include "core/preset.h"

namespace rangesim::app::bench {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The interpreter with NumPy and the folder of the peer scripts; why_not says why they cannot run.
struct PeerEnv {
  std::string python, dir, why_not;
};

PeerEnv peer_env() {
  PeerEnv e;
  e.python = RANGESIM_PEER_PYTHON;
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("RANGESIM_PEER_DIR"); env && *env) dirs.emplace_back(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back(exe.parent_path().parent_path() / "share/rangesim/peers");
  dirs.emplace_back(RANGESIM_SOURCE_PEER_DIR);
  for (const auto& d : dirs)
    if (fs::is_regular_file(d / "lockin_mc.py")) {
      e.dir = d.string();
      break;
    }
  if (e.dir.empty())
    e.why_not = fmt::format("peer scripts not found ($RANGESIM_PEER_DIR, <prefix>/share/rangesim/peers, {})",
                            RANGESIM_SOURCE_PEER_DIR);
  else if (std::system(fmt::format("{} -c 'import numpy' >/dev/null 2>&1", shell_quote(e.python)).c_str()) != 0)
    e.why_not = fmt::format("{} cannot import numpy (Debian: apt-get install python3-numpy; scripts/install-deps.sh)",
                            e.python);
  return e;
}

struct ChildRun {
  json out;               // the JSON the child printed
  double cpu_s = 0;       // its CPU time (getrusage RUSAGE_CHILDREN), whole process
  double wall_s = 0;
};

// Runs a command line (already quoted), stdout parsed as JSON.
ChildRun run_json(const std::string& cmd) {
  ChildRun r;
  const auto w0 = Clock::now();
  const double c0 = children_cpu_now();
  std::fflush(stdout);
  FILE* p = ::popen((cmd + " 2>/dev/null").c_str(), "r");
  if (!p) throw std::runtime_error("bench: popen failed for " + cmd);
  std::string text;
  char buf[65536];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) text.append(buf, n);
  const int status = ::pclose(p);
  r.cpu_s = children_cpu_now() - c0;
  r.wall_s = seconds_since(w0);
  if (status != 0 || text.empty()) throw std::runtime_error(fmt::format("bench: `{}` failed (status {})", cmd, status));
  r.out = json::parse(text);
  return r;
}

std::string self_command(const std::vector<std::string>& args) {
  std::error_code ec;
  std::string cmd = shell_quote(fs::read_symlink("/proc/self/exe", ec).string());
  for (const auto& a : args) cmd += " " + shell_quote(a);
  return cmd;
}

json missing(const char* target, const std::string& why) {
  return json{{"value", nullptr}, {"target", target}, {"target_met", nullptr}, {"note", why}};
}

// tof-lockin Monte Carlo point: `evaluate tof-lockin --trials N` at one (signal, background)
// against app/bench/peers/lockin_mc.py with the same trials.
json lockin_mc(const PeerEnv& env, bool quick, const std::string& scratch) {
  const long long trials = quick ? 200000 : 1000000;
  const std::string sig = "5e-10", bg = "1e-10";
  progress(fmt::format("NumPy peer: tof-lockin Monte Carlo point, {} trials (rangesim, then NumPy)", trials));
  const ChildRun rs = run_json(self_command({"evaluate", "tof-lockin", "--trials", std::to_string(trials), "--signal",
                                             sig + ":" + sig + ":1", "--background", bg + ":" + bg + ":1",
                                             "--threads", "1", "--no-plots", "--json", "--force", "--out",
                                             scratch + "/numpy-peer-lockin"}));
  const ChildRun np =
      run_json(fmt::format("{} -B {} --preset {} --signal {} --background {} --trials {}", shell_quote(env.python),
                           shell_quote(env.dir + "/lockin_mc.py"), shell_quote(resolve_preset("tof-lockin")), sig, bg,
                           trials));
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

// The full ls-conventional map on scenes/plane.toml: `simulate ls-conventional --kernel-only`
// (its outputs included, as a user runs it) against app/bench/peers/ls_conventional_map.py (which
// saves its map too).
json ls_conventional_map(const PeerEnv& env, const std::string& scratch) {
  progress("NumPy peer: ls-conventional full map (rangesim, then NumPy)");
  const std::string scene = scene_path("plane.toml");
  const ChildRun rs = run_json(self_command({"simulate", "ls-conventional", "--scene", scene, "--kernel-only",
                                             "--no-plots", "--json", "--force", "--out",
                                             scratch + "/numpy-peer-ls-conventional"}));
  const ChildRun np = run_json(fmt::format(
      "{} -B {} --preset {} --scene {} --out {}", shell_quote(env.python),
      shell_quote(env.dir + "/ls_conventional_map.py"), shell_quote(resolve_preset("ls-conventional")),
      shell_quote(scene), shell_quote(scratch + "/numpy-peer-ls-conventional-map.npy")));
  const double err_rs = rs.out["range_error_rms_m"].get<double>(), err_np = np.out["rms_error_m"].get<double>();
  // Equal error: both are the rms over the ~134,000 visible points of one map with independent
  // noise; the rms of so many points varies by well under 1% from seed to seed.
  const bool agree = std::fabs(err_rs - err_np) <= 0.02 * err_rs &&
                     rs.out["points_detected"].get<long long>() == np.out["points_detected"].get<long long>();
  const double v = np.cpu_s / rs.cpu_s;
  return json{{"value", v},
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

}  // namespace

const std::vector<FigureSpec>& numpy_peer_figures() {
  static const std::vector<FigureSpec> f = {
      {"numpy_peer_ls_conventional", ">= 10",
       "NumPy peer CPU time / rangesim CPU time, full ls-conventional map, whole processes, equal error"},
      {"numpy_peer_lockin_mc", ">= 10",
       "NumPy peer CPU time / rangesim CPU time, tof-lockin Monte Carlo point, whole processes, equal error"},
  };
  return f;
}

json bench_numpy_peers(bool quick, const std::string& scratch_dir) {
  json out;
  const PeerEnv env = peer_env();
  if (!env.why_not.empty()) {
    out["numpy_peer_lockin_mc"] = missing(">= 10", env.why_not);
    out["numpy_peer_ls_conventional"] = missing(">= 10", env.why_not);
    return out;
  }
  out["numpy_peer_lockin_mc"] = lockin_mc(env, quick, scratch_dir);
  out["numpy_peer_ls_conventional"] = ls_conventional_map(env, scratch_dir);
  return out;
}

}  // namespace rangesim::app::bench
