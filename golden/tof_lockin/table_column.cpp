// Column [12] of thesis Table 5.1: the tof-lockin chip as the thesis lists it, and why rangesim's
// value differs where it does (`rangesim table`).
#include "golden/tof_lockin/model.h"

namespace rangesim::golden {

const ThesisColumn& tof_lockin_table_column() {
  static const ThesisColumn column{
      "tof-lockin",
      "[12]",
      false,
      {{"TOF", kNaN},
       {"50 us", 50e-6},
       {"40fF", 40e-15},
       {"1bit", 1},
       {"43.5dB", 43.5},
       {"83.5", 83.5},
       {"62dB", 62},
       {"-62dB", -62},
       {"12.6mm", 12.6e-3},
       {"40.7mm", 40.7e-3}},
      {{"well_capacity",
        "Table 4.1 of the thesis gives 10 fF for this sensor; Table 5.1 says 40 fF; each table's "
        "numbers fit only its own value"},
       {"adc_tdc", "a 1-bit ADC cannot form the ratio of eq. 4.9; the converter is assumed 12-bit"},
       {"signal_light",
        "the range-noise bound (readout.max_range_noise_fraction: one range value's rms noise at most 5 % of c T0 / 2) "
        "lifts the lower edge to 0.051 nA; the SNR >= 3 rule alone gives 42.2 dB, and with neither it is 43.52 dB, "
        "the thesis's noise-free 0.01-1.5 nA"},
       {"background_light",
        "lower edge is the grid, upper edge is tap saturation at 10 fF; 83.5 dB = 20 log(15 nA / 1 pA) fits 40 fF "
        "(Table 5.1), not Table 4.1's 10 fF"},
       {"sbr_max", "eq. 4.11 (signal / background): the grid's top signal over its lowest background"},
       {"sbr_min", "eq. 4.11: weakest detectable signal under the strongest unsaturated background"},
       {"accuracy_max",
        "the thesis's 'max' (12.6 mm) is smaller than its 'min' (40.7 mm): the two are swapped. Our worst is at the "
        "range-noise bound (0.76 m, 5 % of c T0 / 2); 40.7 mm is pure shot noise at 0.135 V, a level the thesis does "
        "not name"},
       {"accuracy_min",
        "ours includes kTC and read noise and the ambient frame; 12.6 mm is pure signal shot noise at 1.4 V, 1 m, "
        "10 fF, which rangesim gives as 12.65 mm"}}};
  return column;
}

}  // namespace rangesim::golden
