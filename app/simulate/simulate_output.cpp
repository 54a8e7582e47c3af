#include "app/simulate/simulate_output.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>

namespace rangesim::app {

std::string render_range_map(OutputDir& out, const std::vector<std::vector<double>>& map, const std::string& title,
                             const std::string& x_label, const std::string& y_label) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    return "gnuplot not found: range_map.png skipped (scripts/install-deps.sh installs gnuplot-nox)";
  const std::string data = out.scratch("range_map.dat");
  {
    // gnuplot's matrix text, "%.6g" through std::to_chars (no temporary strings: a full map has
    // 137k values).
    std::string text;
    text.reserve(map.size() * (map.empty() ? 0 : map[0].size()) * 9);
    char buf[32];
    for (const auto& row : map) {
      for (std::size_t b = 0; b < row.size(); ++b) {
        if (b) text += ' ';
        if (std::isfinite(row[b]))
          text.append(buf, std::to_chars(buf, buf + sizeof buf, row[b], std::chars_format::general, 6).ptr);
        else
          text += "NaN";
      }
      text += '\n';
    }
    std::ofstream(data, std::ios::binary) << text;
  }
  const std::string png = out.staged("range_map.png");
  const std::string gp = out.scratch("range_map.gp");
  std::ofstream(gp) << fmt::format(
      "set terminal pngcairo size 900,800 font 'Sans,11'\nset output '{}'\nset termoption noenhanced\n"
      "set title '{}'\nset xlabel '{}'\nset ylabel '{}'\nset cblabel 'range [m]'\nset rmargin at screen 0.82\n"
      "set palette rgbformulae 22,13,-31\nset datafile missing 'NaN'\nset autoscale xfix\nset autoscale yfix\n"
      "set tics out\nplot '{}' matrix with image notitle\n",
      png, title, x_label, y_label, data);
  if (std::system(fmt::format("gnuplot '{}' >'{}' 2>&1", gp, out.scratch("gnuplot.log")).c_str()) != 0) {
    std::remove(png.c_str());
    return "gnuplot failed: range_map.png skipped";
  }
  return "";
}

}  // namespace rangesim::app
