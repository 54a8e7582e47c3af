#include "app/simulate/simulate_report.h"

#include <cmath>
#include <fmt/format.h>

namespace rangesim::app {

Progress::Progress(std::string unit, long long total, Clock::time_point start, std::FILE* to)
    : unit_(std::move(unit)), total_(total), start_(start), last_(start), to_(to) {}

void Progress::operator()(long long done) {
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed <= 2.0) return;
  if (std::chrono::duration<double>(now - last_).count() <= 1.0 && done != total_) return;
  fmt::print(to_, "simulate: {} {}/{} ({:.0f}%), {:.1f} s\n", unit_, done, total_,
             total_ > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0, elapsed);
  std::fflush(to_);
  last_ = now;
  ++reports_;
}

namespace {

// A time unit that suits `t_s` for the table: scale and name.
std::pair<double, const char*> time_unit(double t_s) {
  if (t_s < 1e-5) return {1e9, "ns"};
  if (t_s < 1e-2) return {1e6, "us"};
  return {1e3, "ms"};
}

std::string rate_text(double hz) {
  if (hz >= 1e6) return fmt::format("{:.4f} MHz", hz / 1e6);
  if (hz >= 1e3) return fmt::format("{:.3f} kHz", hz / 1e3);
  return fmt::format("{:.4f} Hz", hz);
}

}  // namespace

void print_summary(const systemc::SimulationReport& s, std::FILE* to) {
  fmt::print(to, "{}\n\n", s.headline);
  const auto [scale, unit] = time_unit(s.golden_frame_time_s);
  fmt::print(to, "  {:<18} {:>10} {:>10} {:>14}\n", "phase", "cycles", "golden", "time");
  for (const auto& p : s.phases)
    fmt::print(to, "  {:<18} {:>10} {:>10} {:>11.3f} {}\n", p["name"].get<std::string>(), p["cycles"].get<long long>(),
               p["golden_cycles"].get<long long>(), p["time_s"].get<double>() * scale, unit);
  fmt::print(to, "  {:<18} {:>10} {:>10}\n\n", s.frame_label, s.frame_cycles, s.golden_frame_cycles);
  fmt::print(to, "  frame time       {:>14.4f} {} measured, {:.4f} {} golden{}\n", s.frame_time_s * scale, unit,
             s.golden_frame_time_s * scale, unit, s.timing_matches ? "" : "  (MISMATCH)");
  fmt::print(to, "  frame rate       {:>17} measured, {} golden\n", rate_text(s.frame_rate_Hz),
             rate_text(s.golden_frame_rate_Hz));
  fmt::print(to, "  range maps       {:>14.4f} /s ({} {}{} each)\n\n", s.range_maps_per_s, s.frames_per_range_map,
             s.frame_label,
             s.frames_per_range_map == 1   ? ""
             : s.frame_label.back() == 's' ? "es"
                                           : "s");
  fmt::print(to, "  {}\n", s.points_line);
  if (s.error.detected) {
    const std::string px = s.error_in_px ? fmt::format(" ({:.4f} px)", s.error.rms_px()) : "";
    fmt::print(to, "  range error      rms {:.3f} mm{}, mean {:+.3f} mm, max |e| {:.3f} mm{}\n", s.error.rms_m() * 1e3,
               px, s.error.mean_m() * 1e3, s.error.max_abs_m * 1e3, s.error_note.empty() ? "" : " " + s.error_note);
  }
  fmt::print(to, "  wall time        {:.2f} s{}\n\n", s.wall_time_s, s.wall_note.empty() ? "" : ", " + s.wall_note);
}

}  // namespace rangesim::app
