#pragma once
// TDC bins of one laser period: the actual bin edges (with INL and DNL) that sort photon times
// into codes, and the nominal bin centres the estimator assumes. The difference between the two
// is the TDC's contribution to the range nonlinearity (thesis 4.2.1: "nonlinearity errors may be
// improved with lower TDC nonlinearity").
#include <vector>

#include "core/tof_spad/config.h"

namespace rangesim::golden::spad {

struct TdcBins {
  double lsb_s = 0;             // nominal bin width
  double period_s = 0;          // laser period: the TDC restarts at every pulse
  int phase_bins = 0;           // Np: LSB steps covering one period (the last one may be partial)
  int codes = 0;                // Nc <= Np: codes that can hold an event (later hits overflow: no event)
  std::vector<double> edges_s;  // Np + 1 actual edges, edges_s[0] = 0 (START), edges_s[Np] = period

  // Time the estimator assigns to code i (it does not know the INL/DNL of its TDC).
  double centre_s(int i) const { return (i + 0.5) * lsb_s; }
  double width_s(int i) const { return edges_s[static_cast<size_t>(i) + 1] - edges_s[static_cast<size_t>(i)]; }
};

// Edges e_i = LSB (i + INL_i): INL is a smooth bow, one sine period over the used codes with rms
// inl_rms_lsb (zero at START and at the last code), plus independent per-edge offsets of rms
// dnl_rms_lsb / sqrt(2), so that the bin-width error DNL_i = INL_{i+1} - INL_i has rms dnl_rms_lsb.
// The offsets come from a counter-based generator keyed by (seed, edge): the same seed gives the
// same TDC on every platform.
TdcBins make_tdc_bins(const TdcConfig& tdc, double period_s);

// Standard normal number keyed by (seed, index), platform independent (splitmix64 + Box-Muller).
double keyed_normal(unsigned long long seed, unsigned long long index);

}  // namespace rangesim::golden::spad
