#include "app/table_data.h"

#include <limits>

namespace rangesim::app {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

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

const std::vector<ThesisColumn>& thesis_table_5_1() {
  static const std::vector<ThesisColumn> cols = {
      {"ls-conventional",
       "[31]",
       {{"LS", kNaN}, {"50 us", 50e-6}, {"40f", 40e-15}, {"1-bit", 1}, {"43.5dB", 43.5}, {"63.5", 63.5},
        {"51dB", 51}, {"0.06dB", 0.06}, {"1.2mm", 1.2e-3}, {"0.4mm", 0.4e-3}},
       {{"background_light",
         "the thesis's detectable background at 1.5 V signal is 0.001-0.241 V = 47.6 dB, which rangesim reproduces; "
         "63.5 dB is 20 log(1.5/0.001), the maximum signal over the minimum background"},
        {"sbr_max",
         "eq. 3.11; the thesis calls 1.5 V over 0.001 V detectable, where eq. 3.11 and eq. 3.23 both give 63.5 dB; 51 dB "
         "follows from no operating point it names"},
        {"sbr_min",
         "eq. 3.11 tends to 0 dB for the weakest signal under the strongest background; ours is taken at the grid's "
         "1 V background edge. The thesis attaches 0.06 dB to 1.5 V over 0.24 V, where eq. 3.11 gives 17.2 dB"},
        {"accuracy_max",
         "rms error with shot, kTC and read noise; the maximum sits at the highest background, where rare false "
         "activations move an edge by many pixels (0.29 px = 5.4 mm up to 0.24 V background)"},
        {"accuracy_min",
         "a 1-bit readout with four samplings cannot beat its quantisation (0.03-0.05 px rms); the thesis's "
         "0.004/0.089 px -> 0.4/1.2 mm is not one linear mapping"}}},
      {"ls-demodulation",
       "[27]",
       {{"LS", kNaN}, {"50 us", 50e-6}, {"37fF", 37e-15}, {"1-bit", 1}, {"43.5dB", 43.5}, {"103.5", 103.5},
        {"83dB", 83}, {"-62dB", -62}, {"1.5mm", 1.5e-3}, {"0.6mm", 0.6e-3}},
       {}},
      {"tof-lockin",
       "[12]",
       {{"TOF", kNaN}, {"50 us", 50e-6}, {"40fF", 40e-15}, {"1bit", 1}, {"43.5dB", 43.5}, {"83.5", 83.5},
        {"62dB", 62}, {"-62dB", -62}, {"12.6mm", 12.6e-3}, {"40.7mm", 40.7e-3}},
       {{"well_capacity", "Table 4.1 of the thesis gives 10 fF for this sensor; Table 5.1 says 40 fF"},
        {"accuracy_max", "the thesis's 'max' (12.6 mm) is smaller than its 'min' (40.7 mm): the two are swapped"}}},
      {"tof-spad",
       "[11]",
       {{"TOF", kNaN}, {"-", kNaN}, {"-", kNaN}, {"90ns", 90e-9}, {"20dB", 20}, {"12dB", 12}, {"65dB", 65},
        {"40dB", 40}, {"5.8", kNaN}, {"37", kNaN}},
       {{"adc_tdc",
         "90 ns cannot resolve mm: one LSB is c x 90 ns / 2 = 13.5 m; the chip's TDC LSB is ~97 ps (recalled) and "
         "the thesis text assumes 200 ps"},
        {"accuracy_max", "the thesis gives no unit for 5.8 and 37"}}},
  };
  return cols;
}

}  // namespace rangesim::app
