#pragma once
// The exact law of one tap's ADC code in an aggregated frame, as an alias table (alias_table.h):
// what evaluate --trials draws, from a point's kCodeTablesFromTrial-th trial on, instead of the
// count and the normal (config simulation.code_tables; docs/evaluate-montecarlo.md). Draw only
// what the answer needs: a trial's range needs the four codes, nothing else.
//
// Where the FD cannot reach V_sat (TapFrameLaw::may_saturate false, frame_draw.h) the kernel's
// code is clamp(floor(v / LSB), 0, 2^bits - 1) with
//   v = g (N - o) + A_sf V_offset + sigma Z,
// N the count (Poisson of mean M: frame and offset charge), o the offset charge's mean, g = A_sf q / C
// (volts at the ADC per electron), Z standard normal and sigma the joined kTC and read noise. So
//   P(v < b) = sum_N p(N) Phi((b - mu_N) / sigma),   mu_N = g (N - o) + A_sf V_offset,
// summed over the Poisson window (mass left out < 2^-65), Phi taken as 0 or 1 beyond 9 sigma
// (error < 1.2e-19 per code), in long double; P(code = c) = P(v < (c+1) LSB) - P(v < c LSB), the
// clipped codes 0 and 2^bits - 1 taking the tails. Exact in distribution to ~1e-19 per code
// (TapCodeLaw.* in tests/skipping/test_lockin_code_law.cpp).
#include "systemc/tof_lockin/alias_table.h"
#include "systemc/tof_lockin/column_adc_kernel.h"
#include "systemc/tof_lockin/frame_draw.h"
#include "systemc/tof_lockin/pixel_kernel.h"

namespace rangesim::systemc::lockin {

// The code law of tap `tap` under `law` (which must not saturate); first() .. last() are codes.
AliasTable tap_code_table(const TapFrameLaw& law, const LockinPixelKernel::Readout& r, const ColumnAdcKernel& adc,
                          int tap);

}  // namespace rangesim::systemc::lockin
