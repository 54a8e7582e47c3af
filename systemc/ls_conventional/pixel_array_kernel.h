#pragma once
// Cycle kernel of the ls-conventional pixel array with its 1-bit comparators (thesis [31]):
// plain C++, no SystemC. Photodiode integration with reset and saturation, the comparator
// decision at each sampling instant t_k = k T / N, latched (an activated pixel stays activated),
// and the activation bits of every row packed 64 per word (ActivationRow) for the row's
// address search.
//
// Noise (shot, kTC at reset, read, dark; docs/simulate.md), sampled here from counter-based streams keyed by (seed,
// frame, row, column) (systemc/common/random_stream.h):
//   - shot noise: the electrons integrated up to t_k are a Poisson process of mean
//     mu(t_k) = C v(t_k) / q (signal + background + dark current), drawn as increments per sampling;
//   - kTC reset noise sqrt(kT/C): drawn once at the pixel reset, frozen for the frame access;
//   - read noise (source follower / comparator, input-referred): once per frame access.
// Comparator input: A_sf (min(n q / C + v_kTC, V_sat) + v_read), activated when >= theta
// (golden/common/quantiser.h: tracking theta = A_sf (V_bg + V_dark) + Delta V_ADC, or fixed).
// Without noise the swing is the golden expression itself, so the activations equal
// golden::direct_estimate's bit for bit.
//
// Sparse (fidelity knob, on by default): a pixel whose mean swing at t_N gives it an activation
// probability below 1e-16 (noise; by a closed-form tail bound, see cut_swing_V) or that cannot
// reach theta (noise-free) is never simulated and never activated; the window of simulated pixels
// is computed per row from the spot profile. The skip is bounded: P(a skipped pixel would have
// activated) < 1e-16 per pixel and frame. Dense mode simulates
// every pixel; tests require identical outputs.
//
// Exact activation sampling (config simulation.exact_activation_sampling, on by default; with
// noise): within the window each pixel's first firing sampling is drawn at the reset from its exact
// distribution, or set without a draw where it is certain to 2^-56 (activation_sampler.h); the
// samplings then only latch the drawn bits. Off: the draws above at every sampling, unchanged.
#include <cstdint>
#include <memory>
#include <vector>

#include <pcg_random.hpp>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_conventional/frame_stimulus.h"
#include "systemc/common/poisson_sampler.h"
#include "systemc/ls_conventional/activation_sampler.h"

namespace rangesim::systemc {

// Noise sources of the pixel (each can be switched off; all off = the noise-free model).
struct PixelNoiseConfig {
  bool shot = true;       // Poisson photo/dark electrons
  bool reset_ktc = true;  // kTC at reset
  bool read = true;       // per-frame read noise (PixelConfig::read_noise_V)
  static PixelNoiseConfig none() { return {false, false, false}; }
  bool any() const { return shot || reset_ktc || read; }
};

struct PixelArrayOptions {
  PixelNoiseConfig noise;  // which noise sources are sampled
  std::uint64_t seed = 1;  // key of the random streams
  bool sparse = true;      // simulate only the pixels that can activate (bounded skip)
};

class PixelArrayKernel {
 public:
  // Throws std::invalid_argument for a configuration it cannot simulate (adc_bits != 1, sizes).
  PixelArrayKernel(const LsConventionalConfig& config, const PixelArrayOptions& options, StimulusSource source);

  // The block's control inputs as the readout sequencer drives them (combinational in the
  // sc_module: re-evaluated whenever they change). pix_reset with a new frame number resets the
  // pixels for that frame access (fetching its stimulus); a new sampling index k >= 1 latches the
  // comparators at t_k. Returns true if the activation rows changed.
  bool control(bool pix_reset, std::uint64_t frame, int sampling);

  // The two operations control() dispatches to; callable directly.
  void reset_frame(std::uint64_t frame);
  void sample(int k);

  const ActivationRow& row(int r) const { return act_[static_cast<std::size_t>(r)]; }
  int rows() const { return config_.pixel.rows; }
  int columns() const { return config_.pixel.columns; }
  std::uint64_t frame() const { return frame_; }
  int sampling() const { return sampling_; }
  const FrameStimulus& stimulus() const { return stimulus_; }
  // Pixels simulated one by one since construction (sparse windows), for the speed report.
  long long pixels_simulated() const { return pixels_simulated_; }
  // Of those, pixels whose noise was drawn: every one on the per-sampling path, only the ones with
  // an uncertain outcome on the exact path (the rest were certain to 2^-56).
  long long pixels_drawn() const { return pixels_drawn_; }
  bool exact_sampling() const { return exact_ != nullptr; }
  // Simulated window [first, last] of row r in the current frame access (last < first: none).
  int window_first(int r) const { return rows_[static_cast<std::size_t>(r)].first; }
  int window_last(int r) const { return rows_[static_cast<std::size_t>(r)].last; }
  double threshold_V(int r) const { return rows_[static_cast<std::size_t>(r)].threshold_V; }

 private:
  struct Pixel {
    pcg32 rng;               // this pixel's stream in this frame access
    double electrons = 0;    // integrated electrons up to the last sampling (shot noise on)
    double mean_step_e = 0;  // mean electrons per sampling interval, mu(T) / N
    PoissonSampler shot;     // Poisson sampler of that mean
    double offset_V = 0;     // kTC reset noise on the photodiode
    double read_V = 0;       // read noise at the comparator input (input-referred)
    double profile = 0;      // g(i - x0)
  };
  struct RowState {
    int first = 0, last = -1;   // simulated window [first, last]
    double threshold_V = 0;     // theta at the comparator input
    std::vector<Pixel> pixels;  // window pixels (index i - first), per-sampling path
    std::vector<std::uint8_t> fires_at;  // exact path: first firing sampling per window pixel, 0 never
  };

  double cut_swing_V(double threshold_V);  // smallest mean swing at t_N worth simulating (memoised)
  double compute_cut_swing_V(double threshold_V) const;
  void reset_row_exact(int r, const RowIllumination& in, RowState& row);  // the exact path's reset

  LsConventionalConfig config_;                    // sensor
  PixelArrayOptions options_;                      // noise, seed, sparse
  StimulusSource source_;                          // optics: stimulus per frame access
  FrameStimulus stimulus_;                         // the current frame access
  std::vector<RowState> rows_;                     // per row
  std::vector<ActivationRow> act_;                 // latched activations per row
  std::uint64_t frame_ = 0;                        // current frame access
  bool have_frame_ = false;                        // reset_frame ran at least once
  int sampling_ = 0;                               // last sampling latched (0 after reset)
  double dark_V_ = 0;                              // V_dark = I_dark T / C
  double electrons_per_V_ = 0;                     // C / q
  double ktc_V_ = 0, read_V_ = 0;                  // noise rms
  long long pixels_simulated_ = 0;                 // statistics
  long long pixels_drawn_ = 0;                     // statistics
  std::unique_ptr<ExactActivation> exact_;         // the exact path (null: per-sampling draws)
  double memo_threshold_V_ = -1, memo_cut_V_ = 0;  // last cut_swing_V
};

}  // namespace rangesim::systemc
