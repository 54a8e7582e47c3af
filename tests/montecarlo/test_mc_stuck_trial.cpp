// A trial that never returns (a kernel stuck beyond its own budget) is abandoned once the stop's
// grace time has passed: the sweep returns `abandoned`, names the stuck point, and the journal
// keeps exactly the points finished before it, from which a resumed sweep completes with the
// bits of an uninterrupted one. The stuck trial is injected by a wrapping model; it raises the
// stop flag itself, so the order of events does not depend on timing.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "app/montecarlo/mc_sweep.h"
#include "core/preset.h"
#include "golden/ls_conventional/evaluation.h"
#include "run_command.h"
#include "systemc/ls_conventional/montecarlo.h"

namespace rangesim::app::mc {
namespace {

using namespace rangesim::mc;  // the sensors' trial models (systemc/<sensor>/montecarlo.h)

// Raises `stop` (as Ctrl-C would) and then never returns; touches nothing else afterwards, so the
// abandoned thread may outlive the sweep safely.
class StuckRunner : public McPointRunner {
 public:
  explicit StuckRunner(std::atomic<bool>* stop) : stop_(stop) {}
  McTrial trial(long long) override {
    stop_->store(true);
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));
  }

 private:
  std::atomic<bool>* stop_;
};

class StuckAtModel : public McModel {
 public:
  StuckAtModel(const McModel& inner, std::uint64_t stuck_key, std::atomic<bool>* stop)
      : inner_(inner), stuck_key_(stuck_key), stop_(stop) {}
  const char* unit() const override { return inner_.unit(); }
  double metres_per_unit() const override { return inner_.metres_per_unit(); }
  std::unique_ptr<McPointRunner> point(double s, double b, std::uint64_t key) const override {
    if (key == stuck_key_) return std::make_unique<StuckRunner>(stop_);
    return inner_.point(s, b, key);
  }

 private:
  const McModel& inner_;
  std::uint64_t stuck_key_;
  std::atomic<bool>* stop_;
};

std::vector<std::string> records(const McSweepResult& r) {
  std::vector<std::string> v;
  for (const auto& s : r.stats) v.push_back(s ? s->to_record() : "missing");
  return v;
}

TEST(McStuckTrial, AbandonedAfterGraceKeepingFinishedPointsAndResumable) {
  // Heap objects never freed: the abandoned worker keeps references to them until process exit.
  const auto* model = new LsConventionalMc(ls_conventional_from_params(load_preset("ls-conventional")));
  auto* stop = new std::atomic<bool>(false);
  const auto* pts = new std::vector<McSweepPoint>{{0, 0.05, 0.003}, {1, 0.1, 0.003}, {2, 0.2, 0.003}, {3, 0.4, 0.003}};
  auto* opt = new McSweepOptions;
  opt->trials = 60;
  opt->threads = 1;  // points in order: 0, 1, 2 finish, then 3 sticks
  opt->seed = 3;
  opt->stop = stop;
  opt->stop_grace_s = 0.3;
  const auto* stuck = new StuckAtModel(*model, point_key(opt->seed, 3), stop);
  const std::string path = make_temp_dir() + "/sweep.journal";
  auto* journal = new SweepJournal(path, "stuck test", false);

  const auto t0 = std::chrono::steady_clock::now();
  const McSweepResult r = run_mc_sweep(*stuck, *pts, *opt, journal);
  const double waited_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_TRUE(r.abandoned);
  EXPECT_TRUE(r.stopped);
  EXPECT_FALSE(r.complete);
  EXPECT_EQ(r.stuck_points, std::vector<std::size_t>{3});
  EXPECT_GE(waited_s, opt->stop_grace_s);  // the grace time was granted ...
  EXPECT_LT(waited_s, 60.0);               // ... and the sweep did not hang

  // The journal holds exactly the three finished points, bit-identical to an uninterrupted run's.
  McSweepOptions plain = *opt;
  plain.stop = nullptr;
  const std::vector<std::string> full = records(run_mc_sweep(*model, *pts, plain, nullptr));
  SweepJournal reopened(path, "stuck test", true);
  ASSERT_EQ(reopened.done().size(), 3u);
  for (long long i = 0; i < 3; ++i) {
    ASSERT_EQ(reopened.done().count(i), 1u) << i;
    EXPECT_EQ(reopened.done().at(i), full[static_cast<std::size_t>(i)]) << i;
  }
  // Resuming without the stuck trial runs only point 3 and completes with the same bits.
  const McSweepResult resumed = run_mc_sweep(*model, *pts, plain, &reopened);
  EXPECT_TRUE(resumed.complete);
  EXPECT_EQ(resumed.points_from_journal, 3);
  EXPECT_EQ(resumed.trials_run, opt->trials);
  EXPECT_EQ(records(resumed), full);
}

}  // namespace
}  // namespace rangesim::app::mc
