// `rangesim compare`'s files: compare.json, compare.csv (thesis Table 5.1 in physical units, one
// row per sensor), sbr_vs_background.csv (the Fig. 1.4-style regions), accuracy_vs_background.csv,
// the two plots (gnuplot, PNG and SVG) and report.html (self-contained: the PNG plots inline as
// data: URIs).
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/compare/compare.h"
#include "app/output_dir.h"
#include "core/user_error.h"

namespace rangesim::app {

namespace {

// Sampled from viridis (perceptually uniform, readable in grey and by colour-blind readers); the
// last one darker than viridis' end so that it shows on white.
const char* kColours[] = {"#440154", "#31688e", "#35b779", "#b5a300", "#6ece58", "#26828e"};
const char* colour(size_t i) { return kColours[i % (sizeof(kColours) / sizeof(*kColours))]; }

std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : ""; }
nlohmann::json jnum(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// Per background value of the grid: the SBR' span over the detectable signals (NaN: none).
struct Band {
  std::vector<double> lux, lo, hi;
};
Band sbr_band(const CompareSensor& c) {
  Band b;
  const auto& ev = c.grid;
  for (size_t ib = 0; ib < ev.background.values.size(); ++ib) {
    double lo = golden::kNaN, hi = golden::kNaN;
    for (size_t is = 0; is < ev.signal.values.size(); ++is) {
      const auto& p = ev.at(ib, is);
      const double s = c.sbr_of(p);
      if (p.detect != "detectable" || !std::isfinite(s)) continue;
      lo = std::isfinite(lo) ? std::min(lo, s) : s;
      hi = std::isfinite(hi) ? std::max(hi, s) : s;
    }
    b.lux.push_back(ev.background.values[ib] / c.axes.native_per_lux);
    b.lo.push_back(lo), b.hi.push_back(hi);
  }
  return b;
}

// The widest detectable background span of the grid (in lux, at grid resolution) and the source
// power where it is reached: the thesis's "background light range" taken where it is largest.
struct Span {
  double lo_lux = golden::kNaN, hi_lux = golden::kNaN, power_W = golden::kNaN;
  double dB() const { return std::isfinite(lo_lux) ? 20 * std::log10(hi_lux / lo_lux) : 0.0; }
};
Span widest_background_span(const CompareSensor& c) {
  Span best;
  const auto& ev = c.grid;
  for (size_t is = 0; is < ev.signal.values.size(); ++is) {
    Span s;
    for (size_t ib = 0; ib < ev.background.values.size(); ++ib) {
      if (ev.at(ib, is).detect != "detectable") continue;
      const double lux = ev.background.values[ib] / c.axes.native_per_lux;
      if (!std::isfinite(s.lo_lux)) s.lo_lux = lux;
      s.hi_lux = lux;
    }
    s.power_W = ev.signal.values[is] / c.axes.native_per_W;
    if (std::isfinite(s.lo_lux) && (!std::isfinite(best.lo_lux) || s.dB() > best.dB())) best = s;
  }
  return best;
}

struct TableRow {
  std::string id, label, unit;
  std::function<double(const CompareSensor&)> value;
};

std::vector<TableRow> table_rows() {
  const auto sig = [](const CompareSensor& c, bool hi) {
    return (hi ? c.grid.signal_range.hi : c.grid.signal_range.lo) / c.axes.native_per_W;
  };
  const auto bg = [](const CompareSensor& c, bool hi) {
    const Span s = widest_background_span(c);
    return hi ? s.hi_lux : s.lo_lux;
  };
  return {
      {"signal_min_W", "Signal light, lowest detectable (at the lowest background)", "W", [=](auto& c) { return sig(c, false); }},
      {"signal_max_W", "Signal light, highest detectable", "W", [=](auto& c) { return sig(c, true); }},
      {"signal_range_dB", "Signal light range", "dB", [](auto& c) { return c.grid.signal_range.range_dB; }},
      {"background_min_lux", "Background light, lowest detectable (widest span over the grid)", "lx", [=](auto& c) { return bg(c, false); }},
      {"background_max_lux", "Background light, highest detectable (widest span)", "lx", [=](auto& c) { return bg(c, true); }},
      {"background_range_dB", "Background light range (widest span; grid resolution)", "dB", [](auto& c) { return widest_background_span(c).dB(); }},
      {"background_range_at_W", "Source power of the widest span", "W", [](auto& c) { return widest_background_span(c).power_W; }},
      {"sbr_max_dB", "SBR' max", "dB", [](auto& c) { return c.sbr_definition == "total" ? c.grid.sbr_max_dB : c.grid.sbr_ratio_max_dB; }},
      {"sbr_min_dB", "SBR' min", "dB", [](auto& c) { return c.sbr_definition == "total" ? c.grid.sbr_min_dB : c.grid.sbr_ratio_min_dB; }},
      {"accuracy_min_mm", "Range accuracy, best (rms)", "mm", [](auto& c) { return c.grid.accuracy_min_m * 1e3; }},
      {"accuracy_max_mm", "Range accuracy, worst (rms)", "mm", [](auto& c) { return c.grid.accuracy_max_m * 1e3; }},
      {"accuracy_distance_m", "Distance of the accuracy figures", "m", [](auto& c) { return c.accuracy_distance_m; }},
      {"scene_background_min_lux", "Detectable background at the scene's source power, from", "lx", [](auto& c) { return c.bg_lo_lux; }},
      {"scene_background_max_lux", "Detectable background at the scene's source power, up to", "lx", [](auto& c) { return c.bg_hi_lux; }},
      {"scene_accuracy_mm", "Accuracy at the scene's light", "mm", [](auto& c) { return c.scene_accuracy_m * 1e3; }},
      {"range_maps_per_s", "Frame rate (range maps per second)", "1/s", [](auto& c) { return c.frame_rate_Hz; }},
      {"native_per_lux", "Radiometry: background per lux", "native", [](auto& c) { return c.axes.native_per_lux; }},
      {"native_per_W", "Radiometry: signal per watt", "native", [](auto& c) { return c.axes.native_per_W; }},
  };
}

std::string edge_text(double v, bool at_grid, const char* unit) {
  if (!std::isfinite(v)) return "none";
  return fmt::format("{:.3g} {}{}", v, unit, at_grid ? " (grid end)" : "");
}

}  // namespace

nlohmann::json compare_json(const CompareResult& r, const CompareOptions& opt) {
  nlohmann::json j;
  j["scene"] = {{"file", r.scene_file}, {"name", r.scene_name}, {"description", r.scene_description},
                {"distance_m", r.scene_distance_m}};
  j["axes"] = {{"background_lux", opt.background_lux}, {"signal_power_W", opt.signal_power}};
  j["wall_time_s"] = r.wall_time_s;
  j["sensors"] = nlohmann::json::array();
  for (const auto& c : r.sensors) {
    nlohmann::json s = {{"sensor", c.sensor},
                        {"preset", c.preset},
                        {"title", c.title},
                        {"native_unit", c.axes.radiometry.unit},
                        {"radiometry", c.axes.radiometry.conversion},
                        {"sbr_definition", c.sbr_definition == "total" ? "eq. 3.11, (S + B) / B" : "eq. 3.23 / 4.11, S / B"},
                        {"notes", c.axes.notes},
                        {"scene_light", {{"illuminance_lux", c.scene_lux},
                                         {"source_power_W", c.scene_power_W},
                                         {"signal", c.scene_signal},
                                         {"background", c.scene_background},
                                         {"detect", c.scene_detect},
                                         {"accuracy_m", jnum(c.scene_accuracy_m)}}},
                        {"detectable_background_lux", {{"lo", jnum(c.bg_lo_lux)}, {"hi", jnum(c.bg_hi_lux)},
                                                       {"lo_limited_by_grid", c.bg_lo_grid},
                                                       {"hi_limited_by_grid", c.bg_hi_grid},
                                                       {"at_source_power_W", c.scene_power_W}}}};
    for (const auto& row : table_rows()) s["table"][row.id] = jnum(row.value(c));
    const Band b = sbr_band(c);
    for (size_t i = 0; i < b.lux.size(); ++i)
      s["sbr_vs_background"].push_back({{"lux", b.lux[i]}, {"sbr_min_dB", jnum(b.lo[i])}, {"sbr_max_dB", jnum(b.hi[i])}});
    for (size_t ib = 0; ib < c.profile.background.values.size(); ++ib) {
      const auto& p = c.profile.at(ib, 0);
      s["accuracy_vs_background"].push_back({{"lux", c.profile.background.values[ib] / c.axes.native_per_lux},
                                             {"detect", p.detect},
                                             {"accuracy_m", jnum(p.accuracy_m)}});
    }
    j["sensors"].push_back(s);
  }
  return j;
}

namespace {

std::string table_csv(const CompareResult& r) {
  std::string t = "quantity,unit";
  for (const auto& c : r.sensors) t += "," + c.sensor;
  t += "\n";
  for (const auto& row : table_rows()) {
    t += row.id + "," + (row.unit == "native" ? "V|A|Hz" : row.unit);
    for (const auto& c : r.sensors) t += "," + num(row.value(c));
    t += "\n";
  }
  return t;
}

std::string band_csv(const CompareResult& r) {
  std::string t = "sensor,background_lux,sbr_min_dB,sbr_max_dB\n";
  for (const auto& c : r.sensors) {
    const Band b = sbr_band(c);
    for (size_t i = 0; i < b.lux.size(); ++i)
      t += fmt::format("{},{},{},{}\n", c.sensor, num(b.lux[i]), num(b.lo[i]), num(b.hi[i]));
  }
  return t;
}

std::string accuracy_csv(const CompareResult& r) {
  std::string t = "sensor,background_lux,detect,accuracy_mm\n";
  for (const auto& c : r.sensors)
    for (size_t ib = 0; ib < c.profile.background.values.size(); ++ib) {
      const auto& p = c.profile.at(ib, 0);
      t += fmt::format("{},{},{},{}\n", c.sensor, num(c.profile.background.values[ib] / c.axes.native_per_lux), p.detect,
                       num(p.accuracy_m * 1e3));
    }
  return t;
}

std::string terminal(const std::string& ext, const std::string& path) {
  return fmt::format("reset\nset terminal {} size 1000,650 font 'Sans,12'\nset output '{}'\n",
                     ext == "png" ? "pngcairo" : "svg", path);
}

// Log axis with ticks at every decade labelled 0.1, 1, 10, ..., 10k, 100k, 1M.
const char* kLuxTics =
    "set logscale x\nset xtics ('0.01' 0.01, '0.1' 0.1, '1' 1, '10' 10, '100' 100, '1k' 1e3, '10k' 1e4, '100k' 1e5, "
    "'1M' 1e6, '10M' 1e7, '100M' 1e8)\nset mxtics 10\n";

std::string fig14_script(const CompareResult& r, const std::vector<std::string>& data, double scene_lux) {
  std::string s = fmt::format(
      "set termoption noenhanced\nset title \"SBR' against background illuminance at the target (scene '{}', "
      "{:g} m): detectable region per sensor\"\n"
      "set xlabel 'background illuminance at the target [lx]'\nset ylabel \"SBR' [dB]\"\n{}"
      "set grid xtics ytics mxtics lc rgb '#dddddd'\nset key outside bottom center horizontal maxrows 2 box\nset bmargin 8\n"
      "set datafile missing 'NaN'\nset style fill transparent solid 0.35 border\n"
      "set arrow from {:g}, graph 0 to {:g}, graph 1 nohead dt 2 lc rgb '#555555'\n"
      "set label 'scene' at {:g}, graph 0.97 offset 0.5,0 tc rgb '#555555'\nplot ",
      r.scene_name, r.scene_distance_m, kLuxTics, scene_lux, scene_lux, scene_lux);
  for (size_t i = 0; i < r.sensors.size(); ++i) {
    const bool any = r.sensors[i].grid.points_detectable > 0;
    s += any ? fmt::format("{}'{}' using 1:2:3 with filledcurves lc rgb '{}' title '{}'", i ? ", " : "", data[i],
                           colour(i), r.sensors[i].sensor)
             : fmt::format("{}keyentry with filledcurves lc rgb '{}' title '{} (nothing detectable)'", i ? ", " : "",
                           colour(i), r.sensors[i].sensor);
  }
  return s + "\n";
}

std::string accuracy_script(const CompareResult& r, const std::vector<std::string>& data, double scene_lux) {
  std::string s = fmt::format(
      "set termoption noenhanced\nset title 'Range accuracy against background illuminance (scene {}, source power as "
      "in the scene)'\n"
      "set xlabel 'background illuminance at the target [lx]'\nset ylabel 'rms range error [mm]'\n{}"
      "set logscale y\nset format y '%g'\nset grid xtics ytics mxtics lc rgb '#dddddd'\n"
      "set key outside bottom center horizontal maxrows 2 box\nset bmargin 8\nset datafile missing 'NaN'\n"
      "set arrow from {:g}, graph 0 to {:g}, graph 1 nohead dt 2 lc rgb '#555555'\nplot ",
      r.scene_name, kLuxTics, scene_lux, scene_lux);
  for (size_t i = 0; i < r.sensors.size(); ++i) {
    bool any = false;
    for (const auto& p : r.sensors[i].profile.points) any = any || std::isfinite(p.accuracy_m);
    s += any ? fmt::format("{}'{}' using 1:2 with lines lw 2.5 lc rgb '{}' dt {} title '{} ({:g} m)'", i ? ", " : "",
                           data[i], colour(i), i + 1, r.sensors[i].sensor, r.sensors[i].accuracy_distance_m)
             : fmt::format("{}keyentry with lines lw 2.5 lc rgb '{}' dt {} title '{} (not detectable at this power)'",
                           i ? ", " : "", colour(i), i + 1, r.sensors[i].sensor);
  }
  return s + "\n";
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char ch : s) o += ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : ch == '&' ? "&amp;" : std::string(1, ch);
  return o;
}

// A PNG as an <img> with a data: URI, so the report is one self-contained file.
std::string inline_png(const std::string& path, const std::string& alt) {
  static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const std::string in = slurp(path);
  if (in.empty()) return "";
  std::string out;
  out.reserve(in.size() * 4 / 3 + 4);
  for (size_t i = 0; i < in.size(); i += 3) {
    const unsigned a = static_cast<unsigned char>(in[i]);
    const unsigned b = i + 1 < in.size() ? static_cast<unsigned char>(in[i + 1]) : 0;
    const unsigned c = i + 2 < in.size() ? static_cast<unsigned char>(in[i + 2]) : 0;
    const unsigned v = (a << 16) | (b << 8) | c;
    out += k[(v >> 18) & 63];
    out += k[(v >> 12) & 63];
    out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
    out += i + 2 < in.size() ? k[v & 63] : '=';
  }
  return "<img alt=\"" + alt + "\" style=\"max-width:100%\" src=\"data:image/png;base64," + out + "\">";
}

std::string report_html(const CompareResult& r, const CompareOptions& opt, const std::vector<std::string>& figures) {
  std::string h = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>rangesim compare: {}</title>\n"
      "<style>body{{font-family:sans-serif;max-width:1100px;margin:2em auto;color:#222}}"
      "table{{border-collapse:collapse;margin:1em 0}}td,th{{border:1px solid #bbb;padding:4px 8px;text-align:right}}"
      "th:first-child,td:first-child{{text-align:left}}caption{{text-align:left;font-weight:bold;margin-bottom:.3em}}"
      "figure{{margin:1.5em 0}}figure svg{{max-width:100%;height:auto}}.note{{color:#555;font-size:90%}}</style>"
      "</head><body>\n<h1>Range-finding architectures compared on one scene</h1>\n"
      "<p>Scene <b>{}</b> ({}): {}; target at {:g} m. Axes: background illuminance at the target {} lx, mean source "
      "power {} W (LO:HI:N, log-spaced). Each sensor's radiometry turns both into its own unit; its golden model "
      "evaluates the grid. Wall time {:.1f} s.</p>\n",
      html_escape(r.scene_name), html_escape(r.scene_name), html_escape(r.scene_file), html_escape(r.scene_description),
      r.scene_distance_m, opt.background_lux, opt.signal_power, r.wall_time_s);
  h += "<table><caption>Detectable background at the scene's source power</caption><tr><th>sensor</th><th>from</th>"
       "<th>up to</th><th>at the scene's light</th><th>accuracy there</th><th>range maps/s</th></tr>\n";
  for (const auto& c : r.sensors)
    h += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.4g}</td></tr>\n", c.sensor,
                     edge_text(c.bg_lo_lux, c.bg_lo_grid, "lx"), edge_text(c.bg_hi_lux, c.bg_hi_grid, "lx"),
                     html_escape(c.scene_detect),
                     std::isfinite(c.scene_accuracy_m) ? fmt::format("{:.3g} mm", c.scene_accuracy_m * 1e3) : "-",
                     c.frame_rate_Hz);
  h += "</table>\n";
  const char* captions[] = {
      "Fig. 1.4-style map: SBR' against the background illuminance at the target; each sensor's region spans the SBR' "
      "of its detectable operating points over the source-power axis (dashed: the scene's illuminance).",
      "Range accuracy against background illuminance at the scene's source power and distance."};
  for (size_t i = 0; i < figures.size() && i < 2; ++i)
    if (!figures[i].empty()) h += fmt::format("<figure>{}<figcaption>{}</figcaption></figure>\n", figures[i], captions[i]);
  h += "<table><caption>Thesis Table 5.1 in physical units</caption><tr><th>quantity</th><th>unit</th>";
  for (const auto& c : r.sensors) h += "<th>" + c.sensor + "</th>";
  h += "</tr>\n";
  for (const auto& row : table_rows()) {
    h += "<tr><td>" + html_escape(row.label) + "</td><td>" +
         (row.unit == "native" ? std::string("V | A | Hz") : row.unit) + "</td>";
    for (const auto& c : r.sensors) {
      const double v = row.value(c);
      h += "<td>" + (std::isfinite(v) ? fmt::format("{:.4g}", v) : std::string("-")) +
           (row.unit == "native" ? " " + c.axes.radiometry.unit : "") + "</td>";
    }
    h += "</tr>\n";
  }
  h += "</table>\n<h2>Radiometry</h2><ul>\n";
  for (const auto& c : r.sensors)
    h += fmt::format("<li><b>{}</b> ({}): {}; SBR' {}</li>\n", c.sensor, html_escape(c.title),
                     html_escape(c.axes.radiometry.conversion),
                     c.sbr_definition == "total" ? "as eq. 3.11, (S + B) / B" : "as eq. 3.23 / 4.11, S / B");
  h += "</ul>\n";
  bool any = false;
  for (const auto& c : r.sensors)
    for (const auto& n : c.axes.notes) {
      if (!any) h += "<h2>Notes</h2><ul class=\"note\">\n", any = true;
      h += "<li>" + c.sensor + ": " + html_escape(n) + "</li>\n";
    }
  if (any) h += "</ul>\n";
  h += "<p class=\"note\">Written by rangesim compare. Method: the thesis's background-light suppression and "
       "range-accuracy evaluation (chapters 3-5), with each sensor's golden model; data in compare.json and the CSV "
       "files beside this report.</p>\n</body></html>\n";
  return h;
}

}  // namespace

