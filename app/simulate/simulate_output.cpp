#include "app/simulate/simulate_output.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>

#include "app/plot_style.h"

namespace rangesim::app {

namespace {

// gnuplot's matrix text, "%.6g" through std::to_chars (no temporary strings: a full map has 137k
// values).
void write_matrix(const std::string& path, const std::vector<std::vector<double>>& rows) {
  std::string text;
  text.reserve(rows.size() * (rows.empty() ? 0 : rows[0].size()) * 9);
  char buf[32];
  for (const auto& row : rows) {
    for (std::size_t b = 0; b < row.size(); ++b) {
      if (b) text += ' ';
      if (std::isfinite(row[b]))
        text.append(buf, std::to_chars(buf, buf + sizeof buf, row[b], std::chars_format::general, 6).ptr);
      else
        text += "NaN";
    }
    text += '\n';
  }
  std::ofstream(path, std::ios::binary) << text;
}

// The map's error where both the range and the truth exist.
std::vector<std::vector<double>> error_rows(const systemc::RangeMap& m) {
  std::vector<std::vector<double>> e = m.range_m;
  for (std::size_t r = 0; r < e.size(); ++r)
    for (std::size_t c = 0; c < e[r].size(); ++c)
      e[r][c] = r < m.truth_m.size() && c < m.truth_m[r].size() ? m.range_m[r][c] - m.truth_m[r][c] : NAN;
  return e;
}

// The q-quantile of |v| over the finite values (0 when none).
double abs_quantile(const std::vector<std::vector<double>>& rows, double q) {
  std::vector<double> a;
  for (const auto& r : rows)
    for (double v : r)
      if (std::isfinite(v)) a.push_back(std::fabs(v));
  if (a.empty()) return 0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(a.size() - 1));
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(k), a.end());
  return a[k];
}

// Colour-bar range and a tick format with the decimals that tell ticks a fifth of it apart.
std::string cb_range(double lo, double hi) {
  const double span = std::max(hi - lo, 1e-9 * std::max(1.0, std::fabs(hi)));
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(span / 5))), 0, 9);
  return fmt::format("set cbrange [{:.9g}:{:.9g}]\nset format cb '%.{}f'\n", lo, hi, decimals);
}

// One image: pixels as squares (ratio -1), the rows counted from the first at the bottom.
std::string image_script(const std::string& png, const std::string& data, const systemc::RangeMap& m,
                         const std::string& title, const std::string& palette_and_range, const std::string& cblabel) {
  return fmt::format(
      "reset\nset terminal pngcairo size 900,800 font 'Sans,11'\nset output '{}'\n{}set termoption noenhanced\n"
      "set title '{}'\nset xlabel '{}'\nset ylabel '{}'\nset cblabel '{}' offset 1,0\nset size ratio -1\n"
      "set rmargin at screen 0.80\nunset grid\n{}set datafile missing 'NaN'\nset autoscale xfix\n"
      "set autoscale yfix\nplot '{}' matrix using 1:($2 + {}):3 with image notitle\n",
      png, plot_preamble(), title, m.x_label, m.y_label, cblabel, palette_and_range, data, m.first_row);
}

}  // namespace

std::string render_range_map(OutputDir& out, const systemc::RangeMap& m) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    return "gnuplot not found: range_map.png skipped (scripts/install-deps.sh installs gnuplot-nox)";
  const std::string data = out.scratch("range_map.dat");
  write_matrix(data, m.range_m);
  std::vector<std::string> pngs = {out.staged("range_map.png")};
  const auto [lo, hi] = finite_range(m.range_m);
  std::string script = image_script(pngs[0], data, m, m.title + " — valid ranges (blank: invalid)",
                                    viridis_palette() + (std::isfinite(lo) ? cb_range(lo, hi) : ""), "range [m]");
  const std::vector<std::vector<double>> err = error_rows(m);
  if (std::isfinite(finite_range(err).first)) {
    // Symmetric about 0 to the 99th percentile of |error|: a few edge pixels must not wash the rest
    // out; beyond it the end colours show.
    const double span = std::max(abs_quantile(err, 0.99), 1e-9);
    const std::string err_data = out.scratch("range_error.dat");
    write_matrix(err_data, err);
    pngs.push_back(out.staged("range_error.png"));
    script +=
        image_script(pngs.back(), err_data, m, m.title + " — range error", diverging_palette() + cb_range(-span, span),
                     "range - ground truth [m] (clipped at the 99th percentile of |error|)");
  }
  const std::string gp = out.scratch("range_map.gp");
  std::ofstream(gp) << script;
  if (std::system(fmt::format("gnuplot '{}' >'{}' 2>&1", gp, out.scratch("gnuplot.log")).c_str()) != 0) {
    for (const auto& p : pngs) std::remove(p.c_str());
    return "gnuplot failed: range_map.png skipped";
  }
  return "";
}

}  // namespace rangesim::app
