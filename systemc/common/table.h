#pragma once
// A table of numbers as a scene run returns it (points.csv / points.npy): named columns, cells
// row-major as doubles. The run fills it, or for a large table gives a producer that makes its rows
// in order, block by block, when they are written (a full ls-conventional map has 137,000 points, a
// 14 MB table never held whole); app/simulate/ writes it as CSV or as a NumPy .npy record array.
// Holding numbers rather than text keeps formatting out of the model run and lets a large table go
// to disk without any text at all.
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace rangesim::systemc {

struct Table {
  // What a column holds, which sets how it is written: Real as "%.9g" (CSV) / '<f8' (.npy, NaN = empty);
  // Integer (a count) as an integer / '<i8'; Index (frame, row, column: |v| < 2^31) as an integer /
  // '<i4'; Flag (0 or 1) as 0/1 / '|b1' (NumPy bool). The narrow .npy types keep a full
  // ls-conventional map's table at 71 bytes a record instead of 104: less to write.
  enum class Kind { Real, Integer, Index, Flag };
  struct Column {
    std::string name;        // CSV header / .npy field name
    Kind kind = Kind::Real;  // Integer and Flag columns are never NaN
    bool integer() const { return kind != Kind::Real; }
  };
  // Called with consecutive blocks of whole rows (cells row-major, and the count of rows).
  using BlockSink = std::function<void(const double* cells, std::size_t rows)>;

  std::vector<Column> columns;
  std::vector<double> cells;  // row-major; NaN = empty (floating columns only)
  // Or: produce(sink) calls sink with every row in order, in blocks; produced_rows rows in all.
  std::function<void(const BlockSink& sink)> produce;
  std::size_t produced_rows = 0;

  Table() = default;
  explicit Table(std::vector<Column> c) : columns(std::move(c)) {}
  bool empty() const { return columns.empty(); }
  std::size_t rows() const {
    if (produce) return produced_rows;
    return columns.empty() ? 0 : cells.size() / columns.size();
  }
  std::size_t values() const { return rows() * columns.size(); }
  void add_row(std::initializer_list<double> values) {
    assert(values.size() == columns.size() && !produce);
    cells.insert(cells.end(), values);
  }
  // Every row in order, in blocks: the held cells at once, or the producer's blocks.
  void for_each_block(const BlockSink& sink) const {
    if (produce)
      produce(sink);
    else if (!cells.empty())
      sink(cells.data(), rows());
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