// Writes every file of the comparison into `out` (staged); returns a warning ("" when none).
std::string write_compare(OutputDir& out, const CompareResult& r, const CompareOptions& opt) {
  out.write("compare.json", compare_json(r, opt).dump(2) + "\n");
  out.write("compare.csv", table_csv(r));
  out.write("sbr_vs_background.csv", band_csv(r));
  out.write("accuracy_vs_background.csv", accuracy_csv(r));
  std::vector<std::string> figures;
  std::string warning;
  const double scene_lux = r.sensors.empty() ? 1.0 : r.sensors.front().scene_lux;
  if (!opt.no_plots) {
    if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
      warning = "gnuplot not found: plots skipped (scripts/install-deps.sh installs gnuplot-nox)";
    } else {
      std::vector<std::string> band_data, acc_data;
      for (size_t i = 0; i < r.sensors.size(); ++i) {
        const CompareSensor& c = r.sensors[i];
        band_data.push_back(out.scratch(fmt::format("band{}.dat", i)));
        acc_data.push_back(out.scratch(fmt::format("accuracy{}.dat", i)));
        std::ofstream b(band_data.back()), a(acc_data.back());
        const Band band = sbr_band(c);
        for (size_t k = 0; k < band.lux.size(); ++k)
          b << fmt::format("{:.8g} {} {}\n", band.lux[k], std::isfinite(band.lo[k]) ? num(band.lo[k]) : "NaN",
                           std::isfinite(band.hi[k]) ? num(band.hi[k]) : "NaN");
        for (size_t ib = 0; ib < c.profile.background.values.size(); ++ib) {
          const double acc = c.profile.at(ib, 0).accuracy_m * 1e3;
          a << fmt::format("{:.8g} {}\n", c.profile.background.values[ib] / c.axes.native_per_lux,
                           std::isfinite(acc) ? num(acc) : "NaN");
        }
      }
      std::string script;
      for (const std::string ext : {"png", "svg"}) {
        script += terminal(ext, out.staged("fig1_4_sbr_vs_background." + ext)) + fig14_script(r, band_data, scene_lux);
        script += terminal(ext, out.staged("accuracy_vs_background." + ext)) + accuracy_script(r, acc_data, scene_lux);
      }
      const std::string gp = out.scratch("compare.gp"), log = out.scratch("gnuplot.log");
      std::ofstream(gp) << script;
      if (std::system(fmt::format("gnuplot '{}' >'{}' 2>&1", gp, log).c_str()) != 0) {
        std::string text = slurp(log);
        for (auto& ch : text)
          if (ch == '\n') ch = ' ';
        warning = "gnuplot failed, plots skipped: " + text.substr(0, 300);
        for (const char* n : {"fig1_4_sbr_vs_background.png", "fig1_4_sbr_vs_background.svg",
                              "accuracy_vs_background.png", "accuracy_vs_background.svg"})
          std::remove(out.staged(n).c_str());
      } else {
        figures.push_back(inline_png(out.staged("fig1_4_sbr_vs_background.png"), "SBR' against background illuminance"));
        figures.push_back(inline_png(out.staged("accuracy_vs_background.png"), "accuracy against background illuminance"));
      }
    }
  }
  out.write("report.html", report_html(r, opt, figures));
  return warning;
}

std::string compare_text(const CompareResult& r) {
  std::string t = fmt::format("compare on scene '{}' ({:g} m), {:.1f} s\n", r.scene_name, r.scene_distance_m,
                              r.wall_time_s);
  t += fmt::format("{:<16} {:>26} {:>12} {:>12} {:>12}\n", "sensor", "detectable background [lx]", "at scene",
                   "accuracy", "maps/s");
  for (const auto& c : r.sensors)
    t += fmt::format("{:<16} {:>26} {:>12} {:>12} {:>12.4g}\n", c.sensor,
                     std::isfinite(c.bg_lo_lux) ? fmt::format("{}{:.3g} .. {}{:.3g}", c.bg_lo_grid ? "<=" : "",
                                                              c.bg_lo_lux, c.bg_hi_grid ? ">=" : "", c.bg_hi_lux)
                                                : "none",
                     c.scene_detect.empty() ? "-" : c.scene_detect.substr(0, 12),
                     std::isfinite(c.scene_accuracy_m) ? fmt::format("{:.3g} mm", c.scene_accuracy_m * 1e3) : "-",
                     c.frame_rate_Hz);
  return t;
}

}  // namespace rangesim::app
