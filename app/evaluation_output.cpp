#include "app/evaluation_output.h"

#include <cmath>
#include <fmt/format.h>

namespace rangesim::app {

namespace {

std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : std::string(); }

nlohmann::json json_num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// The text of one matrix cell: the verdict, the accuracy in mm or a metric (metric index k).
std::string cell_text(const golden::EvalPoint& p, const std::string& cell, size_t k) {
  if (cell == "detect") return p.detect;
  if (cell == "accuracy_mm") return num(p.accuracy_m * 1e3);
  return k < p.metrics.size() ? num(p.metrics[k]) : std::string();
}

std::vector<golden::EvalPoint> row_of(const golden::EvalResult& ev, size_t ib) {
  const auto ns = static_cast<std::ptrdiff_t>(ev.signal.values.size());
  const auto first = ev.points.begin() + static_cast<std::ptrdiff_t>(ib) * ns;
  return std::vector<golden::EvalPoint>(first, first + ns);
}

std::string matrix(const golden::EvalResult& ev, const std::string& cell) {
  std::string o = matrix_csv_header(ev);
  for (size_t ib = 0; ib < ev.background.values.size(); ++ib)
    o += matrix_csv_row(ev, ev.background.values[ib], row_of(ev, ib), cell);
  return o;
}

}  // namespace

std::string points_csv_header(const golden::EvalResult& ev) {
  std::string o = fmt::format("signal_{},background_{},detect,sbr_total_dB,sbr_ratio_dB,accuracy_m", ev.signal.unit,
                              ev.background.unit);
  for (const auto& m : ev.metric_names) o += "," + m;
  return o + "\n";
}

std::string points_csv_rows(const std::vector<golden::EvalPoint>& row) {
  std::string o;
  for (const auto& p : row) {
    o += fmt::format("{:.6g},{:.6g},{},{},{},{}", p.signal, p.background, p.detect, num(p.sbr_total_dB),
                     num(p.sbr_ratio_dB), num(p.accuracy_m));
    for (double m : p.metrics) o += "," + num(m);
    o += "\n";
  }
  return o;
}

std::string matrix_csv_header(const golden::EvalResult& ev) {
  std::string o = fmt::format("background_{}\\signal_{}", ev.background.unit, ev.signal.unit);
  for (double s : ev.signal.values) o += fmt::format(",{:.6g}", s);
  return o + "\n";
}

std::string matrix_csv_row(const golden::EvalResult& ev, double background, const std::vector<golden::EvalPoint>& row,
                           const std::string& cell) {
  size_t k = 0;
  while (k < ev.metric_names.size() && ev.metric_names[k] != cell) ++k;
  std::string o = fmt::format("{:.6g}", background);
  for (const auto& p : row) o += "," + cell_text(p, cell, k);
  return o + "\n";
}

std::string points_csv(const golden::EvalResult& ev) {
  std::string o = points_csv_header(ev);
  for (size_t ib = 0; ib < ev.background.values.size(); ++ib) o += points_csv_rows(row_of(ev, ib));
  return o;
}

std::string detect_matrix_csv(const golden::EvalResult& ev) { return matrix(ev, "detect"); }

std::string accuracy_mm_matrix_csv(const golden::EvalResult& ev) { return matrix(ev, "accuracy_mm"); }

std::string metric_matrix_csv(const golden::EvalResult& ev, const std::string& metric) { return matrix(ev, metric); }

