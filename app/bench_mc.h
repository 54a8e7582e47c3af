#pragma once
// Monte Carlo figures of `rangesim bench` (issue 6), measured in one run on an ls-conventional
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
};

// Throws std::runtime_error if the 1- and 2-thread sweeps differ in any bit.
McBenchFigures measure_mc_bench(bool quick);

}  // namespace rangesim::app
