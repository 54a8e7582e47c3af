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
       {{"background_light",
         "above ~0.28 nA the background's shot noise through the correlator makes background-only pixels cross "
         "V_cmp (row false activation > 1%); the thesis's evaluation has no noise, so it has no such limit"},
        {"sbr_max",
         "eq. 3.23: the grid's top signal over its lowest background (0.001 V equivalent); 83 dB implies a 20 dB "
         "lower background floor, and the thesis's spans (43.5 + 103.5 dB) do not add up to its SBR' span (83 + 62 dB)"},
        {"sbr_min", "eq. 3.23: weakest detectable signal under the strongest background where it is detectable, "
                    "limited by the background's shot noise rather than by saturation"},
        {"accuracy_max",
         "rms error over the detectable area at 1 m; at the nominal point the maximum error (|bias| + 3 std) is 2.57 mm "
         "against the chip's 1.5 mm: the 1-bit edge readout spreads its error wider"},
        {"accuracy_min",
         "the chip's 0.6 mm std in the effective area is reproduced at the nominal point (baseline calibrated to it); "
         "over the grid the best is at the strongest signal"}}},
      {"tof-lockin",
       "[12]",
       {{"TOF", kNaN}, {"50 us", 50e-6}, {"40fF", 40e-15}, {"1bit", 1}, {"43.5dB", 43.5}, {"83.5", 83.5},
        {"62dB", 62}, {"-62dB", -62}, {"12.6mm", 12.6e-3}, {"40.7mm", 40.7e-3}},
       {{"well_capacity", "Table 4.1 of the thesis gives 10 fF for this sensor; Table 5.1 says 40 fF; each table's "
                          "numbers fit only its own value"},
        {"adc_tdc", "a 1-bit ADC cannot form the ratio of eq. 4.9; the converter is assumed 12-bit"},
        {"signal_light",
         "the SNR >= 3 rule (readout.min_snr) lifts the lower edge; with min_snr = 0 it is 43.52 dB, the thesis's "
         "noise-free 0.01-1.5 nA"},
        {"background_light",
         "lower edge is the grid, upper edge is tap saturation at 10 fF; 83.5 dB = 20 log(15 nA / 1 pA) fits 40 fF "
         "(Table 5.1), not Table 4.1's 10 fF"},
        {"sbr_max", "eq. 4.11 (signal / background): the grid's top signal over its lowest background"},
        {"sbr_min", "eq. 4.11: weakest detectable signal under the strongest unsaturated background"},
        {"accuracy_max",
         "the thesis's 'max' (12.6 mm) is smaller than its 'min' (40.7 mm): the two are swapped. Our worst is at the "
         "SNR-3 signal edge (metres); 40.7 mm is pure shot noise at 0.135 V, a level the thesis does not name"},
        {"accuracy_min",
         "ours includes kTC and read noise and the ambient frame; 12.6 mm is pure signal shot noise at 1.4 V, 1 m, "
         "10 fF, which rangesim gives as 12.65 mm"}}},
      {"tof-spad",
       "[11]",
       {{"TOF", kNaN}, {"-", kNaN}, {"-", kNaN}, {"90ns", 90e-9}, {"20dB", 20}, {"12dB", 12}, {"65dB", 65},
        {"40dB", 40}, {"5.8", kNaN}, {"37", kNaN}},
       {{"adc_tdc",
         "90 ns cannot resolve mm: one LSB is c x 90 ns / 2 = 13.5 m; the chip's TDC LSB is ~97 ps (recalled) and "
         "the thesis text assumes 200 ps"},
        {"signal_light",
         "the thesis's SPAD evaluation is unfinished (4.2.3), so column [11] follows from no stated model; ours: "
         "200 counts/s (10 counts, 5 sigma above background in the window) to the grid's end at 10/s background"},
        {"background_light",
         "as above; ours: the whole grid, 10 to 1e8 counts/s, at the top signal (background subtraction and the "
         "first-photon histogram keep the peak found)"},
        {"sbr_max", "eq. 4.11 style over our grid; no model behind the thesis's 65 dB"},
        {"sbr_min", "eq. 4.11 style over our grid; 20 + 12 dB of spans cannot give the thesis's 25 dB SBR' span"},
        {"accuracy_max", "the thesis gives no unit for 5.8 and 37 (read as mm); ours: best over the detectable area"},
        {"accuracy_min", "ours: worst over the detectable area; the published chip figures (9 mm nonlinearity, 5.2 mm "
                         "uncertainty at the far end) are reproduced, see --published"}}},
  };
  return cols;
}

}  // namespace rangesim::app
