#include "app/montecarlo/mc_output.h"

#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <fstream>
#include <sstream>

#include "app/plot_style.h"

namespace rangesim::app::mc {

namespace {

std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.9g}", v) : std::string(); }
nlohmann::json json_num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

McInterval in_m(const McInterval& i, double f) { return {i.value * f, i.lo * f, i.hi * f}; }

// |golden - MC| in half-widths of the interval on golden's side (probability intervals are not
// symmetric; the stated test allows 2: about 3.9 standard errors, tests/montecarlo/test_mc_golden.cpp).
double gap_half_widths(const McInterval& i, double golden) {
  const double side = golden >= i.value ? i.hi - i.value : i.value - i.lo;
  const double gap = std::fabs(golden - i.value);
  if (gap <= 1e-12 * std::max(1.0, std::fabs(golden))) return 0;  // equal but for rounding
  return side > 0 ? gap / side : INFINITY;
}

McComparison compare(const char* quantity, double golden, const McInterval& mc) {
  McComparison c;
  c.quantity = quantity;
  c.golden = golden;
  c.mc = mc;
  c.gap_half_widths = gap_half_widths(mc, golden);
  c.inside = mc.contains(golden) || c.gap_half_widths == 0;
  c.within_2_half_widths = c.gap_half_widths <= 2.0;
  return c;
}

bool golden_in_ci(const McGrid& g, std::size_t i) {
  for (const McComparison& c : mc_comparisons(g, i))
    if (!c.inside) return false;
  return true;
}

bool golden_within_2_half_widths(const McGrid& g, std::size_t i) {
  for (const McComparison& c : mc_comparisons(g, i))
    if (!c.within_2_half_widths) return false;
  return true;
}

// The total accuracy (outliers included) where the stated test uses the clean one: information.
bool total_within_2_half_widths(const McGrid& g, std::size_t i) {
  const McInterval a = in_m(g.stats[i]->rms, g.metres_per_unit);
  return gap_half_widths(a, g.ev->points[i].accuracy_m) <= 2.0;
}

}  // namespace

std::vector<McComparison> mc_comparisons(const McGrid& g, std::size_t i) {
  std::vector<McComparison> out;
  if (!g.stats[i]) return out;
  const McPointStats& s = *g.stats[i];
  const auto& p = g.ev->points[i];
  if (std::isfinite(p.accuracy_clean_m))
    out.push_back(compare("accuracy_clean_m", p.accuracy_clean_m, in_m(s.rms_clean, g.metres_per_unit)));
  else
    out.push_back(compare("accuracy_m", p.accuracy_m, in_m(s.rms, g.metres_per_unit)));
  if (std::isfinite(p.p_detect)) out.push_back(compare("p_detect", p.p_detect, s.p_detect));
  if (std::isfinite(p.p_outlier)) out.push_back(compare("p_outlier", p.p_outlier, s.p_outlier));
  return out;
}

std::vector<McOutsidePoint> mc_golden_outside_ci(const McGrid& g) {
  std::vector<McOutsidePoint> out;
  for (std::size_t i = 0; i < g.stats.size(); ++i)
    for (const McComparison& c : mc_comparisons(g, i)) {
      if (c.inside) continue;
      McOutsidePoint o;
      o.index = i;
      o.signal = g.ev->points[i].signal;
      o.background = g.ev->points[i].background;
      o.c = c;
      o.p_detect = g.stats[i]->p_detect.value;
      o.gap_rel = (c.golden - c.mc.value) / c.mc.value;
      out.push_back(o);
    }
  return out;
}

std::string mc_outside_csv(const McGrid& g) {
  std::ostringstream o;
  o << fmt::format(
      "signal_{},background_{},quantity,golden,mc,mc_lo,mc_hi,p_detect,gap_rel,gap_half_widths,"
      "within_2_half_widths\n",
      g.ev->signal.unit, g.ev->background.unit);
  for (const McOutsidePoint& p : mc_golden_outside_ci(g))
    o << fmt::format("{:.6g},{:.6g},{},{},{},{},{},{},{},{},{}\n", p.signal, p.background, p.c.quantity,
                     num(p.c.golden), num(p.c.mc.value), num(p.c.mc.lo), num(p.c.mc.hi), num(p.p_detect),
                     num(p.gap_rel), num(p.c.gap_half_widths), p.c.within_2_half_widths ? 1 : 0);
  return o.str();
}

