#pragma once
// Aggregation figures of `rangesim bench` (docs/bench.md): frames with N identical accumulation
// cycles summed in one draw of the exact distribution of the sum, against the same frames run
// clock by clock, timed in one run and compared by a stated two-sample test (bench_stats.h).
#include <nlohmann/json.hpp>

#include "app/bench/bench_figures.h"
#include "app/bench/bench_stats.h"
#include "core/tof_spad/config.h"

namespace rangesim::app::bench {

// A two-sample comparison (bench_stats.h) as the figures' JSON block.
nlohmann::json comparison_json(const TwoSampleComparison& c);

// tof-lockin: N_acc gate periods per frame as one Poisson draw of the total mean per tap
// (LockinSimOptions::aggregate) vs every gate-clock cycle ticked (event_skipping off).
// Keys: value (per-clock time / aggregated time per frame), target, identical (test passed),
// tap statistics.
nlohmann::json bench_aggregation_lockin(bool quick);
FigureSpec aggregation_figure_lockin();

// The tof-spad preset edited to where laser cycles are independent (no afterpulse, dead time 0,
// no jitter, 20 ns TDC range, 4 ns busy, 1 ms = 40,000 laser cycles per row): tof-spad aggregation
// and the background-only class are exact there (bench_sparse_spad.h uses it too).
TofSpadConfig spad_exact_config();

// tof-spad: the L laser cycles of each TDC group as one multinomial draw (TofSpadKernelOptions::
// aggregate) vs the same frame with every TDC clock cycle ticked (event_skipping off), on the
// preset edited to where aggregation is exact (no afterpulse, dead time 0, no jitter, 20 ns TDC
// range, 4 ns busy, 1 ms integration). Keys as for lock-in; statistically_identical from the
// stated test against the per-cycle path on many groups, per_clock_equals_per_cycle from the
// timed frames.
nlohmann::json bench_aggregation_spad(bool quick);
FigureSpec aggregation_figure_spad();

// ls-demodulation: the N correlation periods of each window in one jump (DemodKernelOptions::
// aggregate) vs the same frame stepped period by period (event skipping, one exact step per
// segment), N = 10,000 periods. Keys as for lock-in; statistically_identical from the stated test
// on D (N = 20, many pixels), the noise-free identity and equal cycles.
nlohmann::json bench_aggregation_demod(bool quick);
FigureSpec aggregation_figure_demod();

}  // namespace rangesim::app::bench
