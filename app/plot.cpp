#include "app/plot.h"

#include "app/plot_style.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace rangesim::app {

namespace {

// Distinct colours for the detectable-area legend: detectable first.
const char* kReasonColours[] = {"#2e8b57", "#d0d0d0", "#c0392b", "#e69f00", "#5b7bd5", "#8e44ad", "#7f8c8d"};

int metric_index(const golden::EvalResult& ev, const std::string& name) {
  for (size_t i = 0; i < ev.metric_names.size(); ++i)
    if (ev.metric_names[i] == name) return static_cast<int>(i);
  return -1;
}

// Value drawn in the accuracy map: pixel pitch where the sensor reports it, else mm.
double accuracy_value(const golden::EvalPoint& p, int px_index) {
  if (p.detect != "detectable") return golden::kNaN;
  return px_index >= 0 ? p.metrics[static_cast<size_t>(px_index)] : p.accuracy_m * 1e3;
}

// Grid data for pm3d: one block per background value, blank line between blocks. Cells are
// drawn from their lower-left corner, so an extra row/column closes the last cells.
void write_grid_data(const std::string& path, const golden::EvalResult& ev) {
  std::ofstream out(path);
  const std::vector<size_t> rows = plot_indices(ev.background.values.size());
  const std::vector<size_t> columns = plot_indices(ev.signal.values.size());
  std::vector<double> s, b;  // the axes at the cells drawn
  for (size_t is : columns) s.push_back(ev.signal.values[is]);
  for (size_t ib : rows) b.push_back(ev.background.values[ib]);
  auto edge = [](const std::vector<double>& a, size_t i) {
    // Geometric cell edges around log-spaced points.
    if (a.size() == 1) return i == 0 ? a[0] / 1.12 : a[0] * 1.12;
    if (i == 0) return a[0] / std::sqrt(a[1] / a[0]);
    if (i == a.size()) return a.back() * std::sqrt(a.back() / a[a.size() - 2]);
    return std::sqrt(a[i - 1] * a[i]);
  };
  const int px = metric_index(ev, "accuracy_px");
  for (size_t ib = 0; ib <= b.size(); ++ib) {
    for (size_t is = 0; is <= s.size(); ++is) {
      const auto& p = ev.at(rows[std::min(ib, b.size() - 1)], columns[std::min(is, s.size() - 1)]);
      int reason = 0;
      for (size_t r = 0; r < ev.reasons.size(); ++r)
        if (ev.reasons[r].first == p.detect) reason = static_cast<int>(r);
      const double acc = accuracy_value(p, px);
      out << fmt::format("{:.6g} {:.6g} {} {}\n", edge(s, is), edge(b, ib), reason,
                         std::isfinite(acc) ? fmt::format("{:.6g}", acc) : "NaN");
    }
    out << "\n";
  }
}

std::string terminal(const std::string& ext, const std::string& path) {
  return fmt::format("reset\nset terminal {} size 900,700 font 'Sans,11'\nset output '{}'\n{}",
                     ext == "png" ? "pngcairo" : "svg", path, plot_preamble());
}

std::string heatmap_header(const golden::EvalResult& ev) {
  return "set logscale xy\n" + log_format("x", ev.signal.unit) + log_format("y", ev.background.unit) +
         fmt::format(
             "set xlabel 'signal [{}]'\nset ylabel 'background [{}]'\nset view map\n"
             "set pm3d map corners2color c1\nunset grid\nunset key\nset autoscale xfix\nset autoscale yfix\n"
             "set rmargin at screen 0.78\n",
             ev.signal.unit, ev.background.unit);
}

// Smallest and largest accuracy value the map draws.
std::pair<double, double> accuracy_range(const golden::EvalResult& ev) {
  const int px = metric_index(ev, "accuracy_px");
  std::vector<std::vector<double>> values(1);
  for (const auto& p : ev.points) values[0].push_back(accuracy_value(p, px));
  return finite_range(values);
}

std::string area_script(const golden::EvalResult& ev, const std::string& data) {
  const size_t n = ev.reasons.size();
  std::string palette, tics;
  for (size_t i = 0; i < n; ++i) {
    const char* c = kReasonColours[i % (sizeof(kReasonColours) / sizeof(*kReasonColours))];
    palette += fmt::format("{}{} '{}', {} '{}'", i ? ", " : "", i - 0.5, c, i + 0.5, c);
    std::string label = ev.reasons[i].first;
    for (auto& ch : label)
      if (ch == '_') ch = ' ';
    tics += fmt::format("{}\"{}\" {}", i ? ", " : "", label, i);
  }
  return heatmap_header(ev) + fmt::format(
                                  "set title '{} — range-information detectable area'\nset palette defined ({})\n"
                                  "set cbrange [-0.5:{}]\nset cbtics ({})\nsplot '{}' using 1:2:3 with pm3d\n",
                                  ev.sensor, palette, n - 0.5, tics, data);
}

std::string accuracy_script(const golden::EvalResult& ev, const std::string& data) {
  const bool px = metric_index(ev, "accuracy_px") >= 0;
  const auto [lo, hi] = accuracy_range(ev);
  return heatmap_header(ev) + viridis_palette() + log_cbtics(lo, hi) +
         fmt::format(
             "set title '{} — range accuracy{}'\nset logscale cb\nset cblabel 'rms error [{}]' offset 2,0\n"
             "splot '{}' using 1:2:4 with pm3d\n",
             ev.sensor, px ? " [pixel pitch]" : fmt::format(" at {:g} m", ev.distance_m), px ? "px" : "mm", data);
}

std::string sweep_script(const golden::EvalSweep& sw, const std::string& data) {
  auto axis = [](const std::string& label, const std::string& unit) {
    return unit.empty() ? label : fmt::format("{} [{}]", label, unit);
  };
  std::string s = fmt::format(
      "set termoption noenhanced\nset title '{}'\nset xlabel '{}'\nset ylabel '{}'\nset grid\n"
      "set key outside bottom center vertical maxrows 3 width 2\nset rmargin 6\n"
      "set datafile missing 'NaN'\n{}{}plot ",
      sw.title, axis(sw.x_label, sw.x_unit), axis(sw.y_label, sw.y_unit),
      sw.log_x ? "set logscale x\n" + log_format("x", sw.x_unit) : "",
      sw.log_y ? "set logscale y\n" + log_format("y", sw.y_unit) : "");
  for (size_t i = 0; i < sw.series.size(); ++i)
    s += fmt::format("{}'{}' index {} using 1:2 with linespoints {} title \"{}\"", i ? ", " : "", data, i,
                     series_style(i), sw.series[i].label);
  return s + "\n";
}

void write_sweep_data(const std::string& path, const golden::EvalSweep& sw) {
  std::ofstream out(path);
  for (const auto& series : sw.series) {
    for (size_t i = 0; i < series.x.size() && i < series.y.size(); ++i)
      out << fmt::format("{:.8g} {}\n", series.x[i],
                         std::isfinite(series.y[i]) ? fmt::format("{:.8g}", series.y[i]) : "NaN");
    out << "\n\n";  // gnuplot data block separator for `index`
  }
}

}  // namespace

