#include "app/sweep/sweep_output.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

#include "app/plot_style.h"

namespace rangesim::app::sweep {

namespace {

double figure(const SweepRow& r, const std::string& name) {
  if (!r.valid || !r.figures.contains(name) || !r.figures.at(name).is_number()) return NAN;
  return r.figures.at(name).get<double>();
}

std::string value_of(const SweepRow& r, std::size_t k) {
  const std::string& a = r.assignment.at(k);
  return a.substr(a.find('=') + 1);
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : c == '\n' ? std::string(" ") : std::string(1, c);
  return q + "\"";
}

std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.10g}", v) : ""; }
std::string short_num(double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : "-"; }

bool numeric(const std::string& s) {
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return !s.empty() && *end == '\0';
}

}  // namespace

std::vector<bool> pareto_front(const std::vector<SweepRow>& rows, const std::string& accuracy) {
  std::vector<bool> front(rows.size(), false);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double ri = figure(rows[i], "range_maps_per_s"), ai = figure(rows[i], accuracy);
    if (!std::isfinite(ri) || !std::isfinite(ai)) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < rows.size() && !dominated; ++j) {
      const double rj = figure(rows[j], "range_maps_per_s"), aj = figure(rows[j], accuracy);
      if (j == i || !std::isfinite(rj) || !std::isfinite(aj)) continue;
      dominated = rj >= ri && aj <= ai && (rj > ri || aj < ai);
    }
    front[i] = !dominated;
  }
  return front;
}

std::string sweep_csv(const SweepHeader& h, const std::vector<SweepRow>& rows) {
  std::string s = "variant";
  for (const auto& k : h.keys) s += "," + k;
  s += ",valid";
  for (const auto& f : figure_names(h.checks)) s += "," + f;
  s += ",pareto,reason\n";
  const std::vector<bool> front = pareto_front(rows, h.pareto_accuracy);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SweepRow& r = rows[i];
    s += fmt::format("{}", r.index);
    for (std::size_t k = 0; k < h.keys.size(); ++k) s += "," + csv_field(value_of(r, k));
    s += r.valid ? ",1" : ",0";
    for (const auto& f : figure_names(h.checks)) s += "," + num(figure(r, f));
    s += front[i] ? ",1," : ",0,";
    s += csv_field(r.reason) + "\n";
  }
  return s;
}

nlohmann::json sweep_json(const SweepHeader& h, const std::vector<SweepRow>& rows) {
  nlohmann::json variants = nlohmann::json::array();
  const std::vector<bool> front = pareto_front(rows, h.pareto_accuracy);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    nlohmann::json j = row_json(rows[i], h.checks);
    for (std::size_t k = 0; k < h.keys.size(); ++k) j[h.keys[k]] = value_of(rows[i], k);
    j["pareto"] = static_cast<bool>(front[i]);
    variants.push_back(j);
  }
  long long valid = 0;
  for (const auto& r : rows) valid += r.valid ? 1 : 0;
  return {{"sensor", h.sensor},
          {"preset", h.preset},
          {"set", h.settings},
          {"varied", h.keys},
          {"zip", h.zip},
          {"variants_total", rows.size()},
          {"variants_valid", valid},
          {"variants", variants},
          {"pareto_axes", {"range_maps_per_s (higher is better)", h.pareto_accuracy + " (lower is better)"}}};
}

std::string sweep_text(const SweepHeader& h, const std::vector<SweepRow>& rows) {
  std::string s = fmt::format("{} sweep: {} variant{}{}\n\n", h.sensor, rows.size(), rows.size() == 1 ? "" : "s",
                              h.zip ? " (zipped)" : "");
  std::string head;
  for (const auto& k : h.keys) head += fmt::format("{:>14} ", k.substr(k.find('.') + 1));
  s += fmt::format("  {:>5} {}{:>14} {:>12} {:>12} {:>12} {:>7}\n", "#", head, "maps/s", "acc min mm", "acc max mm",
                   "bg range dB", "Pareto");
  const std::vector<bool> front = pareto_front(rows, h.pareto_accuracy);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SweepRow& r = rows[i];
    std::string vals;
    for (std::size_t k = 0; k < h.keys.size(); ++k) vals += fmt::format("{:>14} ", value_of(r, k));
    if (!r.valid) {
      s += fmt::format("  {:>5} {}invalid: {}\n", r.index, vals, r.reason);
      continue;
    }
    const auto mm = [&](const char* f) { return short_num(figure(r, f) * 1e3); };
    s += fmt::format("  {:>5} {}{:>14} {:>12} {:>12} {:>12} {:>7}\n", r.index, vals,
                     short_num(figure(r, "range_maps_per_s")), mm("accuracy_min_m"), mm("accuracy_max_m"),
                     short_num(figure(r, "background_range_dB")), front[i] ? "yes" : "");
  }
  return s;
}

namespace {

std::string terminal(const std::string& ext, const std::string& path) {
  return fmt::format("reset\nset terminal {} size 1000,650 font 'Sans,11' noenhanced\nset output '{}'\n{}",
                     ext == "png" ? "pngcairo" : "svg", path, plot_preamble());
}

// Data for the Pareto plot: block 0 every valid variant, block 1 the front in rate order.
std::string pareto_data(const SweepHeader& h, const std::vector<SweepRow>& rows) {
  const std::vector<bool> front = pareto_front(rows, h.pareto_accuracy);
  std::string all, best;
  std::multimap<double, std::string> ordered;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double a = figure(rows[i], h.pareto_accuracy), m = figure(rows[i], "range_maps_per_s");
    if (!std::isfinite(a) || !std::isfinite(m)) continue;
    const std::string line = fmt::format("{:.8g} {:.8g} \"{}\"\n", a * 1e3, m, rows[i].index);
    all += line;
    if (front[i]) ordered.emplace(m, line);
  }
  for (const auto& [m, line] : ordered) best += line;
  return all + "\n\n" + best;
}