std::string mc_points_csv(const McGrid& g) {
  const auto& ev = *g.ev;
  std::ostringstream o;
  o << fmt::format(
      "signal_{},background_{},golden_accuracy_m,trials,detected,p_detect,p_detect_lo,p_detect_hi,bias_m,bias_lo_m,"
      "bias_hi_m,std_m,std_lo_m,std_hi_m,accuracy_m,accuracy_lo_m,accuracy_hi_m,golden_accuracy_clean_m,"
      "accuracy_clean_m,accuracy_clean_lo_m,accuracy_clean_hi_m,golden_p_detect,golden_p_outlier,outliers,p_outlier,"
      "p_outlier_lo,p_outlier_hi,golden_in_ci,golden_within_2_half_widths,target_met\n",
      ev.signal.unit, ev.background.unit);
  for (std::size_t i = 0; i < ev.points.size(); ++i) {
    if (!g.stats[i]) continue;
    const McPointStats& s = *g.stats[i];
    const auto& p = ev.points[i];
    o << fmt::format("{:.6g},{:.6g},{},{},{},{},{},{}", p.signal, p.background, num(p.accuracy_m), s.trials, s.detected,
                     num(s.p_detect.value), num(s.p_detect.lo), num(s.p_detect.hi));
    for (const McInterval* m : {&s.bias, &s.std, &s.rms}) {
      const McInterval x = in_m(*m, g.metres_per_unit);
      o << "," << num(x.value) << "," << num(x.lo) << "," << num(x.hi);
    }
    const McInterval c = in_m(s.rms_clean, g.metres_per_unit);
    o << "," << num(p.accuracy_clean_m) << "," << num(c.value) << "," << num(c.lo) << "," << num(c.hi) << ","
      << num(p.p_detect) << "," << num(p.p_outlier) << "," << s.outliers << "," << num(s.p_outlier.value) << ","
      << num(s.p_outlier.lo) << "," << num(s.p_outlier.hi);
    const double hw = s.rms.half_width() * g.metres_per_unit;
    o << "," << (golden_in_ci(g, i) ? 1 : 0) << "," << (golden_within_2_half_widths(g, i) ? 1 : 0) << ","
      << (g.target_error_m <= 0 ? "" : (std::isfinite(hw) && hw <= g.target_error_m ? "1" : "0")) << "\n";
  }
  return o.str();
}

std::string mc_matrix_csv(const McGrid& g, bool half_width) {
  const auto& ev = *g.ev;
  std::ostringstream o;
  o << fmt::format("background_{}\\signal_{}", ev.background.unit, ev.signal.unit);
  for (double s : ev.signal.values) o << fmt::format(",{:.6g}", s);
  o << "\n";
  const std::size_t ns = ev.signal.values.size();
  for (std::size_t ib = 0; ib < ev.background.values.size(); ++ib) {
    o << fmt::format("{:.6g}", ev.background.values[ib]);
    for (std::size_t is = 0; is < ns; ++is) {
      const auto& s = g.stats[ib * ns + is];
      const double v = !s ? NAN : 1e3 * g.metres_per_unit * (half_width ? s->rms.half_width() : s->rms.value);
      o << "," << num(v);
    }
    o << "\n";
  }
  return o.str();
}

