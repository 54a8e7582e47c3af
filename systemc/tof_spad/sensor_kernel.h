#pragma once
// Clock-level kernel of tof-spad (plain C++, no SystemC): column TDC groups with first-hit
// arbitration, coarse counter + interpolated fine code on the golden bin edges, busy time and
// overflow; per-pixel histogram memory; the row sequencer (integration, histogram readout) that
// counts the clock cycles of the schedule of golden::frame_timing_tof_spad; the estimator of the
// golden model applied to the measured histograms. docs/tof-spad-clock.md.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/tof_spad/config.h"
#include "golden/tof_spad/estimator.h"
#include "golden/tof_spad/tdc_bins.h"
#include "systemc/tof_spad/pixel_kernel.h"
#include "systemc/tof_spad/tdc_kernel.h"

namespace rangesim::systemc::spad {

struct TofSpadKernelOptions {
  std::uint64_t seed = 1;      // key of the noise streams
  SpadNoise noise;             // noise switches
  bool event_skipping = true;  // false: the TDC group is clocked every cycle (simulate_group_ticked)
  bool aggregate = false;      // true: groups whose laser cycles are independent drawn at once (spad_aggregation.h)
  bool sparse = false;         // true: background-only groups (no echo) as one class, in closed form where exact
};

// Histogram memory of one TDC group after one row integration.
struct GroupHistogram {
  std::vector<std::vector<long long>> events;  // [pixel in group][code]: recorded TDC events
  std::vector<long long> armed;                // [code]: laser cycles with the TDC armed at the code's start
  long long starts = 0;                        // START pulses (laser cycles) seen
  long long overflows = 0;                     // hits past the full range (no event)
  long long lost_busy = 0;                     // avalanches while the TDC was busy/stopped
  long long avalanches = 0;                    // all avalanches of the group
  long long photons = 0;                       // photon + dark arrivals of the group (incl. lost)
  bool aggregated = false;                     // drawn by aggregate_spad_group (else cycle by cycle)
  bool background_class = false;               // background-only group drawn by background_spad_group
};

// One pixel's result in a frame.
struct PixelResult {
  int row = 0, column = 0;
  std::vector<long long> events;  // its histogram
  std::vector<long long> armed;   // its TDC's armed cycles per code
  long long avalanches = 0;
  std::optional<double> time_s;  // estimator output (round trip)
  double range_m = 0;            // c t / 2 (NaN when nothing detected)
  double significance = 0;       // of the peak over the histogram's own background, sigma (golden/tof_spad/validity.h)
};

struct FrameResult {
  long long frame = 0;
  long long cycles = 0;                                   // measured clock cycles of the frame
  std::vector<long long> phase_cycles;                    // laser_cycles, histogram_readout
  std::vector<PixelResult> pixels;                        // simulated pixels, row-major
  long long avalanches = 0, photons = 0;                  // over the simulated pixels
  long long groups_aggregated = 0, groups_per_cycle = 0;  // which path ran, per simulated TDC group
  long long groups_background = 0;                        // background-only groups drawn as a class (sparse)
  long long groups_background_per_cycle = 0;              // background-only groups run per cycle (blocker)
};

// Pixel subset: rows and TDC groups (columns [g cpt, (g+1) cpt)) simulated; the other rows only
// cost their cycles.
struct PixelSelection {
  std::vector<int> rows;
  int first_group = 0, groups = 1;
};

using RateSource = std::function<PixelRates(int row, int column)>;

class TofSpadKernel {
 public:
  // Throws std::invalid_argument for an inconsistent configuration.
  TofSpadKernel(const TofSpadConfig& cfg, int rows, int columns, const TofSpadKernelOptions& opt);