nlohmann::json summary_json(const golden::EvalResult& ev, const ParamSet& params) {
  const std::string su = ev.signal.unit, bu = ev.background.unit;
  nlohmann::json j;
  j["sensor"] = ev.sensor;
  j["preset"] = params.origin();
  j["grid"] = {{"signal_min_" + su, ev.signal.values.front()},
               {"signal_max_" + su, ev.signal.values.back()},
               {"signal_points", ev.signal.values.size()},
               {"background_min_" + bu, ev.background.values.front()},
               {"background_max_" + bu, ev.background.values.back()},
               {"background_points", ev.background.values.size()}};
  j["points_total"] = ev.grid_points();
  j["points_detectable"] = ev.points_detectable;
  j["signal_range_dB"] = ev.signal_range.range_dB;
  j["signal_min_" + su] = json_num(ev.signal_range.lo);
  j["signal_max_" + su] = json_num(ev.signal_range.hi);
  j["signal_min_limited_by_grid"] = ev.signal_range.lo_limited_by_grid;
  j["signal_max_limited_by_grid"] = ev.signal_range.hi_limited_by_grid;
  j["signal_range_at_background_" + bu] = json_num(ev.signal_range.at);
  j["background_range_dB"] = ev.background_range.range_dB;
  j["background_min_" + bu] = json_num(ev.background_range.lo);
  j["background_max_" + bu] = json_num(ev.background_range.hi);
  j["background_min_limited_by_grid"] = ev.background_range.lo_limited_by_grid;
  j["background_max_limited_by_grid"] = ev.background_range.hi_limited_by_grid;
  j["background_range_at_signal_" + su] = json_num(ev.background_range.at);
  j["sbr_min_dB"] = json_num(ev.sbr_min_dB);
  j["sbr_max_dB"] = json_num(ev.sbr_max_dB);
  j["sbr_ratio_min_dB"] = json_num(ev.sbr_ratio_min_dB);
  j["sbr_ratio_max_dB"] = json_num(ev.sbr_ratio_max_dB);
  j["accuracy_min_m"] = json_num(ev.accuracy_min_m);
  j["accuracy_max_m"] = json_num(ev.accuracy_max_m);
  j["distance_m"] = json_num(ev.distance_m);
  for (const auto& [key, value] : ev.summary_extra) j[key] = json_num(value);
  nlohmann::json sweeps = nlohmann::json::array();
  for (const auto& sw : ev.sweeps) sweeps.push_back(sw.id);
  j["sweeps"] = sweeps;
  return j;
}

std::string summary_text(const golden::EvalResult& ev) {
  const std::string su = ev.signal.unit, bu = ev.background.unit;
  std::string s =
      fmt::format("{} evaluation: grid {} x {} (signal {:g}-{:g} {}, background {:g}-{:g} {})\n\n", ev.sensor,
                  ev.signal.values.size(), ev.background.values.size(), ev.signal.values.front(),
                  ev.signal.values.back(), su, ev.background.values.front(), ev.background.values.back(), bu);
  s += fmt::format("  {:<36} {} / {}\n", "detectable points", ev.points_detectable, ev.grid_points());
  if (ev.points_detectable == 0)
    return s + "  nothing is detectable on this grid: detectable_area.csv gives the reason at each point\n";
  auto edge_note = [](const golden::EvalRange& r) {
    std::string n;
    if (r.lo_limited_by_grid) n += "; lower edge = grid start";
    if (r.hi_limited_by_grid) n += "; upper edge = grid end";
    return n;
  };
  s += fmt::format("  {:<36} {:.2f} dB  ({:.4g} .. {:.4g} {} at background {:.4g} {}{})\n", "signal range",
                   ev.signal_range.range_dB, ev.signal_range.lo, ev.signal_range.hi, su, ev.signal_range.at, bu,
                   edge_note(ev.signal_range));
  s += fmt::format("  {:<36} {:.2f} dB  ({:.4g} .. {:.4g} {} at signal {:.4g} {}{})\n", "background range",
                   ev.background_range.range_dB, ev.background_range.lo, ev.background_range.hi, bu,
                   ev.background_range.at, su, edge_note(ev.background_range));
  s += fmt::format("  {:<36} {:.2f} .. {:.2f} dB\n", "SBR' (signal+background)/background", ev.sbr_min_dB,
                   ev.sbr_max_dB);
  s +=
      fmt::format("  {:<36} {:.2f} .. {:.2f} dB\n", "SBR' signal/background", ev.sbr_ratio_min_dB, ev.sbr_ratio_max_dB);
  s += fmt::format("  {:<36} {:.3f} .. {:.3f} mm at {:g} m\n", "range accuracy (rms)", ev.accuracy_min_m * 1e3,
                   ev.accuracy_max_m * 1e3, ev.distance_m);
  for (const auto& [key, value] : ev.summary_extra) s += fmt::format("  {:<36} {:.6g}\n", key, value);
  return s;
}

}  // namespace rangesim::app
