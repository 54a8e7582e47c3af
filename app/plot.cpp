#include "app/plot.h"

#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <cstdio>
#include <fstream>
#include <iterator>

namespace rangesim::app {

namespace {

// Grid data for pm3d: one block per background value, blank line between blocks. Cells are
// drawn from their lower-left corner, so an extra row/column closes the last cells.
void write_pm3d_data(const std::string& path, const golden::Evaluation& ev) {
  std::ofstream out(path);
  const auto& s = ev.signal_V;
  const auto& b = ev.background_V;
  auto edge = [](const std::vector<double>& a, size_t i) {
    // Geometric cell edges around log-spaced points.
    if (a.size() == 1) return i == 0 ? a[0] / 1.12 : a[0] * 1.12;
    if (i == 0) return a[0] / std::sqrt(a[1] / a[0]);
    if (i == a.size()) return a.back() * std::sqrt(a.back() / a[a.size() - 2]);
    return std::sqrt(a[i - 1] * a[i]);
  };
  for (size_t ib = 0; ib <= b.size(); ++ib) {
    for (size_t is = 0; is <= s.size(); ++is) {
      const size_t pb = std::min(ib, b.size() - 1), ps = std::min(is, s.size() - 1);
      const auto& p = ev.at(pb, ps);
      const bool ok = p.detect == golden::Detect::Detectable;
      out << fmt::format("{:.6g} {:.6g} {} {}\n", edge(s, is), edge(b, ib), static_cast<int>(p.detect),
                         ok ? fmt::format("{:.6g}", p.accuracy_px) : "NaN");
    }
    out << "\n";
  }
}

std::string script(const std::string& data, const std::string& png_or_svg, const std::string& out_path,
                   const std::string& title, bool area) {
  std::string term = png_or_svg == "png" ? "pngcairo size 900,700 font 'Sans,11'" : "svg size 900,700 font 'Sans,11'";
  std::string s = fmt::format(
      "reset\nset terminal {}\nset output '{}'\nset logscale xy\nset format x '10^{{%L}}'\nset format y '10^{{%L}}'\n"
      "set xlabel 'signal V_{{sig}} [V]'\nset ylabel 'background V_{{bg}} [V]'\nset view map\n"
      "set pm3d map corners2color c1\nset tics out\nunset key\nset autoscale xfix\nset autoscale yfix\nset rmargin at screen 0.80\n",
      term, out_path);
  if (area) {
    s += fmt::format(
        "set title '{} — range-information detectable area'\n"
        "set palette defined (-0.5 '#2e8b57', 0.5 '#2e8b57', 0.5 '#d0d0d0', 1.5 '#d0d0d0', 1.5 '#c0392b', "
        "2.5 '#c0392b', 2.5 '#e69f00', 3.5 '#e69f00')\nset cbrange [-0.5:3.5]\n"
        "set cbtics ('detectable' 0, \"below\\nthreshold\" 1, 'saturated' 2, \"background\\nactivates\" 3)\n"
        "splot '{}' using 1:2:3 with pm3d\n",
        title, data);
  } else {
    s += fmt::format(
        "set title '{} — range accuracy [pixel pitch]'\nset logscale cb\nset cblabel 'rms position error [px]'\n"
        "set palette rgbformulae 22,13,-31\nsplot '{}' using 1:2:4 with pm3d\n",
        title, data);
  }
  return s;
}

}  // namespace

std::string render_heatmaps(OutputDir& out, const golden::Evaluation& ev, const std::string& title) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    return "gnuplot not found: heat maps skipped (scripts/install-deps.sh installs gnuplot-nox)";
  const std::string data = out.scratch("plot.dat");
  write_pm3d_data(data, ev);
  std::string all;
  bool any_accuracy = ev.summary.points_detectable > 0;
  for (const std::string fmt_ext : {"png", "svg"}) {
    all += script(data, fmt_ext, out.staged("detectable_area." + fmt_ext), title, true);
    if (any_accuracy) all += script(data, fmt_ext, out.staged("accuracy_px." + fmt_ext), title, false);
  }
  const std::string gp = out.scratch("plot.gp");
  std::ofstream(gp) << all;
  const std::string log = out.scratch("gnuplot.log");
  const int rc = std::system(fmt::format("gnuplot '{}' >'{}' 2>&1", gp, log).c_str());
  if (rc != 0) {
    // Drop whatever gnuplot left half-written; the data files are complete without plots.
    for (const std::string name : {"detectable_area", "accuracy_px"})
      for (const std::string ext : {".png", ".svg"}) std::remove(out.scratch(name + ext).c_str());
    std::ifstream in(log);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (auto& c : text)
      if (c == '\n') c = ' ';
    return "gnuplot failed, heat maps skipped: " + text.substr(0, 300);
  }
  return "";
}

}  // namespace rangesim::app
