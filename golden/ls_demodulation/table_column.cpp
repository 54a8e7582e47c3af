// Column [27] of thesis Table 5.1: the ls-demodulation chip as the thesis lists it, and why rangesim's
// value differs where it does (`rangesim table`).
#include "golden/ls_demodulation/model.h"

namespace rangesim::golden {

const ThesisColumn& ls_demodulation_table_column() {
  static const ThesisColumn column{
      "ls-demodulation",
      "[27]",
      false,
      {{"LS", kNaN},
       {"50 us", 50e-6},
       {"37fF", 37e-15},
       {"1-bit", 1},
       {"43.5dB", 43.5},
       {"103.5", 103.5},
       {"83dB", 83},
       {"-62dB", -62},
       {"1.5mm", 1.5e-3},
       {"0.6mm", 0.6e-3}},
      {{"background_light",
        "above ~0.28 nA the background's shot noise through the correlator makes background-only pixels cross "
        "V_cmp (row false activation > 1%); the thesis's evaluation has no noise, so it has no such limit"},
       {"sbr_max",
        "eq. 3.23: the grid's top signal over its lowest background (0.001 V equivalent); 83 dB implies a 20 dB "
        "lower background floor, and the thesis's spans (43.5 + 103.5 dB) do not add up to its SBR' span (83 + 62 dB)"},
       {"sbr_min",
        "eq. 3.23: weakest detectable signal under the strongest background where it is detectable, "
        "limited by the background's shot noise rather than by saturation"},
       {"accuracy_max",
        "rms error over the detectable area at 1 m; at the nominal point the maximum error (|bias| + 3 std) is 2.57 mm "
        "against the chip's 1.5 mm: the 1-bit edge readout spreads its error wider"},
       {"accuracy_min",
        "the chip's 0.6 mm std in the effective area is reproduced at the nominal point (baseline calibrated to it); "
        "over the grid the best is at the strongest signal"}}};
  return column;
}

}  // namespace rangesim::golden
