#include "golden/common/grid_scan.h"

#include <algorithm>
#include <atomic>
#include <iterator>
#include <thread>

namespace rangesim::golden {

namespace {

// Points evaluated before a block is handed on: bounds the memory of a streamed scan (~200 bytes a
// point with its metrics) while keeping the cores busy on rows of any length.
constexpr std::size_t kBlockPoints = 1 << 16;

}  // namespace

GridScan scan_grid(EvalResult& r, const std::function<EvalPoint(std::size_t ib, std::size_t is)>& point,
                   ProgressFn progress, EvalSink* sink, bool parallel,
                   const std::function<void(const EvalPoint&)>& observe) {
  const std::size_t ns = r.signal.values.size(), nb = r.background.values.size();
  GridScan g;
  g.first_row_detectable.assign(ns, false);
  g.last_column_detectable.assign(nb, false);
  PointSummary summary;
  if (sink)
    sink->begin(r);
  else
    r.points.reserve(ns * nb);
  const std::size_t block_rows = std::max<std::size_t>(1, kBlockPoints / std::max<std::size_t>(ns, 1));
  const unsigned cores = parallel ? std::max(1u, std::thread::hardware_concurrency()) : 1u;
  std::vector<std::vector<EvalPoint>> block(std::min(block_rows, nb));
  for (std::size_t b0 = 0; b0 < nb; b0 += block_rows) {
    const std::size_t rows = std::min(block_rows, nb - b0), points = rows * ns;
    for (std::size_t k = 0; k < rows; ++k) block[k].resize(ns);
    // Points, not rows, are handed out and reported: one point can cost up to a second (an adaptive
    // average over spot positions), so a cancel is seen, and the workers stop, within a point.
    std::atomic<std::size_t> next{0}, done{0};
    auto work = [&](bool report) {
      for (std::size_t k; (k = next.fetch_add(1)) < points;) {
        block[k / ns][k % ns] = point(b0 + k / ns, k % ns);
        const std::size_t d = done.fetch_add(1) + 1;
        if (report && progress) progress(static_cast<int>(b0 * ns + d), static_cast<int>(nb * ns));
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < std::min<std::size_t>(cores, points); ++t) pool.emplace_back(work, false);
    try {
      work(true);  // only the calling thread reports
    } catch (...) {  // the progress callback cancelled the run: hand out nothing more, join, pass it on
      next.store(points);
      for (auto& t : pool) t.join();
      throw;
    }
    for (auto& t : pool) t.join();
    for (std::size_t k = 0; k < rows; ++k) {
      const std::size_t ib = b0 + k;
      for (const auto& p : block[k]) {
        summary.add(p);
        if (observe) observe(p);
      }
      for (std::size_t is = 0; ib == 0 && is < ns; ++is)
        g.first_row_detectable[is] = block[k][is].detect == "detectable";
      g.last_column_detectable[ib] = ns > 0 && block[k].back().detect == "detectable";
      if (sink)
        sink->row(ib, block[k]);
      else
        std::move(block[k].begin(), block[k].end(), std::back_inserter(r.points));
    }
  }
  if (progress) progress(static_cast<int>(nb * ns), static_cast<int>(nb * ns));
  summary.into(r);
  return g;
}

}  // namespace rangesim::golden
