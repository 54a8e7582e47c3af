#pragma once
// Signal-to-background ratio SBR', under both of the thesis's definitions (eq. 3.11 and eq. 3.23 / 4.11).
//
//  - total (eq. 3.11 evaluated at an operating point): 20 log10((V_sig + V_bg) / V_bg). Eq. 3.11
//    writes V_sig_min / V_bg with V_sig_min = Delta V_ADC + V_bg, i.e. the swing the pixel reaches
//    over the background's; at 0.01 V / 0.001 V it gives the quoted 20.83 dB.
//  - ratio (eq. 3.23 / 4.11): 20 log10(V_sig / V_bg), signal over background alone.
namespace rangesim::golden {

double sbr_total_dB(double signal_V, double background_V);
double sbr_ratio_dB(double signal_V, double background_V);

}  // namespace rangesim::golden