nlohmann::json mc_summary_json(const McGrid& g) {
  nlohmann::json j;
  long long points = 0, trials = 0, in_ci = 0, within2 = 0, met = 0, total2 = 0, outliers = 0;
  double acc_min = INFINITY, acc_max = -INFINITY, hw_max = 0;
  for (std::size_t i = 0; i < g.stats.size(); ++i) {
    if (!g.stats[i]) continue;
    const McPointStats& s = *g.stats[i];
    ++points, trials += s.trials;
    const double a = s.rms.value * g.metres_per_unit, hw = s.rms.half_width() * g.metres_per_unit;
    if (std::isfinite(a)) acc_min = std::min(acc_min, a), acc_max = std::max(acc_max, a);
    if (std::isfinite(hw)) hw_max = std::max(hw_max, hw);
    if (golden_in_ci(g, i)) ++in_ci;
    if (golden_within_2_half_widths(g, i)) ++within2;
    if (total_within_2_half_widths(g, i)) ++total2;
    outliers += s.outliers;
    if (g.target_error_m > 0 && std::isfinite(hw) && hw <= g.target_error_m) ++met;
  }
  j["trials_per_point"] = g.trials;
  j["target_error_m"] = g.target_error_m > 0 ? nlohmann::json(g.target_error_m) : nlohmann::json(nullptr);
  j["max_trials"] = g.max_trials;
  j["seed"] = g.seed;
  j["model_unit"] = g.unit;
  j["points"] = points;
  j["trials_total"] = trials;
  j["accuracy_min_m"] = json_num(points ? acc_min : NAN);
  j["accuracy_max_m"] = json_num(points ? acc_max : NAN);
  j["accuracy_ci_half_width_max_m"] = json_num(points ? hw_max : NAN);
  j["points_golden_in_ci"] = in_ci;
  j["points_golden_within_2_half_widths"] = within2;
  j["points_total_accuracy_within_2_half_widths"] = total2;
  j["outliers_total"] = outliers;
  nlohmann::json outside = nlohmann::json::array();
  for (const McOutsidePoint& p : mc_golden_outside_ci(g))
    outside.push_back({{"signal", p.signal},
                       {"background", p.background},
                       {"quantity", p.c.quantity},
                       {"golden", json_num(p.c.golden)},
                       {"mc", json_num(p.c.mc.value)},
                       {"mc_lo", json_num(p.c.mc.lo)},
                       {"mc_hi", json_num(p.c.mc.hi)},
                       {"p_detect", json_num(p.p_detect)},
                       {"gap_rel", json_num(p.gap_rel)},
                       {"gap_half_widths", json_num(p.c.gap_half_widths)},
                       {"within_2_half_widths", p.c.within_2_half_widths}});
  j["golden_outside_ci"] = outside;
  j["points_target_met"] = g.target_error_m > 0 ? nlohmann::json(met) : nlohmann::json(nullptr);
  j["confidence"] = 0.95;
  return j;
}

std::string mc_summary_text(const McGrid& g) {
  const nlohmann::json j = mc_summary_json(g);
  std::string t =
      fmt::format("Monte Carlo ({} trials/point{}): {} points, {} trials\n", g.trials,
                  g.target_error_m > 0 ? fmt::format(", target CI half-width {:g} m", g.target_error_m) : "",
                  j["points"].get<long long>(), j["trials_total"].get<long long>());
  if (j["points"].get<long long>() > 0)
    t += fmt::format(
        "  accuracy {:.4g} .. {:.4g} m, largest 95% CI half-width {:.3g} m\n"
        "  golden inside the MC 95% CI at {} of {} points; within 2 CI half-widths (the stated test) at {}\n"
        "  (compared: the accuracy without outliers where golden splits them off, P(detect), P(outlier); the total\n"
        "  accuracy, outliers included, within 2 half-widths at {}, {} outlier trials in all)\n",
        j["accuracy_min_m"].is_null() ? NAN : j["accuracy_min_m"].get<double>(),
        j["accuracy_max_m"].is_null() ? NAN : j["accuracy_max_m"].get<double>(),
        j["accuracy_ci_half_width_max_m"].is_null() ? NAN : j["accuracy_ci_half_width_max_m"].get<double>(),
        j["points_golden_in_ci"].get<long long>(), j["points"].get<long long>(),
        j["points_golden_within_2_half_widths"].get<long long>(),
        j["points_total_accuracy_within_2_half_widths"].get<long long>(), j["outliers_total"].get<long long>());
  // Every quantity where golden falls outside the CI (all of them are in mc_golden_outside_ci.csv).
  const std::vector<McOutsidePoint> outside = mc_golden_outside_ci(g);
  constexpr std::size_t kShown = 40;
  for (std::size_t k = 0; k < outside.size() && k < kShown; ++k) {
    const McOutsidePoint& p = outside[k];
    const bool metres = p.c.quantity.back() == 'm';
    const double f = metres ? 1e3 : 1.0;
    const char* unit = metres ? " mm" : "";
    t += fmt::format(
        "  golden outside the CI at signal {:.4g} {}, background {:.4g} {}: {} golden {:.4g}{}, MC {:.4g} [{:.4g}, "
        "{:.4g}]{}, p_detect {:.3g}, gap {} = {:.1f} half-widths{}\n",
        p.signal, g.ev->signal.unit, p.background, g.ev->background.unit, p.c.quantity, p.c.golden * f, unit,
        p.c.mc.value * f, p.c.mc.lo * f, p.c.mc.hi * f, unit, p.p_detect,
        std::isfinite(p.gap_rel) ? fmt::format("{:+.1f}%", 100 * p.gap_rel) : std::string("(MC 0)"),
        p.c.gap_half_widths, p.c.within_2_half_widths ? "" : " (fails the stated test)");
  }
  if (outside.size() > kShown) t += fmt::format("  ... {} more in mc_golden_outside_ci.csv\n", outside.size() - kShown);
  return t;
}

