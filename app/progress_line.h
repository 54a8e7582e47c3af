#pragma once
// One progress line per update on stderr, for work counted in real units (operating points,
// variants): nothing in the first second but the final count, then on a terminal a line rewritten
// in place at most every 0.2 s, in a log (CI) a line per quarter of the work; the final count
// once; the same count never twice, however often the work reports it. The time left is the caller's estimate, or the
// elapsed time scaled by the count when it has none.
#include <chrono>
#include <cstdio>
#include <string>

namespace rangesim::app {

class ProgressLine {
 public:
  using Clock = std::chrono::steady_clock;
  // `label` starts each line ("evaluate"), `unit` follows the count ("operating points").
  ProgressLine(std::string label, std::string unit, std::FILE* to = stderr);
  void set_label(std::string label) { label_ = std::move(label); }
  // `left_s` < 0: estimate from the count.
  void update(long long done, long long total, double left_s = -1);
  int lines() const { return lines_; }  // lines printed so far

 private:
  std::string label_, unit_;
  std::FILE* to_;
  bool tty_;
  Clock::time_point start_ = Clock::now(), last_ = start_;
  long long last_done_ = -1, last_total_ = -1;
  int last_quarter_ = -1;
  int lines_ = 0;
};

}  // namespace rangesim::app
