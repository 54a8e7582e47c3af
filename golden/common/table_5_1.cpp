#include "golden/common/table_5_1.h"

namespace rangesim::golden {

const std::vector<TableRowInfo>& table_rows() {
  static const std::vector<TableRowInfo> rows = {
      {TableRow::Type, "type", "Type", ""},
      {TableRow::IntegrationTime, "integration_time", "Integration Time", "s"},
      {TableRow::WellCapacity, "well_capacity", "Well Capacity", "F"},
      {TableRow::AdcTdc, "adc_tdc", "ADC/TDC", ""},
      {TableRow::SignalLight, "signal_light", "Signal Light", "dB"},
      {TableRow::BackgroundLight, "background_light", "Background Light", "dB"},
      {TableRow::SbrMax, "sbr_max", "SBR' Max", "dB"},
      {TableRow::SbrMin, "sbr_min", "SBR' Min", "dB"},
      {TableRow::AccuracyMax, "accuracy_max", "Range Accuracy Max", "m"},
      {TableRow::AccuracyMin, "accuracy_min", "Range Accuracy Min", "m"},
  };
  return rows;
}

}  // namespace rangesim::golden