std::vector<size_t> plot_indices(size_t n) {
  constexpr size_t kMaxCells = 1000;
  std::vector<size_t> kept;
  const size_t stride = (n + kMaxCells - 1) / kMaxCells;
  for (size_t i = 0; i < n; i += std::max<size_t>(stride, 1)) kept.push_back(i);
  if (n > 0 && kept.back() != n - 1) kept.push_back(n - 1);
  return kept;
}

std::string render_plots(OutputDir& out, const golden::EvalResult& ev) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    return "gnuplot not found: plots skipped (scripts/install-deps.sh installs gnuplot-nox)";
  std::vector<std::string> images;
  std::string script;
  const std::string grid = out.scratch("grid.dat");
  write_grid_data(grid, ev);
  for (const std::string ext : {"png", "svg"}) {
    images.push_back("detectable_area." + ext);
    script += terminal(ext, out.staged(images.back())) + area_script(ev, grid);
    if (ev.points_detectable > 0) {
      images.push_back("accuracy." + ext);
      script += terminal(ext, out.staged(images.back())) + accuracy_script(ev, grid);
    }
  }
  for (const auto& sw : ev.sweeps) {
    const std::string data = out.scratch(sw.id + ".dat");
    write_sweep_data(data, sw);
    for (const std::string ext : {"png", "svg"}) {
      images.push_back(sw.id + "." + ext);
      script += terminal(ext, out.staged(images.back())) + sweep_script(sw, data);
    }
  }
  const std::string gp = out.scratch("plots.gp");
  std::ofstream(gp) << script;
  const std::string log = out.scratch("gnuplot.log");
  if (std::system(fmt::format("gnuplot '{}' >'{}' 2>&1", gp, log).c_str()) != 0) {
    // Drop whatever gnuplot left half-written.
    for (const auto& name : images) std::remove(out.scratch(name).c_str());
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (auto& c : text)
      if (c == '\n') c = ' ';
    return "gnuplot failed, plots skipped: " + text.substr(0, 300);
  }
  return "";
}

}  // namespace rangesim::app
