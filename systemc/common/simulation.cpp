#include "systemc/common/simulation.h"

#include <cmath>
#include <fmt/format.h>

#include "core/user_error.h"

namespace rangesim::systemc {

double RangeErrorStats::rms_m() const { return detected ? std::sqrt(sum_sq_m / detected) : NAN; }
double RangeErrorStats::rms_px() const { return detected ? std::sqrt(sum_sq_px / detected) : NAN; }
double RangeErrorStats::mean_m() const { return detected ? sum_m / detected : NAN; }

void RangeErrorStats::to_json(nlohmann::json& j, bool with_px) const {
  j["range_error_rms_m"] = json_number(rms_m());
  if (with_px) j["range_error_rms_px"] = json_number(rms_px());
  j["range_error_mean_m"] = json_number(mean_m());
  j["range_error_max_abs_m"] = detected ? nlohmann::json(max_abs_m) : nlohmann::json(nullptr);
}

void check_trace_pixels(const std::vector<TracePixel>& pixels, int first_row, int rows, int first_column, int columns,
                        const std::string& what) {
  for (const TracePixel& p : pixels)
    if (p.row < first_row || p.row >= first_row + rows || p.column < first_column || p.column >= first_column + columns)
      throw UserError(fmt::format("--trace-pixels {}:{}: allowed rows {}..{}, columns {}..{} ({})", p.row, p.column,
                                  first_row, first_row + rows - 1, first_column, first_column + columns - 1, what),
                      "trace_pixels");
}

void set_timing(SimulationReport& r, const golden::FrameTiming& gt, nlohmann::json phases, long long first_frame_cycles,
                double frame_time_s, long long frames_per_range_map, bool matches) {
  r.phases = std::move(phases);
  r.frame_cycles = first_frame_cycles, r.golden_frame_cycles = gt.frame_cycles;
  r.frame_time_s = frame_time_s, r.golden_frame_time_s = gt.frame_time_s;
  r.frame_rate_Hz = 1.0 / frame_time_s, r.golden_frame_rate_Hz = gt.frame_access_rate_Hz;
  r.timing_matches = matches;
  r.range_maps_per_s = r.frame_rate_Hz / static_cast<double>(frames_per_range_map);
  r.frames_per_range_map = frames_per_range_map;
}

void add_timing_json(nlohmann::json& j, const SimulationReport& r, const golden::FrameTiming& gt) {
  j["frame_time_s"] = r.frame_time_s;
  j["frame_rate_Hz"] = r.frame_rate_Hz;
  j["range_maps_per_s"] = r.range_maps_per_s;
  j["phases"] = r.phases;
  j["timing_matches_golden"] = r.timing_matches;
  j["golden"] = {{"frame_cycles", gt.frame_cycles},
                 {"frame_time_s", gt.frame_time_s},
                 {"frame_access_rate_Hz", gt.frame_access_rate_Hz},
                 {"range_maps_per_s", gt.range_maps_per_s}};
}

std::string csv_number(double v) {
  std::string s;
  append_csv_number(s, v);
  return s;
}

nlohmann::json json_number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

namespace {

std::string map_csv(const RangeMap& map, const std::vector<std::vector<double>>& values) {
  std::string csv = "row";
  for (const auto& name : map.column_names) csv += "," + name;
  csv += "\n";
  csv.reserve(csv.size() + values.size() * (8 + 12 * map.column_names.size()));
  for (std::size_t r = 0; r < values.size(); ++r) {
    append_csv_integer(csv, map.first_row + static_cast<long long>(r));
    for (double v : values[r]) {
      csv += ',';
      append_csv_number(csv, v);
    }
    csv += '\n';
  }
  return csv;
}

nlohmann::json fraction(long long n, long long of) { return of > 0 ? json_number(double(n) / double(of)) : nullptr; }

}  // namespace

std::string range_map_csv(const RangeMap& map) { return map_csv(map, map.range_m); }
std::string confidence_map_csv(const RangeMap& map) { return map_csv(map, map.confidence); }

ValidityStats validity_of(const RangeMap& map) {
  ValidityStats s;
  for (std::size_t r = 0; r < map.range_m.size(); ++r)
    for (std::size_t c = 0; c < map.range_m[r].size(); ++c) {
      const bool valid = map.valid(r, c), echo = r < map.truth_m.size() && std::isfinite(map.truth_m[r][c]);
      ++s.pixels, s.valid += valid;
      if (echo)
        ++s.echo, s.echo_valid += valid;
      else
        ++s.no_echo, s.false_valid += valid;
    }
  return s;
}

void add_validity_json(nlohmann::json& j, const RangeMap& map) {
  const ValidityStats s = validity_of(map);
  j["valid_fraction"] = fraction(s.valid, s.pixels);
  j["false_valid_fraction"] = fraction(s.false_valid, s.no_echo);
  j["echo_valid_fraction"] = fraction(s.echo_valid, s.echo);
  j["validity"] = {{"rule", map.validity_rule},  {"confidence", map.confidence_label}, {"pixels", s.pixels},
                   {"valid", s.valid},           {"pixels_without_echo", s.no_echo},   {"false_valid", s.false_valid},
                   {"pixels_with_echo", s.echo}, {"echo_valid", s.echo_valid}};
}

}  // namespace rangesim::systemc
