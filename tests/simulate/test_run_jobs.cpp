// run_jobs (app/simulate/run_jobs.h): every job once on any number of threads, the first failure
// rethrown after all ran, and helpers started on a CPU other than the caller's that may then run
// on any CPU of the process's set, the caller's own set untouched.
#include <gtest/gtest.h>

#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "app/simulate/run_jobs.h"

namespace {

using rangesim::app::run_jobs;

// The CPUs the calling thread may run on.
cpu_set_t own_cpus() {
  cpu_set_t s;
  CPU_ZERO(&s);
  ::sched_getaffinity(0, sizeof s, &s);
  return s;
}

TEST(RunJobs, EveryJobRunsOnceAndTheFirstFailureIsRethrownAfterAll) {
  const cpu_set_t before = own_cpus();
  for (const int threads : {0, 1, 2, 8}) {
    std::vector<std::atomic<int>> runs(13);
    std::vector<std::function<void()>> jobs;
    for (std::size_t i = 0; i < runs.size(); ++i)
      jobs.emplace_back([&runs, i] {
        ++runs[i];
        if (i == 4 || i == 9) throw std::runtime_error("job " + std::to_string(i));
      });
    try {
      run_jobs(jobs, threads);
      ADD_FAILURE() << "no failure rethrown with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "job 4") << threads << " threads";
    }
    for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << "job " << i << ", " << threads;
    // Helpers that end before the caller is done starting the others must not pass their CPU on to it.
    const cpu_set_t after = own_cpus();
    EXPECT_TRUE(CPU_EQUAL(&after, &before)) << threads << " threads: the caller's own CPUs changed";
  }
}

TEST(RunJobs, AHelperStartsOnAnotherCpuAndMayThenRunOnAny) {
  cpu_set_t all;
  CPU_ZERO(&all);
  ASSERT_EQ(::sched_getaffinity(0, sizeof all, &all), 0);
  if (CPU_COUNT(&all) < 2) GTEST_SKIP() << "one CPU: nowhere else to start";
  std::mutex m;
  std::vector<int> helper_cpus;
  std::vector<cpu_set_t> helper_sets;
  const std::thread::id caller = std::this_thread::get_id();
  for (int round = 0; round < 20; ++round) {
    const int here = ::sched_getcpu();
    std::atomic<bool> helper_ran{false};
    // The caller holds its first job until a helper has run one, so that one runs on a helper.
    std::vector<std::function<void()>> jobs(2, [&] {
      if (std::this_thread::get_id() == caller) {
        while (!helper_ran) std::this_thread::yield();
        return;
      }
      const int cpu = ::sched_getcpu();
      cpu_set_t mine;
      CPU_ZERO(&mine);
      ::pthread_getaffinity_np(::pthread_self(), sizeof mine, &mine);
      std::lock_guard<std::mutex> lock(m);
      if (helper_ran) return;  // the helper took both jobs: its first one counts
      helper_cpus.push_back(cpu == here ? -1 : 1);
      helper_sets.push_back(mine);
      helper_ran = true;
    });
    run_jobs(jobs, 2);
    const cpu_set_t after = own_cpus();
    EXPECT_TRUE(CPU_EQUAL(&after, &all)) << "round " << round << ": the caller's own CPUs changed";
  }
  ASSERT_EQ(helper_cpus.size(), 20u);
  for (std::size_t i = 0; i < helper_cpus.size(); ++i) {
    EXPECT_EQ(helper_cpus[i], 1) << "round " << i << ": the helper began on the caller's CPU";
    EXPECT_TRUE(CPU_EQUAL(&helper_sets[i], &all)) << "round " << i << ": the helper stays pinned";
  }
}

}  // namespace
