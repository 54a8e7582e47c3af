#include "app/simulate/run_jobs.h"

#include <pthread.h>
#include <sched.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <utility>

namespace rangesim::app {

namespace {

// The CPUs a helper may start on: the process's set without the caller's CPU (empty when the set
// is unknown or has only that CPU).
std::vector<int> other_cpus(cpu_set_t& all) {
  std::vector<int> cpus;
  CPU_ZERO(&all);
  if (::sched_getaffinity(0, sizeof all, &all) != 0) return cpus;
  const int here = ::sched_getcpu();
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (c != here && CPU_ISSET(c, &all)) cpus.push_back(c);
  return cpus;
}

struct Helper {
  const std::function<void()>* work;
  cpu_set_t all;  // what it may run on once started
  bool pinned;    // started on one CPU: allow it `all` first
};

extern "C" void* helper_main(void* arg) {
  const auto* h = static_cast<const Helper*>(arg);
  if (h->pinned) ::pthread_setaffinity_np(::pthread_self(), sizeof h->all, &h->all);
  (*h->work)();  // catches every job's failure itself
  return nullptr;
}

// Starts helper `h` on `cpu` (-1: wherever the scheduler puts it). The CPU is set in the thread's
// attributes, so it holds from its first instruction (set afterwards, on a thread that had
// already ended, it would land on the caller). False when no thread could be made.
bool start(Helper& h, int cpu, pthread_t& thread) {
  pthread_attr_t attr;
  if (::pthread_attr_init(&attr) != 0) return false;
  h.pinned = false;
  if (cpu >= 0) {
    cpu_set_t one;
    CPU_ZERO(&one);
    CPU_SET(cpu, &one);
    h.pinned = ::pthread_attr_setaffinity_np(&attr, sizeof one, &one) == 0;
  }
  bool ok = ::pthread_create(&thread, &attr, helper_main, &h) == 0;
  if (!ok && h.pinned) {  // a CPU the system refuses: start it anywhere
    h.pinned = false;
    ok = ::pthread_create(&thread, nullptr, helper_main, &h) == 0;
  }
  ::pthread_attr_destroy(&attr);
  return ok;
}

double cpu_clock_s(clockid_t clock) {
  timespec t{};
  if (::clock_gettime(clock, &t) != 0) return -1;
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

struct BackgroundJobs::State {
  std::mutex m;
  std::condition_variable more;
  std::deque<std::function<void()>> queue;  // under m
  bool closed = false;                      // under m: no job comes after those queued
  std::exception_ptr failure;
  std::function<void()> work;
  Helper helper{};
  pthread_t thread{};
  bool running = false;                // a helper was started and not yet joined
  std::atomic<bool> ended{false};      // the helper has set total_cpu_s
  std::atomic<double> total_cpu_s{0};  // the jobs' CPU, once they have run

  // Queued jobs until the queue is closed and empty (false: return once it is empty).
  void run_queued(bool until_closed) {
    for (;;) {
      std::function<void()> job;
      {
        std::unique_lock<std::mutex> lock(m);
        if (until_closed) more.wait(lock, [&] { return closed || !queue.empty(); });
        if (queue.empty()) return;
        job = std::move(queue.front());
        queue.pop_front();
      }
      try {
        job();
      } catch (...) {
        std::lock_guard<std::mutex> lock(m);
        if (!failure) failure = std::current_exception();
      }
    }
  }
  // The helper's life.
  void run_all() {
    const double start = cpu_clock_s(CLOCK_THREAD_CPUTIME_ID);
    run_queued(true);
    total_cpu_s = cpu_clock_s(CLOCK_THREAD_CPUTIME_ID) - start;
    ended = true;
  }
  void close() {
    {
      std::lock_guard<std::mutex> lock(m);
      closed = true;
    }
    more.notify_one();
  }
};

BackgroundJobs::BackgroundJobs(std::vector<std::function<void()>> jobs) : s_(std::make_unique<State>()) {
  State& s = *s_;
  for (auto& job : jobs) s.queue.push_back(std::move(job));
  s.work = [&s] { s.run_all(); };
  cpu_set_t all;
  const std::vector<int> cpus = other_cpus(all);
  s.helper = Helper{&s.work, all, false};
  s.running = start(s.helper, cpus.empty() ? -1 : cpus.front(), s.thread);
}

BackgroundJobs::~BackgroundJobs() {
  try {
    wait();
  } catch (...) {  // the caller is already failing, or never asked
  }
}

void BackgroundJobs::add(std::function<void()> job) {
  {
    std::lock_guard<std::mutex> lock(s_->m);
    s_->queue.push_back(std::move(job));
  }
  s_->more.notify_one();
}

void BackgroundJobs::wait() {
  s_->close();
  s_->run_queued(false);  // beside the helper, or alone where none could be made
  if (s_->running) ::pthread_join(s_->thread, nullptr);
  s_->running = false;
  if (s_->failure) std::rethrow_exception(std::exchange(s_->failure, nullptr));
}

double BackgroundJobs::cpu_s() const {
  if (!s_->ended && s_->running) {
    clockid_t clock;
    if (::pthread_getcpuclockid(s_->thread, &clock) == 0)
      if (const double now = cpu_clock_s(clock); now >= 0 && !s_->ended) return now;
  }
  return s_->ended ? s_->total_cpu_s.load() : 0.0;
}

void run_jobs(const std::vector<std::function<void()>>& jobs, int threads) {
  std::atomic<std::size_t> next{0};
  std::vector<std::exception_ptr> failures(jobs.size());
  const std::function<void()> work = [&] {
    for (std::size_t i; (i = next++) < jobs.size();) {
      try {
        jobs[i]();
      } catch (...) {
        failures[i] = std::current_exception();
      }
    }
  };
  const std::size_t helper_count = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), jobs.size());
  cpu_set_t all;
  CPU_ZERO(&all);
  const std::vector<int> cpus = helper_count > 1 ? other_cpus(all) : std::vector<int>{};
  std::vector<Helper> helpers(helper_count > 1 ? helper_count - 1 : 0, Helper{&work, all, false});
  std::vector<pthread_t> started;
  for (std::size_t t = 0; t < helpers.size(); ++t) {
    pthread_t thread;
    if (start(helpers[t], cpus.empty() ? -1 : cpus[t % cpus.size()], thread)) started.push_back(thread);
  }
  work();  // with no helper (none could be made), the caller runs every job
  for (const pthread_t& thread : started) ::pthread_join(thread, nullptr);
  for (const std::exception_ptr& f : failures)
    if (f) std::rethrow_exception(f);
}

}  // namespace rangesim::app
