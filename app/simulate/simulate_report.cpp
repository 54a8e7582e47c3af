#include "app/simulate/simulate_report.h"

#include <cmath>
#include <fmt/format.h>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "app/simulate/simulate_output.h"

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

double RangeErrorStats::rms_m() const { return detected ? std::sqrt(sum_sq_m / detected) : NAN; }
double RangeErrorStats::rms_px() const { return detected ? std::sqrt(sum_sq_px / detected) : NAN; }
double RangeErrorStats::mean_m() const { return detected ? sum_m / detected : NAN; }

void RangeErrorStats::to_json(nlohmann::json& j, bool with_px) const {
  j["range_error_rms_m"] = json_number(rms_m());
  if (with_px) j["range_error_rms_px"] = json_number(rms_px());
  j["range_error_mean_m"] = json_number(mean_m());
  j["range_error_max_abs_m"] = detected ? nlohmann::json(max_abs_m) : nlohmann::json(nullptr);
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

void print_summary(const SimulateSummary& s, std::FILE* to) {
  fmt::print(to, "{}\n\n", s.headline);
  const auto [scale, unit] = time_unit(s.golden_frame_time_s);
  fmt::print(to, "  {:<18} {:>10} {:>10} {:>14}\n", "phase", "cycles", "golden", "time");
  for (const auto& p : s.phases)
    fmt::print(to, "  {:<18} {:>10} {:>10} {:>11.3f} {}\n", p["name"].get<std::string>(), p["cycles"].get<long long>(),
               p["golden_cycles"].get<long long>(), p["time_s"].get<double>() * scale, unit);
  fmt::print(to, "  {:<18} {:>10} {:>10}\n\n", s.frame_label, s.frame_cycles, s.golden_frame_cycles);
  fmt::print(to, "  frame time       {:>14.4f} {} measured, {:.4f} {} golden{}\n", s.frame_time_s * scale, unit,
             s.golden_frame_time_s * scale, unit, s.timing_matches ? "" : "  (MISMATCH)");
  fmt::print(to, "  frame rate       {:>17} measured, {} golden\n", rate_text(s.frame_rate_Hz), rate_text(s.golden_frame_rate_Hz));
  fmt::print(to, "  range maps       {:>14.4f} /s ({} {}{} each)\n\n", s.range_maps_per_s, s.frames_per_range_map, s.frame_label,
             s.frames_per_range_map == 1 ? "" : s.frame_label.back() == 's' ? "es" : "s");
  fmt::print(to, "  {}\n", s.points_line);
  if (s.error.detected) {
    const std::string px = s.error_in_px ? fmt::format(" ({:.4f} px)", s.error.rms_px()) : "";
    fmt::print(to, "  range error      rms {:.3f} mm{}, mean {:+.3f} mm, max |e| {:.3f} mm{}\n", s.error.rms_m() * 1e3, px,
               s.error.mean_m() * 1e3, s.error.max_abs_m * 1e3, s.error_note.empty() ? "" : " " + s.error_note);
  }
  fmt::print(to, "  wall time        {:.2f} s{}\n\n", s.wall_time_s, s.wall_note.empty() ? "" : ", " + s.wall_note);
}

int finish_simulate(const SimulateOptions& opt, OutputDir& out, TraceOutput& trace, nlohmann::json& j,
                    const std::string& plot_warning, const SimulateSummary& summary) {
  if (!plot_warning.empty()) j["warnings"] = {plot_warning};
  if (trace.enabled()) j["trace"] = opt.trace;
  out.write("summary.json", j.dump(2) + "\n");
  trace.finish();  // may throw: the output folder is still staged
  const std::vector<std::string> written = out.commit();
  const std::string trace_file = trace.commit();
  if (opt.json) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  if (!plot_warning.empty()) fmt::print(stderr, "rangesim: warning: {}\n", plot_warning);
  print_summary(summary);
  for (const auto& w : written) fmt::print("  wrote {}\n", w);
  if (!trace_file.empty()) fmt::print("  wrote {}\n", trace_file);
  return kExitOk;
}

}  // namespace rangesim::app
