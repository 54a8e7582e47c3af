#pragma once
// A table of numbers as a scene run returns it (points.csv / points.npy): named columns, cells
// row-major as doubles. The run fills it; app/simulate/ writes it as CSV or as a NumPy .npy
// record array. Holding numbers rather than text keeps formatting out of the model run and lets
// a large table go to disk without any text at all.
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace rangesim::systemc {

struct Table {
  struct Column {
    std::string name;      // CSV header / .npy field name
    bool integer = false;  // written as an integer (CSV) / '<i8' (.npy); never NaN
  };
  std::vector<Column> columns;
  std::vector<double> cells;  // row-major; NaN = empty (floating columns only)

  Table() = default;
  explicit Table(std::vector<Column> c) : columns(std::move(c)) {}
  bool empty() const { return columns.empty(); }
  std::size_t rows() const { return columns.empty() ? 0 : cells.size() / columns.size(); }
  void add_row(std::initializer_list<double> values) {
    assert(values.size() == columns.size());
    cells.insert(cells.end(), values);
  }
};

// Appends `v` as the CSV has always printed it: printf "%.9g" ("" for NaN/inf). std::to_chars
// gives the same characters as printf without a locale or a temporary string.
inline void append_csv_number(std::string& out, double v) {
  if (!std::isfinite(v)) return;  // NaN or inf: empty cell
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 9);
  out.append(buf, r.ptr);
}
inline void append_csv_integer(std::string& out, long long v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

// The table as CSV: header line, then one line per row.
std::string table_csv(const Table& t);

}  // namespace rangesim::systemc
