// Frame timing of tof-spad from its clock schedule (docs/tof-spad-clock.md).
//
// The clock is the TDC clock, one cycle per nominal LSB: clock_Hz = 1 / tdc.lsb_s. A laser period
// spans Np = ceil(period / LSB) cycles (the coarse counter restarts at every START, so a partial
// last step still costs a whole cycle). One row is connected to the column TDCs at a time
// (array.rows), so a frame is, for each of the `rows` rows in turn:
//   1. "laser_cycles": L = round(histogram.integration_time_s x laser.repetition_rate_Hz) laser
//      periods of Np cycles each, the row's pixels integrating their histograms;
//   2. "histogram_readout": the row's histograms (codes words per pixel) read out, one output
//      lane per TDC (columns / columns_per_tdc lanes in parallel), so a lane reads
//      columns_per_tdc x codes words at histogram.readout_word_rate_Hz, W = ceil(clock_Hz / word rate)
//      clock cycles per word.
//   frame_cycles = rows x (L x Np + columns_per_tdc x codes x W)
// Phases are listed in schedule order, each summed over the rows.
// A range map is evaluation.frames_averaged frames (the golden model's accumulated histograms).
#include <cmath>

#include "core/tof_spad/config.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/tof_spad/tdc_bins.h"
#include "golden/tof_spad/model.h"

namespace rangesim::golden {

FrameTiming frame_timing_tof_spad(const ParamSet& params) {
  const TofSpadConfig cfg = tof_spad_from_params(params);
  const double period_s = 1.0 / cfg.laser.repetition_rate_Hz;
  const spad::TdcBins bins = spad::make_tdc_bins(cfg.tdc, period_s);
  const double clock_Hz = tdc_clock_Hz(cfg);
  const long long laser_cycles = laser_cycles_per_row(cfg);
  const long long rows = params.integer("array.rows");
  const long long cycles_per_word = cycles_per_histogram_word(cfg);
  const long long words_per_lane = static_cast<long long>(cfg.tdc.columns_per_tdc) * bins.codes;

  FrameTiming t;
  t.clock_Hz = clock_Hz;
  t.samplings = 1;
  const long long integ = rows * laser_cycles * bins.phase_bins, readout = rows * words_per_lane * cycles_per_word;
  t.phases.push_back({"laser_cycles", integ, integ / clock_Hz});
  t.phases.push_back({"histogram_readout", readout, readout / clock_Hz});
  t.frame_cycles = integ + readout;
  t.frame_time_s = t.frame_cycles / clock_Hz;
  t.frame_access_rate_Hz = 1.0 / t.frame_time_s;
  t.frames_per_range_map = cfg.evaluation.frames_averaged;
  t.range_map_time_s = t.frame_time_s * static_cast<double>(t.frames_per_range_map);
  t.range_maps_per_s = 1.0 / t.range_map_time_s;
  return t;
}

}  // namespace rangesim::golden
