#include "app/bench/bench_numpy_peers.h"

#include "app/bench/numpy_peer.h"

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

using nlohmann::json;
namespace fs = std::filesystem;

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

const std::vector<FigureSpec>& numpy_peer_figures() {
  static const std::vector<FigureSpec> f = {numpy_peer_ls_conventional_figure(), numpy_peer_tof_lockin_figure()};
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
  out["numpy_peer_lockin_mc"] = numpy_peer_tof_lockin(env, quick, scratch_dir);
  out["numpy_peer_ls_conventional"] = numpy_peer_ls_conventional(env, scratch_dir);
  return out;
}

}  // namespace rangesim::app::bench
