#pragma once
// Aggregated laser cycles of one tof-spad TDC group (docs/tof-spad-clock.md
// "Aggregation"): the L laser cycles of a row integration drawn at once from the exact
// distribution of their sum, where successive cycles are independent and identically
// distributed (up to the first and last two cycles, drawn apart).
//
// Exact condition (spad_aggregation_exact): no afterpulses (switched off or probability 0), SPAD
// dead time 0, no timing jitter (switched off or sigma 0), the TDC re-armed by the next START
// whatever its hit (b + block(b) <= Np for every code b, block = busy/dead bins of an event or an
// overflow), and the group's pixels identical (same rates and round trip) or one pixel per TDC.
// Then every cycle starts from the same state (SPAD live, TDC armed), the avalanches of a pixel
// are its Poisson arrivals, and the TDC records the group's first avalanche of the cycle: per
// cycle the outcome is one of (pixel, code), (overflow) or "no detection" with the Coates
// probabilities p_i = exp(-sum_{j<i} Lambda_j) (1 - exp(-Lambda_i)) on the golden bin edges,
// shared equally among identical pixels; N cycles are multinomial over those cells, sampled
// exactly by sequential binomials. Otherwise the caller runs the per-cycle path.
#include <cstdint>
#include <string>
#include <vector>

#include "core/tof_spad/config.h"
#include "golden/tof_spad/tdc_bins.h"
#include "systemc/tof_spad/pixel_kernel.h"

namespace rangesim::systemc::spad {

struct GroupHistogram;

// Why the per-cycle path must run for this configuration (empty: aggregation is exact as far as
// the configuration goes; the pixel rates are checked by spad_group_aggregatable).
std::string spad_aggregation_blocker(const TofSpadConfig& cfg, const SpadNoise& noise, int phase_bins, int codes,
                                     int block_event_bins, int block_overflow_bins);
// The group's pixels allow the equal share of a bin among them (identical rates, or one pixel;
// one echo each: further returns run per cycle).
bool spad_group_aggregatable(const std::vector<PixelRates>& pixels);

// The aggregated histogram of one group (same GroupHistogram fields as the per-cycle path;
// avalanches / photons / lost_busy drawn from their exact distribution given the histogram).
// Random stream keyed by (seed ^ salt, frame, row, first column of the group).
GroupHistogram aggregate_spad_group(const TofSpadConfig& cfg, const SpadNoise& noise, const golden::spad::TdcBins& bins,
                                    const std::vector<PixelRates>& pixels, long long laser_cycles, std::uint64_t seed,
                                    std::uint64_t frame, int row, int first_column);

// Background-only groups ("sparse pixels"; docs/tof-spad-clock.md "Background-only
// pixels"): no pixel of the group receives an echo (signal 0) and all have the same background,
// so every laser cycle of every such group has the same arrival rate and these groups form one
// class. Where pure-background cycles are independent (empty blocker: no afterpulse, dead time 0,
// no jitter, TDC re-armed by the next START) the L cycles are one multinomial over (column, code)
// + overflow + none with the Coates probabilities of the uniform rate (closed form, exact, O(Np)
// per group); with a uniform rate of 0 the histogram is empty whatever the configuration.
std::string spad_background_blocker(const TofSpadConfig& cfg, const SpadNoise& noise, int phase_bins, int codes,
                                    int block_event_bins, int block_overflow_bins);
bool spad_group_background_only(const std::vector<PixelRates>& pixels);
// The histogram of one background-only group (same fields as the per-cycle path; background_class
// set). Random stream keyed by (seed ^ salt, frame, row, first column of the group).
GroupHistogram background_spad_group(const TofSpadConfig& cfg, const SpadNoise& noise,
                                     const golden::spad::TdcBins& bins, const std::vector<PixelRates>& pixels,
                                     long long laser_cycles, std::uint64_t seed, std::uint64_t frame, int row,
                                     int first_column);

}  // namespace rangesim::systemc::spad
