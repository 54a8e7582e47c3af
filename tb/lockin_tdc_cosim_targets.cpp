// The issue-5b co-simulation targets (see tb/lockin_gate_generator_cosim.h).
#include "tb/lockin_tdc_cosim_targets.h"

#include "tb/lockin_gate_generator_cosim.h"
#include "tb/ls_demodulation_cosim.h"
#include "tb/tof_spad_cosim.h"

namespace rangesim::tb {
namespace {
CosimReport gate_generator(const CosimOptions& o) { return run_lockin_gate_generator_cosim(o); }
CosimReport column_adc(const CosimOptions& o) { return run_column_adc_cosim(o); }
CosimReport tof_spad(const CosimOptions& o) { return run_tof_spad_cosim(o, false); }
CosimReport tdc(const CosimOptions& o) { return run_tof_spad_cosim(o, true); }
}  // namespace

std::vector<CosimTarget> lockin_tdc_cosim_targets() {
  return {
      {"ls-demodulation",
       "ls-demodulation frame sequencer + address search vs the ticking sensor kernel: phases, "
       "address stream, row results, centres",
       {"dropped_row", "address_bit_flip"},
       &run_ls_demodulation_cosim},
      {"tof-lockin",
       "tof-lockin frame sequencer + gate generator + column ADCs vs the tick-mode sensor kernel; "
       "ranges (eq. 2.25) from RTL codes vs the kernel's",
       {"gate_shift", "adc_code_off_by_one"},
       &run_tof_lockin_cosim},
      {"tof-spad",
       "tof-spad row sequencer + TDC + histogram vs the SPAD/TDC kernels: codes, bins, peaks, "
       "centroid sums; golden estimator on the RTL histograms",
       {"tdc_code_off_by_one", "dropped_histogram_count"},
       &tof_spad},
      {"lockin_gate_generator",
       "PHASE1/2/3 (TX1/TX2/TXD) and light pulse vs LockinGateKernel, random T0/duty/N_acc",
       {"gate_shift", "period_change_while_busy"},
       &gate_generator},
      {"column_adc",
       "single-slope column ADC counter vs LockinColumnAdcKernel, random resolution/inputs",
       {"adc_code_off_by_one"},
       &column_adc},
      {"tdc",
       "shared TDC at high count rates: arbitration, dead time, overflow, lost hits vs "
       "TdcGroupKernel",
       {"tdc_code_off_by_one"},
       &tdc},
  };
}

}  // namespace rangesim::tb
