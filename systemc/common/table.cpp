#include "systemc/common/table.h"

namespace rangesim::systemc {

std::string table_csv(const Table& t) {
  std::string csv;
  const std::size_t C = t.columns.size();
  // ~12 characters per cell: one allocation for most tables.
  csv.reserve(16 * C + 12 * t.cells.size());
  for (std::size_t c = 0; c < C; ++c) {
    if (c) csv += ',';
    csv += t.columns[c].name;
  }
  csv += '\n';
  for (std::size_t i = 0; i < t.cells.size(); i += C) {
    for (std::size_t c = 0; c < C; ++c) {
      if (c) csv += ',';
      if (t.columns[c].integer)
        append_csv_integer(csv, static_cast<long long>(t.cells[i + c]));
      else
        append_csv_number(csv, t.cells[i + c]);
    }
    csv += '\n';
  }
  return csv;
}

}  // namespace rangesim::systemc
