#pragma once
// The scan of an evaluation grid that every sensor's golden model shares: points evaluated row by
// row (background rows in order, a block of rows at a time, shared out over the cores where the
// model allows), progress in points, the grid summary accumulated as the rows go by, and the rows
// either kept in EvalResult::points or handed to an EvalSink and dropped, so that memory stays
// bounded however large the grid (10000 x 10000 points are ~20 GB kept, a few MB streamed).
#include <cstddef>
#include <functional>
#include <vector>

#include "golden/common/evaluate_sensor.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::golden {

// Where the scan leaves the grid's detect verdicts that the ranges need.
struct GridScan {
  std::vector<bool> first_row_detectable;    // per signal value, at the lowest background
  std::vector<bool> last_column_detectable;  // per background value, at the highest signal
};

// Scans r.signal x r.background with `point(ib, is)` (which must depend on its inputs only, so the
// result is the same for any thread count); `parallel` shares each block's rows over the cores.
// Fills r.points (sink == nullptr) or feeds the sink, and the summary of summarise_points(); an
// exception from `progress` (a cancel) stops the scan after the rows in flight and is passed on.
// `observe` sees every point once, in grid order, on the calling thread (a model's own summary).
GridScan scan_grid(EvalResult& r, const std::function<EvalPoint(std::size_t ib, std::size_t is)>& point,
                   ProgressFn progress, EvalSink* sink, bool parallel,
                   const std::function<void(const EvalPoint&)>& observe = {});

}  // namespace rangesim::golden