std::string pareto_script(const std::string& data, const SweepHeader& h, const std::string& ext,
                          const std::string& path) {
  return terminal(ext, path) +
         fmt::format(
             "set title '{} sweep: range-map rate against accuracy'\nset logscale xy\nset grid\n"
             "set xlabel '{} rms range accuracy over the detectable area [mm]'\n"
             "set ylabel 'range maps per second'\nset key top right\n"
             "plot '{}' index 0 using 1:2 with points pt 7 ps 1.2 lc rgb '{}' title 'variant (label: its index)', "
             "'' index 0 using 1:2:3 with labels font ',8' offset 0.8,0.6 notitle, "
             "'' index 1 using 1:2 with linespoints pt 6 ps 2 lw 2 lc rgb '{}' title 'Pareto front'\n",
             h.sensor, h.pareto_accuracy == "accuracy_max_m" ? "worst" : "best", data, series_colour(0),
             series_colour(1));
}

// One plot per numeric varied key: range-map rate (left axis) and worst accuracy (right axis)
// against the key's value, one line per combination of the other keys' values.
std::string key_data(const SweepHeader& h, const std::vector<SweepRow>& rows, std::size_t k,
                     std::vector<std::string>& titles) {
  std::map<std::string, std::vector<const SweepRow*>> by_rest;
  std::vector<std::string> order;
  for (const auto& r : rows) {
    if (!r.valid) continue;
    std::string rest;
    for (std::size_t o = 0; o < h.keys.size(); ++o)
      if (o != k) rest += (rest.empty() ? "" : ", ") + r.assignment[o];
    if (!by_rest.count(rest)) order.push_back(rest);
    by_rest[rest].push_back(&r);
  }
  std::string s;
  titles.clear();
  for (const auto& rest : order) {
    s += fmt::format("# {}\n", rest.empty() ? "all" : rest);
    for (const SweepRow* r : by_rest[rest])
      s += fmt::format("{} {:.8g} {:.8g}\n", value_of(*r, k), figure(*r, "range_maps_per_s"),
                       figure(*r, h.pareto_accuracy) * 1e3);
    s += "\n\n";
    titles.push_back(rest);
  }
  return s;
}

// Solid lines: range-map rate (left axis); dashed: accuracy (right axis); one colour per
// combination of the other keys, named in the legend.
std::string key_script(const std::string& data, const SweepHeader& h, std::size_t k,
                       const std::vector<std::string>& titles, const std::string& ext, const std::string& path) {
  std::string s = terminal(ext, path) +
                  fmt::format(
                      "set title '{} sweep over {} (solid: range maps/s, dashed: accuracy)'\nset grid\n"
                      "set xlabel '{}'\nset ylabel 'range maps per second'\nset logscale y\n"
                      "set y2label '{} rms range accuracy [mm]'\nset y2tics\nset ytics nomirror\n"
                      "set key outside right top vertical\nplot ",
                      h.sensor, h.keys[k], h.keys[k], h.pareto_accuracy == "accuracy_max_m" ? "worst" : "best");
  const std::size_t shown = std::min<std::size_t>(titles.size(), 8);  // beyond 8 lines a legend cannot be read
  for (std::size_t i = 0; i < shown; ++i) {
    const std::string title = titles[i].empty() ? "" : titles[i];
    s += fmt::format(
        "{}'{}' index {} using 1:2 with linespoints pt 7 lw 2 lc rgb '{}' title '{}', '' index {} using 1:3 axes "
        "x1y2 with linespoints pt 4 dt 2 lw 2 lc rgb '{}' notitle",
        i ? ", " : "", data, i, series_colour(i), title.empty() ? "all variants" : title, i, series_colour(i));
  }
  return s + "\n";
}

}  // namespace

std::string render_sweep_plots(OutputDir& out, const SweepHeader& h, const std::vector<SweepRow>& rows) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    return "gnuplot not found: plots skipped (scripts/install-deps.sh installs gnuplot-nox)";
  std::string script;
  const std::string pd = out.scratch("pareto.dat");
  std::ofstream(pd) << pareto_data(h, rows);
  for (const char* ext : {"png", "svg"}) script += pareto_script(pd, h, ext, out.staged(fmt::format("pareto.{}", ext)));
  for (std::size_t k = 0; k < h.keys.size(); ++k) {
    bool all_numeric = true;
    for (const auto& r : rows) all_numeric = all_numeric && numeric(value_of(r, k));
    if (!all_numeric) continue;
    std::vector<std::string> titles;
    const std::string name = h.keys[k];
    const std::string kd = out.scratch(name + ".dat");
    std::ofstream(kd) << key_data(h, rows, k, titles);
    if (titles.empty()) continue;
    for (const char* ext : {"png", "svg"})
      script += key_script(kd, h, k, titles, ext, out.staged(fmt::format("{}.{}", name, ext)));
  }
  const std::string gp = out.scratch("sweep.gp");
  std::ofstream(gp) << script;
  if (std::system(fmt::format("gnuplot '{}' >'{}' 2>&1", gp, out.scratch("gnuplot.log")).c_str()) != 0)
    return "gnuplot failed: plots skipped";
  return "";
}

}  // namespace rangesim::app::sweep