std::string render_mc_plot(OutputDir& out, const McGrid& g) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    return "gnuplot not found: mc_accuracy plot skipped (scripts/install-deps.sh installs gnuplot-nox)";
  const auto& ev = *g.ev;
  const std::size_t ns = ev.signal.values.size(), nb = ev.background.values.size();
  // Up to 6 background rows with MC points, evenly spread.
  std::vector<std::size_t> rows;
  for (std::size_t ib = 0; ib < nb; ++ib)
    for (std::size_t is = 0; is < ns; ++is)
      if (g.stats[ib * ns + is]) {
        rows.push_back(ib);
        break;
      }
  if (rows.empty()) return "";
  std::vector<std::size_t> pick;
  const std::size_t k = std::min<std::size_t>(6, rows.size());
  for (std::size_t i = 0; i < k; ++i) pick.push_back(rows[k == 1 ? 0 : i * (rows.size() - 1) / (k - 1)]);
  const std::string data = out.scratch("mc_accuracy.dat");
  {
    std::ofstream d(data);
    for (std::size_t ib : pick) {
      for (std::size_t is = 0; is < ns; ++is) {
        const auto& s = g.stats[ib * ns + is];
        if (!s || !std::isfinite(s->rms.value)) continue;
        const double f = 1e3 * g.metres_per_unit;
        d << fmt::format("{:.9g} {:.9g} {:.9g} {:.9g} {:.9g}\n", ev.signal.values[is], s->rms.value * f, s->rms.lo * f,
                         s->rms.hi * f, ev.points[ib * ns + is].accuracy_m * 1e3);
      }
      d << "\n\n";
    }
  }
  std::string script;
  std::vector<std::string> images;
  for (const std::string ext : {"png", "svg"}) {
    images.push_back("mc_accuracy." + ext);
    script += "reset\n";
    script +=
        ext == "png" ? "set terminal pngcairo size 900,600 noenhanced\n" : "set terminal svg size 900,600 noenhanced\n";
    script += fmt::format("set output '{}'\n", out.staged(images.back())) + plot_preamble();
    script += fmt::format(
        "set title '{}: Monte Carlo (points, 95% CI) and golden (lines)'\n"
        "set logscale xy\n{}set format y '%g'\nset xlabel 'signal [{}]'\nset ylabel 'rms range error [mm]'\n"
        "set key outside right top title 'background'\nset grid\n",
        ev.sensor, log_format("x", ev.signal.unit), ev.signal.unit);
    std::string plot = "plot ";
    for (std::size_t i = 0; i < pick.size(); ++i) {
      const std::string bg = fmt::format("{:.3g} {}", ev.background.values[pick[i]], ev.background.unit);
      plot += fmt::format(
          "{}'{}' index {} using 1:2:3:4 with yerrorbars lc rgb '{}' pt 7 ps 0.6 title '{}', "
          "'{}' index {} using 1:5 with lines lw 2 lc rgb '{}' notitle",
          i ? ", " : "", data, i, series_colour(i), bg, data, i, series_colour(i));
    }
    script += plot + "\nunset output\n";
  }
  const std::string gp = out.scratch("mc_plot.gp");
  std::ofstream(gp) << script;
  const std::string log = out.scratch("mc_gnuplot.log");
  if (std::system(fmt::format("gnuplot '{}' >'{}' 2>&1", gp, log).c_str()) != 0) {
    for (const auto& name : images) std::remove(out.scratch(name).c_str());
    return "gnuplot failed on mc_accuracy: plot skipped";
  }
  return "";
}

}  // namespace rangesim::app::mc
