#include "app/montecarlo/mc_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#ifdef __linux__
#include <sys/mman.h>
#endif

namespace rangesim::app::mc {

namespace {

using Clock = std::chrono::steady_clock;

struct PointOutcome {
  McPointStats stats;
  long long trials = 0, variates = 0;
  bool finished = false;
};

long long next_trial_count(const McPointStats& s, double metres_per_unit, const McSweepOptions& opt) {
  const long long n = s.trials;
  long long want = n + opt.trials;
  const double hw = s.rms.half_width() * metres_per_unit;
  if (std::isfinite(hw) && hw > 0) {
    const double projected = static_cast<double>(n) * (hw / opt.target_error_m) * (hw / opt.target_error_m) * 1.2;
    if (projected > static_cast<double>(want)) want = static_cast<long long>(std::min(projected, 9e18));
  }
  return std::min(want, opt.max_trials);
}

// Room for a point's trial errors before the first one is written. Each 4 KB page of a fresh
// buffer costs a page fault when first touched (about 20 us on a virtual machine, more than the
// trials that fill it on a fast model); large buffers ask for transparent huge pages instead.
void reserve_trial_buffer(std::vector<double>& errors, long long trials) {
  errors.reserve(static_cast<std::size_t>(trials));
#ifdef __linux__
  constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
  const auto begin = reinterpret_cast<std::uintptr_t>(errors.data());
  const std::uintptr_t lo = (begin + kHuge - 1) & ~(kHuge - 1),
                       hi = (begin + errors.capacity() * sizeof(double)) & ~(kHuge - 1);
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);  // advice only: ignored where unsupported
#endif
}

// All trials of one point, in order; returns unfinished if the stop flag rises between trials.
PointOutcome run_point(const McModel& model, const McSweepPoint& p, const McSweepOptions& opt,
                       const std::atomic<bool>& halt) {
  PointOutcome o;
  auto runner = model.point(p.signal, p.background, point_key(opt.seed, static_cast<std::uint64_t>(p.index)));
  long long n = 0, target = std::min(opt.trials, opt.max_trials);
  std::vector<double> errors;
  // Per detected trial up to the last outlier (summarise_trials: the ones after it are clean);
  // empty while there is none, so a model without outliers never touches a page of it.
  std::vector<char> outlier;
  constexpr long long kBatch = 16;
  McTrial batch[kBatch];
  reserve_trial_buffer(errors, target);
  for (;;) {
    // In batches of kBatch trials (the runner's loop), the stop flag looked at between them.
    while (n < target) {
      if (halt.load(std::memory_order_relaxed)) return o;
      const long long m = std::min<long long>(kBatch, target - n);
      runner->trials(n, m, batch);
      for (long long i = 0; i < m; ++i) {
        if (!batch[i].detected) continue;
        errors.push_back(batch[i].error);
        if (batch[i].outlier) outlier.resize(errors.size(), 0), outlier.back() = 1;
      }
      n += m;
    }
    o.stats = summarise_trials(n, errors, outlier);
    if (opt.target_error_m <= 0 || meets_target(o.stats, model.metres_per_unit(), opt.target_error_m) ||
        n >= opt.max_trials)
      break;
    target = next_trial_count(o.stats, model.metres_per_unit(), opt);
  }
  o.trials = n;
  o.variates = runner->variates();
  o.finished = true;
  return o;
}

}  // namespace

bool meets_target(const McPointStats& s, double metres_per_unit, double target_error_m) {
  if (target_error_m <= 0) return true;
  const double hw = s.rms.half_width() * metres_per_unit;
  return std::isfinite(hw) && hw <= target_error_m;
}

