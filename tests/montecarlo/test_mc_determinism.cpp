// A Monte Carlo sweep is bit-identical for any thread count and any order of the points, with and
// without a target error; the trial budget is honoured; a journal makes a second run reuse points.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "app/montecarlo/mc_sweep.h"
#include "core/preset.h"
#include "golden/ls_conventional/evaluation.h"
#include "run_command.h"
#include "systemc/ls_conventional/montecarlo.h"

namespace rangesim::app::mc {
namespace {

using namespace rangesim::mc;  // the sensors' trial models (systemc/<sensor>/montecarlo.h)

std::vector<McSweepPoint> grid(const LsConventionalConfig& cfg) {
  std::vector<McSweepPoint> pts;
  long long index = 0;
  for (double bg : {0.002, 0.01})
    for (double sig : {0.03, 0.06, 0.12, 0.25, 0.5}) {
      if (golden::evaluate_point(cfg, sig, bg).detect == golden::Detect::Detectable) pts.push_back({index, sig, bg});
      ++index;
    }
  return pts;
}

std::vector<std::string> records(const McSweepResult& r) {
  std::vector<std::string> v;
  for (const auto& s : r.stats) v.push_back(s ? s->to_record() : "missing");
  return v;
}

TEST(McDeterminism, ThreadsAndOrderDoNotChangeAnyBit) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  const LsConventionalMc model(cfg);
  const auto pts = grid(cfg);
  ASSERT_GE(pts.size(), 6u);
  McSweepOptions o;
  o.trials = 150;
  o.threads = 1;
  const auto one = records(run_mc_sweep(model, pts, o, nullptr));
  o.threads = 2;
  EXPECT_EQ(records(run_mc_sweep(model, pts, o, nullptr)), one);
  o.threads = 3;
  o.order.resize(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) o.order[i] = i;
  std::shuffle(o.order.begin(), o.order.end(), std::mt19937(42));
  EXPECT_EQ(records(run_mc_sweep(model, pts, o, nullptr)), one);
  std::reverse(o.order.begin(), o.order.end());
  o.threads = 2;
  EXPECT_EQ(records(run_mc_sweep(model, pts, o, nullptr)), one);
  // Another seed gives other bits.
  o.seed = 2;
  EXPECT_NE(records(run_mc_sweep(model, pts, o, nullptr)), one);
}

TEST(McDeterminism, TargetErrorIsMetOrCappedIdenticallyOnAnyThreadCount) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  const LsConventionalMc model(cfg);
  const auto pts = grid(cfg);
  McSweepOptions o;
  o.trials = 50;
  o.target_error_m = 2e-4;
  o.max_trials = 3000;
  o.threads = 1;
  const McSweepResult a = run_mc_sweep(model, pts, o, nullptr);
  o.threads = 2;
  const McSweepResult b = run_mc_sweep(model, pts, o, nullptr);
  EXPECT_EQ(records(a), records(b));
  long long more = 0;
  for (const auto& s : a.stats) {
    ASSERT_TRUE(s);
    EXPECT_LE(s->trials, o.max_trials);
    more += s->trials > o.trials;
    if (meets_target(*s, model.metres_per_unit(), o.target_error_m)) continue;
    EXPECT_EQ(s->trials, o.max_trials);  // only the cap stops a point short of the target
  }
  EXPECT_GT(more, 0);  // the target did add trials
  EXPECT_EQ(a.points_capped, b.points_capped);
}

TEST(McDeterminism, JournalledPointsAreNotRerun) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  const LsConventionalMc model(cfg);
  const auto pts = grid(cfg);
  McSweepOptions o;
  o.trials = 100;
  o.threads = 2;
  const std::string path = make_temp_dir() + "/sweep.journal";
  std::vector<std::string> first;
  {
    SweepJournal j(path, "test", false);
    first = records(run_mc_sweep(model, pts, o, &j));
  }
  SweepJournal j(path, "test", true);
  EXPECT_EQ(j.done().size(), pts.size());
  const McSweepResult again = run_mc_sweep(model, pts, o, &j);
  EXPECT_EQ(again.points_from_journal, static_cast<long long>(pts.size()));
  EXPECT_EQ(again.trials_run, 0);
  EXPECT_EQ(records(again), first);
}

}  // namespace
}  // namespace rangesim::app::mc
