#include "systemc/common/table.h"

namespace rangesim::systemc {

std::string table_csv(const Table& t) {
  std::string csv;
  const std::size_t C = t.columns.size();
  // ~12 characters per cell: one allocation for most tables.
  csv.reserve(16 * C + 12 * t.values());
  for (std::size_t c = 0; c < C; ++c) {
    if (c) csv += ',';
    csv += t.columns[c].name;
  }
  csv += '\n';
  t.for_each_block([&](const double* cells, std::size_t rows) {
    for (std::size_t i = 0; i < rows * C; i += C) {
      for (std::size_t c = 0; c < C; ++c) {
        if (c) csv += ',';
        if (t.columns[c].integer())
          append_csv_integer(csv, static_cast<long long>(cells[i + c]));
        else
          append_csv_number(csv, cells[i + c]);
      }
      csv += '\n';
    }
  });
  return csv;
}

}  // namespace rangesim::systemc
