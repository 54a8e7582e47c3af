#pragma once
// Thesis Table 5.1 as published (rows here, one column per sensor in golden/<sensor>/table_column.cpp,
// reached through the sensor's GoldenModel), with the notes that explain where rangesim's value
// differs and why.
#include <string>
#include <vector>

namespace rangesim::golden {

// Rows of Table 5.1, in the thesis's order.
enum class TableRow {
  Type,
  IntegrationTime,
  WellCapacity,
  AdcTdc,
  SignalLight,
  BackgroundLight,
  SbrMax,
  SbrMin,
  AccuracyMax,
  AccuracyMin
};

struct TableRowInfo {
  TableRow row;
  std::string id;     // snake_case key in JSON/CSV
  std::string label;  // as in the thesis
  std::string unit;   // unit of the numeric values ("" for text rows)
};
const std::vector<TableRowInfo>& table_rows();

struct ThesisCell {
  std::string text;  // as printed in the thesis
  double value;      // numeric value in the row's unit (NaN for text or "-")
};

struct ThesisColumn {
  std::string sensor;      // preset id
  std::string reference;   // "[31]"
  bool sbr_total = false;  // the column's SBR' is eq. 3.11, (signal + background) / background; else eq. 3.23 / 4.11
  std::vector<ThesisCell> cells;  // one per table_rows()
  // Why rangesim's value differs (per row id), "" where it agrees or nothing is known.
  std::vector<std::pair<std::string, std::string>> notes;
};

}  // namespace rangesim::golden