  // One TDC group over one row integration: event driven (jumps from avalanche to avalanche), or
  // with event_skipping off simulate_group_ticked.
  // `observer` (may be null) sees every timed avalanche the TDC arbitrates, in time order, with
  // its column in the group; only the per-cycle path has them (the aggregated and sparse paths
  // draw the histogram at once: GroupHistogram::aggregated / background_class).
  using HitObserver = std::function<void(int who, const TdcHit& hit)>;
  GroupHistogram simulate_group(std::uint64_t frame, int row, int group, const RateSource& rates,
                                const HitObserver* observer = nullptr) const;
  // The same group clocked cycle by cycle (one TDC clock = one coarse phase bin): in every cycle
  // the TDC's arm state is sampled and counted into the armed histogram, and the avalanches whose
  // code falls in that cycle are arbitrated. Same streams, same draws: tests require a histogram
  // identical to the event-driven one.
  GroupHistogram simulate_group_ticked(std::uint64_t frame, int row, int group, const RateSource& rates) const;
  // The group's L laser cycles at once (spad_aggregation.h); simulate_group calls it when
  // options.aggregate is on, event skipping on, aggregation_blocker() empty and the group's pixels identical.
  GroupHistogram simulate_group_aggregated(std::uint64_t frame, int row, int group, const RateSource& rates) const;
  // Why this configuration needs the per-cycle path (empty: aggregation exact for identical pixels).
  const std::string& aggregation_blocker() const { return aggregation_blocker_; }
  // Why background-only groups need the per-cycle path (empty: the class's closed form is exact).
  const std::string& background_blocker() const { return background_blocker_; }
  // The sparse path of a background-only group: the class's closed form when exact (blocker empty
  // or no background at all), else nullopt (the caller runs the group per cycle).
  std::optional<GroupHistogram> simulate_group_background(std::uint64_t frame, int row, int group,
                                                          const RateSource& rates) const;
  // Estimator of the golden model on one pixel's histogram.
  std::optional<double> estimate(const std::vector<long long>& events, const std::vector<long long>& armed) const;
  // The histogram as the golden estimator and validity test read it.
  golden::spad::HistogramCounts counts(const std::vector<long long>& events, const std::vector<long long>& armed) const;
  PixelResult make_pixel(int row, int column, const GroupHistogram& g, int index) const;

  // Adds a simulated group to the frame's totals and path counters.
  void count_group(FrameResult& f, int row, int group, const GroupHistogram& g, const RateSource& rates) const;
  // Whole frame: every row in turn (integration then readout), cycles counted by the sequencer.
  FrameResult run_frame(std::uint64_t frame, const PixelSelection& sel, const RateSource& rates) const;

  // Schedule quantities (the sequencer's counters).
  long long laser_cycles() const { return laser_cycles_; }  // STARTs per row integration
  int phase_bins() const { return bins_.phase_bins; }       // clock cycles per laser period
  int codes() const { return bins_.codes; }
  // Dead time of the shared TDC after an event / an overflow, in phase bins (TdcGroupKernel's).
  int block_event_bins() const { return block_event_bins_; }
  int block_overflow_bins() const { return block_overflow_bins_; }
  long long readout_words_per_row() const { return static_cast<long long>(cfg_.tdc.columns_per_tdc) * bins_.codes; }
  long long cycles_per_word() const { return cycles_per_word_; }
  double clock_Hz() const { return tdc_clock_Hz(cfg_); }
  int rows() const { return rows_; }
  int columns() const { return columns_; }
  int groups() const { return columns_ / cfg_.tdc.columns_per_tdc; }
  const golden::spad::TdcBins& bins() const { return bins_; }
  const TofSpadConfig& config() const { return cfg_; }
  // TDC code of a phase in the laser period (coarse count + fine interpolation on the edges).
  int phase_bin(double phase_s) const;

 private:
  TofSpadConfig cfg_;
  int rows_, columns_;
  TofSpadKernelOptions opt_;
  golden::spad::TdcBins bins_;
  golden::spad::EstimatorConfig est_;
  double share_;
  long long laser_cycles_, cycles_per_word_;
  int block_event_bins_, block_overflow_bins_;
  std::string aggregation_blocker_, background_blocker_;
};

}  // namespace rangesim::systemc::spad
