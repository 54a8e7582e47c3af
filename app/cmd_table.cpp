// rangesim table: thesis Table 5.1 for the four seed sensors beside rangesim's values, and the
// chips' published figures with their status.
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/command_data.h"
#include "app/commands.h"
#include "app/output_dir.h"
#include "app/progress_line.h"
#include "core/preset.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/table_5_1.h"

namespace rangesim::app {

namespace {

struct Cell {
  std::string thesis, ours, difference, note;
  double thesis_value = golden::kNaN, ours_value = golden::kNaN;
};

struct Column {
  std::string sensor, reference;
  bool modelled = false;
  std::vector<Cell> cells;
  std::vector<golden::PublishedFigure> published;
};

std::string key_with_suffix(const ParamSet& p, const std::string& suffix) {
  for (const auto& [key, _] : p.values())
    if (key.size() >= suffix.size() && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0) return key;
  return "";
}

// Value in the row's unit shown with an engineering prefix.
std::string show(double v, const std::string& unit) {
  if (!std::isfinite(v)) return "-";
  if (unit == "dB") return fmt::format("{:.2f} dB", v);
  if (unit == "m") return fmt::format("{:.3g} mm", v * 1e3);
  if (unit == "s") return v < 1e-3 ? fmt::format("{:.4g} us", v * 1e6) : fmt::format("{:.4g} ms", v * 1e3);
  if (unit == "F") return fmt::format("{:.4g} fF", v * 1e15);
  return fmt::format("{:g}", v);
}

std::string difference(double ours, double thesis, const std::string& unit) {
  if (!std::isfinite(ours) || !std::isfinite(thesis)) return "";
  const double d = ours - thesis;
  if (unit == "dB") return fmt::format("{:+.2f} dB", d);
  if (unit == "m") return fmt::format("{:+.3g} mm", d * 1e3);
  if (std::fabs(d) <= 1e-9 * std::fabs(thesis)) return "0";
  return fmt::format("{:+.3g}x", ours / thesis);
}

// The command's progress, one line per sensor. Golden models report through a plain function
// pointer, hence the pointer here; per thread, since the Python module may build tables on
// several threads at once.
thread_local ProgressLine* g_progress = nullptr;
void table_progress(int done, int total) {
  if (g_progress) g_progress->update(done, total);
}

Column build_column(const golden::ThesisColumn& tc, golden::ProgressFn progress) {
  Column c{tc.sensor, tc.reference, false, {}, {}};
  const ParamSet params = load_preset(tc.sensor);
  c.modelled = golden::golden_model(tc.sensor) != nullptr;
  golden::EvalResult ev;
  if (c.modelled) {
    golden::DiscardPoints discard;  // the table needs the summary and the ranges only
    ev = golden::evaluate_sensor_streamed(params, discard, progress);
    c.published = golden::published_figures(params);
  }
  const bool total_sbr = tc.sbr_total;  // eq. 3.11, or eq. 3.23/4.11
  const auto& rows = golden::table_rows();
  for (size_t i = 0; i < rows.size(); ++i) {
    Cell cell;
    cell.thesis = tc.cells[i].text;
    cell.thesis_value = tc.cells[i].value;
    const auto& r = rows[i];
    double v = golden::kNaN;
    switch (r.row) {
      case golden::TableRow::Type: cell.ours = tc.sensor.rfind("ls-", 0) == 0 ? "LS" : "TOF"; break;
      case golden::TableRow::IntegrationTime: {
        const std::string k = key_with_suffix(params, "integration_time_s");
        if (!k.empty()) v = params.real(k);
        for (const auto& [key, value] : ev.summary_extra)  // tof-lockin: accumulations x repetition period
          if (k.empty() && key == "accumulation_time_s") v = value;
        break;
      }
      case golden::TableRow::WellCapacity:
        for (const char* k : {"pixel.pd_capacitance_F", "correlator.capacitance_plus_F", "pixel.fd1_capacitance_F"})
          if (params.has(k)) v = params.real(k);
        break;
      case golden::TableRow::AdcTdc: {
        const std::string bits = key_with_suffix(params, ".adc_bits");
        if (params.has("tdc.lsb_s")) {
          cell.ours = fmt::format("{:.4g} ps LSB", params.real("tdc.lsb_s") * 1e12);
          cell.ours_value = params.real("tdc.lsb_s");
        } else if (!bits.empty()) {
          cell.ours = fmt::format("{}-bit", params.integer(bits));
          cell.ours_value = static_cast<double>(params.integer(bits));
        }
        break;
      }
      case golden::TableRow::SignalLight: v = c.modelled ? ev.signal_range.range_dB : v; break;
      case golden::TableRow::BackgroundLight: v = c.modelled ? ev.background_range.range_dB : v; break;
      case golden::TableRow::SbrMax: v = c.modelled ? (total_sbr ? ev.sbr_max_dB : ev.sbr_ratio_max_dB) : v; break;
      case golden::TableRow::SbrMin: v = c.modelled ? (total_sbr ? ev.sbr_min_dB : ev.sbr_ratio_min_dB) : v; break;
      case golden::TableRow::AccuracyMax: v = c.modelled ? ev.accuracy_max_m : v; break;
      case golden::TableRow::AccuracyMin: v = c.modelled ? ev.accuracy_min_m : v; break;
    }
    const bool model_row = r.row >= golden::TableRow::SignalLight;
    if (cell.ours.empty()) {
      cell.ours_value = v;
      cell.ours = model_row && !c.modelled ? "not modelled yet" : show(v, r.unit);
    }
    if (r.row != golden::TableRow::AdcTdc || cell.thesis_value == cell.ours_value)
      cell.difference = difference(cell.ours_value, cell.thesis_value, r.unit);
    for (const auto& [id, note] : tc.notes)
      if (id == r.id) cell.note = note;
    if ((r.row == golden::TableRow::SbrMax || r.row == golden::TableRow::SbrMin) && c.modelled && cell.note.empty())
      cell.note = total_sbr ? "eq. 3.11, (V_sig + V_bg) / V_bg" : "eq. 3.23 / 4.11, signal / background";
    c.cells.push_back(cell);
  }
  return c;
}

std::string tolerance_text(double rel) { return fmt::format("±{:g}%", rel * 100); }

// Per basis: figures and how many are reproduced.
struct BasisCount {
  int total = 0, reproduced = 0;
};
std::vector<std::pair<golden::FigureBasis, BasisCount>> basis_counts(const std::vector<Column>& cols) {
  std::vector<std::pair<golden::FigureBasis, BasisCount>> out;
  for (golden::FigureBasis b : golden::kFigureBases) out.push_back({b, {}});
  for (const auto& c : cols)
    for (const auto& f : c.published)
      for (auto& [b, n] : out)
        if (b == f.basis) ++n.total, n.reproduced += f.reproduced();
  return out;
}

// "by basis: calibrated 10 (10 reproduced), ...; predicted figures reproduced: 4 of 27"
std::string basis_summary_text(const std::vector<Column>& cols) {
  std::string t = "by basis:";
  BasisCount predicted;
  for (const auto& [b, n] : basis_counts(cols)) {
    t += fmt::format(" {} {} ({} reproduced){}", golden::to_string(b), n.total, n.reproduced,
                     b == golden::FigureBasis::Predicted ? ";" : ",");
    if (b == golden::FigureBasis::Predicted) predicted = n;
  }
  return t + fmt::format(" predicted figures reproduced: {} of {}", predicted.reproduced, predicted.total);
}

std::string markdown(const std::vector<Column>& cols, bool published) {
  std::ostringstream o;
  o << "# Thesis Table 5.1 beside rangesim\n";
  for (const auto& c : cols) {
    o << fmt::format("\n## {} {}{}\n\n| row | thesis | rangesim | difference | note |\n|---|---|---|---|---|\n",
                     c.sensor, c.reference, c.modelled ? "" : " (golden model not yet available)");
    for (size_t i = 0; i < c.cells.size(); ++i) {
      const auto& cell = c.cells[i];
      o << fmt::format("| {} | {} | {} | {} | {} |\n", golden::table_rows()[i].label, cell.thesis, cell.ours,
                       cell.difference, cell.note);
    }
  }
  if (published) {
    o << "\n# Published figures\n\n"
         "basis: `calibrated` a preset value was tuned to this figure (named); `fitted` follows from a preset value "
         "fitted to several figures at once; `arithmetic` follows from published numbers or structure alone; "
         "`predicted` the model's output from values not tuned to it. Only a reproduced `predicted` figure is "
         "evidence of fidelity.\n\n"
         "| sensor | figure | published | rangesim | tolerance | status | basis | note |\n"
         "|---|---|---|---|---|---|---|---|\n";
    for (const auto& c : cols)
      for (const auto& f : c.published)
        o << fmt::format("| {} | {} | {:.4g} {} | {:.4g} {} | {} | {} | {} | {} |\n", f.sensor, f.description,
                         f.published, f.unit, f.ours, f.unit, tolerance_text(f.tolerance),
                         f.reproduced() ? "reproduced" : "differs", f.basis_text(), f.note);
    o << "\n" << basis_summary_text(cols) << "\n";
  }
  return o.str();
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char ch : s) o += ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : ch == '&' ? "&amp;" : std::string(1, ch);
  return o;
}

std::string html(const std::vector<Column>& cols) {
  std::ostringstream o;
  o << "<!doctype html><meta charset=utf-8><title>rangesim: Table 5.1</title><style>"
       "body{font-family:sans-serif;margin:2em}table{border-collapse:collapse;margin-bottom:2em}"
       "td,th{border:1px solid #bbb;padding:4px 8px;vertical-align:top}th{background:#eee}"
       "td.n{text-align:right;white-space:nowrap}td.note{max-width:40em;font-size:90%}</style>"
       "<h1>Thesis Table 5.1 beside rangesim</h1>";
  for (const auto& c : cols) {
    o << fmt::format("<h2>{} {}</h2><table><tr><th>row<th>thesis<th>rangesim<th>difference<th>note", c.sensor,
                     c.reference);
    for (size_t i = 0; i < c.cells.size(); ++i) {
      const auto& cell = c.cells[i];
      o << fmt::format("<tr><td>{}<td class=n>{}<td class=n>{}<td class=n>{}<td class=note>{}",
                       golden::table_rows()[i].label, html_escape(cell.thesis), html_escape(cell.ours),
                       html_escape(cell.difference), html_escape(cell.note));
    }
    o << "</table>";
  }
  o << "<h1>Published figures</h1><table><tr><th>sensor<th>figure<th>published<th>rangesim<th>tolerance<th>status"
       "<th>basis<th>note";
  for (const auto& c : cols)
    for (const auto& f : c.published)
      o << fmt::format(
          "<tr><td>{}<td>{}<td class=n>{:.4g} {}<td class=n>{:.4g} {}<td class=n>{}<td>{}<td>{}<td class=note>{}",
          f.sensor, html_escape(f.description), f.published, f.unit, f.ours, f.unit, tolerance_text(f.tolerance),
          f.reproduced() ? "reproduced" : "differs", html_escape(f.basis_text()), html_escape(f.note));
  o << "</table><p>" << html_escape(basis_summary_text(cols)) << "</p>\n";
  return o.str();
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string o = "\"";
  for (char ch : s) o += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return o + "\"";
}

std::string num_or_empty(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : ""; }

nlohmann::json json_num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// The columns of the registered sensors that have one in the thesis's table, in registry order.
std::vector<Column> build_columns(golden::ProgressFn progress) {
  std::vector<const golden::ThesisColumn*> thesis;
  for (const auto& s : sensors())
    if (const golden::GoldenModel* m = golden::golden_model(s.id); m && m->table_column)
      thesis.push_back(m->table_column);
  std::vector<Column> cols;
  for (const golden::ThesisColumn* tc : thesis) {
    std::optional<ProgressLine> line;
    if (progress == &table_progress) {
      line.emplace(fmt::format("table: sensor {}/{}", cols.size() + 1, thesis.size()), "operating points");
      g_progress = &*line;
    }
    cols.push_back(build_column(*tc, progress));
    g_progress = nullptr;
  }
  return cols;
}

nlohmann::json columns_json(const std::vector<Column>& cols) {
  nlohmann::json j;
  j["table_5_1"] = nlohmann::json::array();
  for (const auto& c : cols) {
    nlohmann::json rows = nlohmann::json::array();
    for (size_t i = 0; i < c.cells.size(); ++i) {
      const auto& cell = c.cells[i];
      const auto& r = golden::table_rows()[i];
      rows.push_back({{"row", r.id},
                      {"label", r.label},
                      {"unit", r.unit},
                      {"thesis", cell.thesis},
                      {"thesis_value", json_num(cell.thesis_value)},
                      {"rangesim", cell.ours},
                      {"rangesim_value", json_num(cell.ours_value)},
                      {"difference", cell.difference},
                      {"note", cell.note}});
    }
    j["table_5_1"].push_back(
        {{"sensor", c.sensor}, {"reference", c.reference}, {"golden_modelled", c.modelled}, {"rows", rows}});
  }
  j["published"] = nlohmann::json::array();
  int reproduced = 0, total = 0;
  for (const auto& c : cols)
    for (const auto& f : c.published) {
      ++total;
      reproduced += f.reproduced();
      j["published"].push_back({{"sensor", f.sensor},
                                {"id", f.id},
                                {"description", f.description},
                                {"published", f.published},
                                {"unit", f.unit},
                                {"rangesim", json_num(f.ours)},
                                {"tolerance", f.tolerance},
                                {"reproduced", f.reproduced()},
                                {"basis", golden::to_string(f.basis)},
                                {"basis_key", f.basis_key},
                                {"fitted_to", f.fitted_to},
                                {"basis_note", f.basis_note},
                                {"note", f.note}});
    }
  j["published_reproduced"] = reproduced;
  j["published_total"] = total;
  j["published_by_basis"] = nlohmann::json::object();
  for (const auto& [b, n] : basis_counts(cols))
    j["published_by_basis"][golden::to_string(b)] = {{"total", n.total}, {"reproduced", n.reproduced}};
  return j;
}

}  // namespace

