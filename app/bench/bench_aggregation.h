#pragma once
// Aggregation figures of `rangesim bench` (docs/bench.md): frames with N identical accumulation
// cycles summed in one draw of the exact distribution of the sum, against the same frames run
// clock by clock, timed in one run and compared by a stated two-sample test (bench_stats.h).
#include <nlohmann/json.hpp>

namespace rangesim::app::bench {

// tof-lockin: N_acc gate periods per frame as one Poisson draw of the total mean per tap
// (LockinSimOptions::aggregate) vs every gate-clock cycle ticked (event_skipping off).
// Keys: value (per-clock time / aggregated time per frame), target, identical (test passed),
// tap statistics.
nlohmann::json bench_aggregation_lockin(bool quick);

}  // namespace rangesim::app::bench
