#pragma once
// Monte Carlo figures of `rangesim bench`, measured in one run on an ls-conventional
// sweep of detectable grid points (the full sensor kernel, one row, noise on):
//   mc_vs_bare_rng   random variates per second consumed by the Monte Carlo sweep on 1 thread over
//                    those of a bare loop drawing the same variates (same streams, distributions
//                    and means: per simulated pixel and trial one kTC and one read normal and one
//                    Poisson per sampling); target >= 0.5;
//   threads2_vs_1    sweep speed on 2 threads over 1 (same sweep, results checked bit-identical);
//                    target >= 1.8.
// quick: 8 points x 20000 trials (a few seconds); otherwise 16 x 80000 (about 8x the work).
namespace rangesim::app {

struct McBenchFigures {
  double mc_vs_bare_rng = 0;       // mc_variates_per_s / bare_variates_per_s
  double threads2_vs_1 = 0;        // sweep_1thread_s / sweep_2threads_s
  double mc_variates_per_s = 0;    // variates drawn by the sweep per second (1 thread)
  double bare_variates_per_s = 0;  // variates drawn by the bare loop per second
  double sweep_1thread_s = 0;      // wall time of the sweep on 1 thread
  double sweep_2threads_s = 0;     // wall time of the same sweep on 2 threads
  // Why threads2_vs_1 falls short of 2, apart: the process CPU time of each sweep; cpu_share_2threads
  // = sweep_2threads_cpu_s / (2 sweep_2threads_s) is ~1 when the machine gave the sweep two cores
  // throughout (lower: other load, or workers idle at the end); cpu_2threads_vs_1 = CPU time on 2
  // threads over 1 is ~1 unless the threads slow each other down (caches, allocator, SMT siblings).
  double sweep_1thread_cpu_s = 0, sweep_2threads_cpu_s = 0;
  double cpu_share_2threads = 0, cpu_2threads_vs_1 = 0;
  double load_average_1min = -1;  // of the machine just before the sweeps (-1: unknown)
};

// Throws std::runtime_error if the 1- and 2-thread sweeps differ in any bit.
McBenchFigures measure_mc_bench(bool quick);

}  // namespace rangesim::app
