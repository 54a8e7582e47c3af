#pragma once
// Shared setup of the ls-demodulation clock-level tests.
#include <cmath>

#include "core/ls_demodulation/config.h"
#include "core/preset.h"
#include "systemc/ls_demodulation/sensor_kernel.h"

namespace rangesim::systemc::test {

// The preset itself (presets/ls-demodulation.toml).
inline LsDemodulationConfig preset_config() {
  return ls_demodulation_from_params(load_preset_file(std::string(RANGESIM_PRESET_DIR) + "/ls-demodulation.toml"));
}

// A small array with the preset's physics (fast enough to tick).
inline LsDemodulationConfig small_config(int rows = 3, int columns = 16) {
  LsDemodulationConfig c = preset_config();
  c.pixel.rows = rows;
  c.pixel.columns = columns;
  return c;
}

// Gaussian spot of peak `signal_A` at column x0 on every row (shifted by `shift_px` per row) over
// a uniform background.
inline DemodStimulusSource spot_source(const LsDemodulationConfig& c, double signal_A, double background_A, double x0,
                                       double shift_px = 0.37, double per_frame_px = 0.0) {
  return [=](std::uint64_t f, DemodStimulus& s) {
    const double sigma = c.spot.fwhm_px * c.spot.sigma_per_fwhm;
    s.beam_A.assign(static_cast<std::size_t>(c.pixel.rows) * c.pixel.columns, 0.0);
    s.background_A.assign(s.beam_A.size(), background_A);
    for (int r = 0; r < c.pixel.rows; ++r)
      for (int col = 0; col < c.pixel.columns; ++col) {
        const double x = col - (x0 + r * shift_px + per_frame_px * static_cast<double>(f));
        s.beam_A[static_cast<std::size_t>(r) * c.pixel.columns + col] =
            signal_A * std::exp(-x * x / (2 * sigma * sigma));
      }
  };
}

}  // namespace rangesim::systemc::test
