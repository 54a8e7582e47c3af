#include "app/bench_mc.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <random>
#include <stdexcept>
#include <string>

#include "app/montecarlo/mc_sweep.h"
#include "core/preset.h"
#include "golden/ls_conventional/evaluation.h"
#include "golden/common/row_model.h"
#include "systemc/common/poisson_sampler.h"
#include "systemc/common/random_stream.h"
#include "systemc/ls_conventional/montecarlo.h"

namespace rangesim::app {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// CPU time of the whole process (all threads, finished ones included).
double process_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// A sweep on `threads` threads; `cpu_s` receives the process CPU time it took.
mc::McSweepResult timed_sweep(const mc::McModel& model, const std::vector<mc::McSweepPoint>& points,
                              mc::McSweepOptions opt, int threads, double& cpu_s) {
  opt.threads = threads;
  const double cpu0 = process_cpu_s();
  mc::McSweepResult r = mc::run_mc_sweep(model, points, opt, nullptr);
  cpu_s = process_cpu_s() - cpu0;
  return r;
}

}  // namespace

McBenchFigures measure_mc_bench(bool quick) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  const rangesim::mc::LsConventionalMc model(cfg);
  // Detectable points along the signal axis at the preset's lowest background.
  std::vector<mc::McSweepPoint> points;
  const int n_points = quick ? 8 : 16;
  const double bg = cfg.grid.background_min_V;
  for (int i = 0; points.size() < static_cast<std::size_t>(n_points) && i < 4 * n_points; ++i) {
    const double sig = 0.02 * std::pow(1.5 / 0.02, static_cast<double>(i) / (4 * n_points - 1));
    if (golden::evaluate_point(cfg, sig, bg).detect == golden::Detect::Detectable)
      points.push_back({static_cast<long long>(i), sig, bg});
  }
  if (points.empty()) throw std::runtime_error("bench_mc: no detectable point in the preset");
  mc::McSweepOptions opt;
  opt.trials = quick ? 20000 : 80000;
  opt.seed = 7;

  McBenchFigures f;
  double load[1];
  if (getloadavg(load, 1) == 1) f.load_average_1min = load[0];
  // Warm-up (page faults, caches, CPU frequency) on a tenth of the trials, not measured.
  opt.threads = 1;
  opt.trials /= 10;
  mc::run_mc_sweep(model, points, opt, nullptr);
  opt.trials *= 10;
  const mc::McSweepResult r1 = timed_sweep(model, points, opt, 1, f.sweep_1thread_cpu_s);
  f.sweep_1thread_s = r1.wall_s;
  const mc::McSweepResult r2 = timed_sweep(model, points, opt, 2, f.sweep_2threads_cpu_s);
  f.sweep_2threads_s = r2.wall_s;
  f.cpu_share_2threads = f.sweep_2threads_cpu_s / (2 * f.sweep_2threads_s);
  f.cpu_2threads_vs_1 = f.sweep_2threads_cpu_s / f.sweep_1thread_cpu_s;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (r1.stats[i]->to_record() != r2.stats[i]->to_record())
      throw std::runtime_error("bench_mc: 1- and 2-thread sweeps differ at point " + std::to_string(i));
  f.threads2_vs_1 = f.sweep_1thread_s / f.sweep_2threads_s;
  f.mc_variates_per_s = static_cast<double>(r1.variates) / f.sweep_1thread_s;

  // The bare loop: per point and trial, the same number of pixels (the sweep's count), each with
  // its own keyed stream, one kTC and one read normal (one pair) and N Poisson draws of the pixel's
  // mean per sampling interval (golden row model at a spot position drawn per trial), with the
  // pixel array's own samplers (systemc/common/poisson_sampler.h).
  const int N = cfg.multisampling.samplings;
  long long drawn = 0;
  double sink = 0;
  const auto t0 = Clock::now();
  for (std::size_t p = 0; p < points.size(); ++p) {
    const golden::RowModel row = golden::make_row_model(cfg, points[p].signal, points[p].background);
    const long long per_trial = r1.point_variates[p] / (opt.trials * (2 + N));
    const int first = row.centre_pixel - static_cast<int>(per_trial / 2);
    const std::uint64_t key = mc::point_key(opt.seed, static_cast<std::uint64_t>(points[p].index));
    for (long long t = 0; t < opt.trials; ++t) {
      const double x0 = row.centre_pixel - 0.5 + rangesim::mc::trial_uniform(key, static_cast<std::uint64_t>(t));
      for (long long j = 0; j < per_trial; ++j) {
        const int col = first + static_cast<int>(j);
        pcg32 rng = systemc::pixel_stream(
            systemc::pixel_stream_key(key, static_cast<std::uint64_t>(t), 0, static_cast<std::uint32_t>(col)));
        double ktc = 0, read = 0;
        systemc::standard_normal_pair(rng, ktc, read);
        sink += ktc + read;
        const systemc::PoissonSampler shot(golden::row_pixel_mean_electrons(row, col, x0, 1));
        for (int k = 0; k < N; ++k) sink += static_cast<double>(shot(rng));
        drawn += 2 + N;
      }
    }
  }
  const double bare_s = seconds_since(t0);
  if (!(sink == sink)) throw std::runtime_error("bench_mc: bare loop produced NaN");  // keeps the loop alive
  f.bare_variates_per_s = static_cast<double>(drawn) / bare_s;
  f.mc_vs_bare_rng = f.mc_variates_per_s / f.bare_variates_per_s;
  return f;
}

}  // namespace rangesim::app