McSweepResult run_mc_sweep(const McModel& model, const std::vector<McSweepPoint>& points, const McSweepOptions& opt,
                           SweepJournal* journal) {
  McSweepResult res;
  res.stats.resize(points.size());
  res.point_variates.assign(points.size(), 0);
  std::vector<std::size_t> order = opt.order;
  if (order.empty())
    for (std::size_t i = 0; i < points.size(); ++i) order.push_back(i);
  // Points finished by an earlier run come from the journal.
  std::vector<std::size_t> todo;
  for (std::size_t i : order) {
    if (journal) {
      const auto it = journal->done().find(points[i].index);
      if (it != journal->done().end()) {
        res.stats[i] = McPointStats::from_record(it->second);
        ++res.points_from_journal;
        continue;
      }
    }
    todo.push_back(i);
  }

  const auto start = Clock::now();
  // State shared with the workers lives on the heap, owned jointly: if the workers have to be
  // abandoned (see stop_grace_s) they may still touch it after this function has returned.
  struct Shared {
    std::atomic<std::size_t> next{0};
    std::atomic<long long> done{0}, trials{0}, variates{0};
    std::atomic<bool> halt{false}, counted{true};
    std::mutex mutex;
    std::condition_variable cv;
    std::exception_ptr failure;
    int running = 0;
    std::vector<std::size_t> todo;
    std::vector<std::optional<McPointStats>> stats;
    std::vector<long long> point_variates;
    std::vector<std::size_t> in_progress;  // entries of `points` being computed (under mutex)
    std::vector<double> cost;              // relative cost of each entry of `points` (McModel::relative_cost)
    double cost_done = 0;                  // relative cost of the finished points (under mutex)
    Clock::time_point last_finish;         // when the last point finished (under mutex)
  };
  auto sh = std::make_shared<Shared>();
  sh->todo = todo;
  sh->stats = res.stats;
  sh->point_variates = res.point_variates;
  sh->running = std::max(1, std::min<int>(opt.threads, static_cast<int>(std::max<std::size_t>(todo.size(), 1))));
  // The time left weighs the points by their relative cost: a sweep's cheap points may come first.
  sh->cost.assign(points.size(), 0.0);
  double cost_todo = 0;
  for (std::size_t i : todo) cost_todo += sh->cost[i] = model.relative_cost(points[i].signal, points[i].background);
  const int workers = sh->running;

  auto worker = [sh, &model, &points, &opt, journal] {
    try {
      for (;;) {
        if (sh->halt.load()) break;
        const std::size_t k = sh->next.fetch_add(1);
        if (k >= sh->todo.size()) break;
        const std::size_t i = sh->todo[k];
        {
          std::lock_guard<std::mutex> lock(sh->mutex);
          sh->in_progress.push_back(i);
        }
        PointOutcome o = run_point(model, points[i], opt, sh->halt);
        {
          std::lock_guard<std::mutex> lock(sh->mutex);
          sh->in_progress.erase(std::find(sh->in_progress.begin(), sh->in_progress.end(), i));
          if (o.finished) sh->cost_done += sh->cost[i], sh->last_finish = Clock::now();
        }
        if (!o.finished) break;
        if (journal) journal->append(points[i].index, o.stats.to_record());
        sh->stats[i] = o.stats;  // distinct element per point: no race
        sh->point_variates[i] = o.variates;
        sh->trials += o.trials;
        if (o.variates < 0)
          sh->counted = false;
        else
          sh->variates += o.variates;
        ++sh->done;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(sh->mutex);
      if (!sh->failure) sh->failure = std::current_exception();
      sh->halt = true;
    }
    std::lock_guard<std::mutex> lock(sh->mutex);
    --sh->running;
    sh->cv.notify_all();
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < workers; ++t) pool.emplace_back(worker);

  // The calling thread watches the stop flag, the time budget and reports progress.
  {
    std::unique_lock<std::mutex> lock(sh->mutex);
    auto last = Clock::now();
    double halted_at = -1;
    while (sh->running > 0) {
      sh->cv.wait_for(lock, std::chrono::milliseconds(100));
      const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
      if (opt.stop && opt.stop->load()) res.stopped = true, sh->halt = true;
      if (opt.max_seconds > 0 && elapsed > opt.max_seconds && !sh->halt) res.out_of_time = true, sh->halt = true;
      if (sh->halt && halted_at < 0) halted_at = elapsed;
      // A trial that does not return within the grace time after a stop (a kernel stuck beyond its
      // own budget): leave the workers behind; the caller must end the process at once.
      if (sh->halt && !sh->failure && halted_at >= 0 && elapsed - halted_at > opt.stop_grace_s) {
        for (auto& t : pool) t.detach();
        res.abandoned = true;
        res.stuck_points = sh->in_progress;
        std::sort(res.stuck_points.begin(), res.stuck_points.end());
        res.wall_s = elapsed;
        return res;
      }
      if (opt.progress && std::chrono::duration<double>(Clock::now() - last).count() >= opt.progress_interval_s) {
        last = Clock::now();
        const long long d = sh->done.load(), total = static_cast<long long>(todo.size());
        // The cost done took the time up to the last finish; the time since went into points still
        // running, whose share of the remaining cost is already spent. Unknown (NaN) before the first
        // finish or once a point runs past the estimate.
        const double at_last = std::chrono::duration<double>(sh->last_finish - start).count();
        const double since = elapsed - at_last;
        double left = sh->cost_done > 0 ? at_last * (cost_todo - sh->cost_done) / sh->cost_done - since : NAN;
        if (!(left > 0)) left = NAN;
        lock.unlock();
        opt.progress(d + res.points_from_journal, total + res.points_from_journal, sh->trials.load(), elapsed, left);
        lock.lock();
      }
    }
  }
  for (auto& t : pool) t.join();
  if (sh->failure) std::rethrow_exception(sh->failure);
  res.stats = std::move(sh->stats);
  res.point_variates = std::move(sh->point_variates);
  res.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  res.trials_run = sh->trials.load();
  res.variates = sh->counted ? sh->variates.load() : -1;
  res.complete = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!res.stats[i]) {
      res.complete = false;
      continue;
    }
    if (!meets_target(*res.stats[i], model.metres_per_unit(), opt.target_error_m)) {
      ++res.points_capped;
      const double hw = res.stats[i]->rms.half_width() * model.metres_per_unit();
      if (std::isfinite(hw)) res.worst_capped_half_width_m = std::max(res.worst_capped_half_width_m, hw);
    }
  }
  if (opt.progress && !todo.empty())
    opt.progress(res.points_from_journal + sh->done.load(), static_cast<long long>(points.size()), res.trials_run,
                 res.wall_s, 0);
  return res;
}

}  // namespace rangesim::app::mc
