#pragma once
// What `rangesim simulate` prints for people, whatever the sensor: progress on long runs (stderr)
// and the timing/phase table with the points and the range error (the scene run's report).
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "systemc/common/simulation.h"

namespace rangesim::app {

// Progress on stderr for runs longer than a couple of seconds: at most once a second, from 2 s
// after `start` on, and at the end. `unit` names what is counted ("frame", "frame access").
class Progress {
 public:
  using Clock = std::chrono::steady_clock;
  Progress(std::string unit, long long total, Clock::time_point start, std::FILE* to = stderr);
  void operator()(long long done);
  int reports() const { return reports_; }  // lines printed so far

 private:
  std::string unit_;         // what is counted
  long long total_;          // count at the end
  Clock::time_point start_;  // start of the command
  Clock::time_point last_;   // last line printed
  std::FILE* to_;            // stream
  int reports_ = 0;          // lines printed
};

// The terminal summary of a scene run (the same layout for every sensor; times in a unit that
// fits the frame: ns, us or ms).
void print_summary(const systemc::SimulationReport& s, std::FILE* to = stdout);

}  // namespace rangesim::app
