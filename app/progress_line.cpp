#include "app/progress_line.h"

#include <fmt/format.h>
#include <unistd.h>

namespace rangesim::app {

ProgressLine::ProgressLine(std::string label, std::string unit, std::FILE* to)
    : label_(std::move(label)), unit_(std::move(unit)), to_(to), tty_(isatty(fileno(to)) != 0) {}

void ProgressLine::update(long long done, long long total, double left_s) {
  if (done == last_done_ && total == last_total_) return;
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const bool final = done >= total;
  if (elapsed < 1.0 && !final) return;
  const int quarter = static_cast<int>(4 * done / std::max(total, 1LL));
  if (!final && (tty_ ? now - last_ < std::chrono::milliseconds(200) : quarter == last_quarter_)) return;
  if (left_s < 0) left_s = done > 0 ? elapsed * static_cast<double>(total - done) / static_cast<double>(done) : -1;
  const std::string left = final ? "" : left_s < 0 ? ", time left unknown" : fmt::format(", ~{:.0f} s left", left_s);
  fmt::print(to_, "{}{}: {}/{} {}, {:.1f} s{}{}", tty_ ? "\r" : "", label_, done, total, unit_, elapsed, left,
             tty_ && !final ? "   " : "\n");
  std::fflush(to_);
  last_ = now, last_done_ = done, last_total_ = total, last_quarter_ = quarter;
  ++lines_;
}

}  // namespace rangesim::app
