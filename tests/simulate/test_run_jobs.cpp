// run_jobs (app/simulate/run_jobs.h): every job once on any number of threads, the first failure
// rethrown after all ran, and helpers started on a CPU other than the caller's that may then run
// on any CPU of the process's set, the caller's own set untouched. BackgroundJobs: the jobs given
// and added run once each, in order, on another thread while the caller goes on; wait() and the
// destructor run what is left on the caller and the helper and wait for them all.
#include <gtest/gtest.h>

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/simulate/run_jobs.h"

namespace {

using rangesim::app::BackgroundJobs;
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

// Spins until `flag` is set or 10 s have gone; false on the timeout.
bool await(const std::atomic<bool>& flag) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!flag)
    if (std::chrono::steady_clock::now() > until) return false;
  return true;
}

// Busy for about `ms` milliseconds of CPU.
void spin(int ms) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  volatile double x = 1;
  while (std::chrono::steady_clock::now() < until) x = x * 1.0000001;
}

TEST(BackgroundJobs, JobsRunBesideTheCallerAndWaitRunsTheRestOnBothAndRethrowsAFailure) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> first_ran{false};
  std::thread::id first_thread;
  BackgroundJobs b({[&] {
    first_thread = std::this_thread::get_id();
    first_ran = true;
  }});
  // The caller goes on while the helper runs the job it was given.
  ASSERT_TRUE(await(first_ran)) << "the first job did not run before wait()";
  EXPECT_NE(first_thread, caller);
  std::vector<std::atomic<int>> runs(12);
  std::mutex m;
  std::vector<std::thread::id> threads;
  for (std::size_t i = 0; i < runs.size(); ++i)
    b.add([&, i] {
      spin(2);  // the caller reaches wait() long before the helper could have run them all
      ++runs[i];
      {
        std::lock_guard<std::mutex> lock(m);
        threads.push_back(std::this_thread::get_id());
      }
      if (i == 5 || i == 9) throw std::runtime_error("job " + std::to_string(i));
    });
  try {
    b.wait();
    ADD_FAILURE() << "no failure rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_TRUE(std::string(e.what()) == "job 5" || std::string(e.what()) == "job 9") << e.what();
  }
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << "job " << i;
  EXPECT_NE(std::find(threads.begin(), threads.end(), caller), threads.end()) << "wait() left every job to the helper";
  EXPECT_NO_THROW(b.wait());  // the failure was handed over once
}

TEST(BackgroundJobs, TheDestructorWaitsForEveryJobAndTheHelpersCpuTimeIsCounted) {
  std::atomic<int> done{0};
  std::atomic<bool> started{false};
  {
    BackgroundJobs b({[&] {
      started = true;
      spin(20);
      ++done;
    }});
    b.add([&] { ++done; });
    b.add([] { throw std::runtime_error("dropped by the destructor"); });
    b.add([&] { ++done; });
    ASSERT_TRUE(await(started));
    const double so_far = b.cpu_s();  // while it runs
    EXPECT_GE(so_far, 0);
    EXPECT_LT(so_far, 1);
  }
  EXPECT_EQ(done.load(), 3);
  started = false;
  BackgroundJobs b({[&] {
    started = true;
    spin(20);
  }});
  ASSERT_TRUE(await(started));
  b.wait();
  EXPECT_GT(b.cpu_s(), 0.005) << "the helper's CPU time once ended";
  EXPECT_LT(b.cpu_s(), 1.0);
}

}  // namespace