nlohmann::json table_json(golden::ProgressFn progress) { return columns_json(build_columns(progress)); }

int run_table(const TableOptions& opt) {
  std::unique_ptr<OutputDir> out;
  if (!opt.out.empty()) out = std::make_unique<OutputDir>(opt.out, "--out", OutputFolder{"table", opt.force});
  const std::vector<Column> cols = build_columns(&table_progress);
  const nlohmann::json j = columns_json(cols);
  const int reproduced = j["published_reproduced"].get<int>(), total = j["published_total"].get<int>();

  if (out) {
    std::ostringstream csv;
    csv << "sensor,reference,row,unit,thesis,thesis_value,rangesim,rangesim_value,difference,note\n";
    for (const auto& c : cols)
      for (size_t i = 0; i < c.cells.size(); ++i) {
        const auto& cell = c.cells[i];
        const auto& r = golden::table_rows()[i];
        csv << fmt::format("{},{},{},{},{},{},{},{},{},{}\n", c.sensor, c.reference, r.id, r.unit,
                           csv_field(cell.thesis), num_or_empty(cell.thesis_value), csv_field(cell.ours),
                           num_or_empty(cell.ours_value), csv_field(cell.difference), csv_field(cell.note));
      }
    std::ostringstream pcsv;
    pcsv << "sensor,id,description,published,unit,rangesim,tolerance,status,basis,basis_key,fitted_to,basis_note,note\n";
    for (const auto& c : cols)
      for (const auto& f : c.published) {
        std::string fitted;
        for (const auto& id : f.fitted_to) fitted += (fitted.empty() ? "" : ";") + id;
        pcsv << fmt::format("{},{},{},{:.6g},{},{},{:g},{},{},{},{},{},{}\n", f.sensor, f.id, csv_field(f.description),
                            f.published, f.unit, num_or_empty(f.ours), f.tolerance,
                            f.reproduced() ? "reproduced" : "differs", golden::to_string(f.basis), f.basis_key,
                            csv_field(fitted), csv_field(f.basis_note), csv_field(f.note));
      }
    out->write("table5_1.csv", csv.str());
    out->write("published_figures.csv", pcsv.str());
    out->write("table5_1.md", markdown(cols, true));
    out->write("table5_1.html", html(cols));
    out->write("table5_1.json", j.dump(2) + "\n");
    out->commit();
  }

  if (opt.json) {
    fmt::print("{}\n", j.dump(2));
  } else {
    fmt::print("{}", markdown(cols, opt.published));
    fmt::print("\npublished figures: {} of {} reproduced{}\n{}\n", reproduced, total,
               opt.published ? "" : " (--published lists them)", basis_summary_text(cols));
    if (out)
      fmt::print("written to {}/: table5_1.md, table5_1.html, table5_1.csv, table5_1.json, published_figures.csv\n",
                 opt.out);
  }
  return 0;
}

}  // namespace rangesim::app
