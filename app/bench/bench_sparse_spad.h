#pragma once
// tof-spad sparse pixels in `rangesim bench` (docs/bench.md, `sparse_vs_dense_spad`): a frame of
// a beam spot on an array whose other pixels see background only, with background-only TDC
// groups drawn as one class (TofSpadKernelOptions::sparse) against every group simulated cycle by
// cycle (dense), timed in one run and compared: lit pixels bit-identical, frame cycles identical,
// background-only pixels by the stated two-sample test (bench_stats.h).
#include <nlohmann/json.hpp>

namespace rangesim::app::bench {

// Keys: value (dense CPU time / sparse CPU time per frame), target, checks (cycles_identical,
// lit_pixels_identical, background_statistically_identical) and their details.
nlohmann::json bench_sparse_spad(bool quick);

}  // namespace rangesim::app::bench
