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
// distribution, or set without a draw where it is certain to 2^-56 (activation_sampler.h). The
// reset also works out each row's extent (lowest and highest activated column) at every sampling,
// all the event-skipping readout reads; a row's bits are made only when row() asks for them (the
// ticked readout, the sc_module), from the same draws. Off: the draws above at every sampling.
// Two further switches of that path: simulation.certain_intervals (sparse only; --dense looks at
// every pixel) finds a row's certain pixels as intervals around the spot centre and looks only at
// the band between them one by one (certain_intervals.h; bit-identical to looking at every window
// pixel), and simulation.inversion_draw draws an uncertain pixel's first firing sampling with one
// keyed uniform by inversion of its exact distribution function (activation_sampler.h; else the
// Gamma draw).
//
// Per-pixel path (pixel_array_pixelwise.cpp): when a frame's stimulus carries per-pixel inputs
// (FrameStimulus::per_pixel(): the chip's fixed pattern or a spread spot, core/nonideal.h), every
// row's pixels get their own drive, dark swing and comparator offset; the window and certain
// intervals, which assume one drive and threshold per row, give way to a per-pixel test: a pixel
// is simulated when its mean swing at t_N reaches the cut of the band's most favourable comparator
// (threshold less the band's largest offset), the same bounded skip as above, and its noise is
// drawn at every sampling (the per-sampling draws, exact in distribution). Without per-pixel
// inputs nothing of it runs, so every other path keeps its bits.
//
// Rows: a kernel may simulate a band of the array's rows (PixelArrayOptions::first_row,
// row_count) so that bands run on several cores; the keyed streams make each row's bits
// independent of the band it runs in.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <pcg_random.hpp>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_conventional/frame_stimulus.h"
#include "systemc/common/poisson_sampler.h"
#include "systemc/ls_conventional/activation_sampler.h"
#include "systemc/ls_conventional/certain_intervals.h"

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
  int first_row = 0;       // the band of rows simulated: first_row ..
  int row_count = -1;      // .. first_row + row_count - 1 (-1: to the last row)
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

  // Rows are counted within the band: row(r) is the array's row first_row() + r. On the exact path
  // a row's bits are made when asked for (the event-skipping readout reads extent() instead).
  const ActivationRow& row(int r) const {
    const std::size_t i = static_cast<std::size_t>(r);
    if (lazy_bits_ && act_at_[i] != generation_) build_row(r);
    return act_[i];
  }
  // Lowest and highest activated column of row r, all the address search reads of it: on the exact
  // path from the first firings drawn at the reset, without the bits; equal to row(r)'s first() and
  // last() on every path (tests/skipping).
  ActivationExtent extent(int r) const {
    if (sampling_ == 0) return {};
    if (!lazy_bits_) return {row(r).first(), row(r).last()};
    const std::size_t N = static_cast<std::size_t>(config_.multisampling.samplings);
    const std::size_t i = row_pattern_[static_cast<std::size_t>(r)] * N + static_cast<std::size_t>(sampling_ - 1);
    return {pattern_first_[i], pattern_last_[i]};
  }
  // The exact path's extents of every sampling of the frame access by pattern (made at the reset):
  // row r's at sampling k (1-based) are those of pattern p = row_pattern[r], first[p * samplings +
  // k - 1] and last[...]; rows whose band pixels fired alike share one (on the plane map a frame
  // access's 365 rows have about 4). False where there are none (ask extent(r)).
  bool extent_patterns(const std::uint32_t*& row_pattern, const int*& first, const int*& last,
                       std::size_t& patterns) const {
    if (!has_extent_patterns()) return false;
    row_pattern = row_pattern_.data();
    first = pattern_first_.data();
    last = pattern_last_.data();
    patterns = patterns_;
    return true;
  }
  bool has_extent_patterns() const { return lazy_bits_ && sampling_ != 0; }  // extent_patterns would give them
  int rows() const { return static_cast<int>(rows_.size()); }
  int first_row() const { return first_row_; }
  int columns() const { return config_.pixel.columns; }
  std::uint64_t frame() const { return frame_; }
  int sampling() const { return sampling_; }
  const FrameStimulus& stimulus() const { return stimulus_; }
  // Pixels simulated one by one since construction (sparse windows), for the speed report.
  long long pixels_simulated() const { return pixels_simulated_; }
  // Of those, pixels whose noise was drawn: every one on the per-sampling path, only the ones with
  // an uncertain outcome on the exact path (the rest were certain to 2^-56).
  long long pixels_drawn() const { return pixels_drawn_; }
  // Exact path: pixels looked at one by one (every window pixel, or with certain intervals the band).
  long long pixels_examined() const { return pixels_examined_; }
  bool exact_sampling() const { return exact_ != nullptr; }
  bool certain_intervals() const { return intervals_ != nullptr; }
  bool inversion_draw() const { return inversion_; }
  const ExactActivation* exact() const { return exact_.get(); }
  bool per_pixel() const { return per_pixel_; }  // the current frame access took the per-pixel path
  // Simulated window [first, last] of row r in the current frame access (last < first: none).
  int window_first(int r) const { return lazy_bits_ ? shape_of(r).first : rows_[static_cast<std::size_t>(r)].first; }
  int window_last(int r) const { return lazy_bits_ ? shape_of(r).last : rows_[static_cast<std::size_t>(r)].last; }
  double threshold_V(int r) const {
    return lazy_bits_ ? shape_of(r).threshold_V : rows_[static_cast<std::size_t>(r)].threshold_V;
  }

 private:
  struct Pixel {
    int column = 0;           // per-pixel path: the pixel's column (the window is not contiguous)
    double swing_T_V = 0;     // per-pixel path: noise-free mean swing at t_N
    double comparator_V = 0;  // per-pixel path: comparator offset at its input
    pcg32 rng;                // this pixel's stream in this frame access
    double electrons = 0;     // integrated electrons up to the last sampling (shot noise on)
    double mean_step_e = 0;   // mean electrons per sampling interval, mu(T) / N
    PoissonSampler shot;      // Poisson sampler of that mean
    double offset_V = 0;      // kTC reset noise on the photodiode
    double read_V = 0;        // read noise at the comparator input (input-referred)
    double profile = 0;       // g(i - x0)
  };
  // Per row, the per-sampling paths' (the exact path keeps its rows by run: ExactRun).
  struct RowState {
    int first = 0, last = -1;   // simulated window [first, last]
    double threshold_V = 0;     // theta at the comparator input
    std::vector<Pixel> pixels;  // window pixels (index i - first), per-sampling path
  };
  // Exact path: a run of rows r0..r1 - 1 (within the band) with one drive, so one RowShape.
  struct ExactRun {
    int r0 = 0, r1 = 0;
    int shape = -1;           // its RowShape in shapes_
    int uniforms = 0;         // a row's band pixels drawn by inversion of the frame's keyed uniforms
    std::size_t band_at = 0;  // row r0 + i's band pixels' first firings from band_k_[band_at + i n]
    std::size_t u_at = 0;     // its uniforms from uniforms_[u_at], drawn pixel by drawn pixel, row by row within ..
    bool grid = false;        // .. unless made as a grid (at least kGridRows rows) in draw_run, without keys
  };
  static constexpr std::size_t kGridRows = 8;
  // Exact path: a pixel looked at one by one, with its certain first firing or its drive for a draw.
  struct BandPixel {
    int column = 0;
    int certain = -1;  // first firing sampling if certain (0: never), -1: drawn
    PixelDrive drive;
    std::size_t cut_at = 0;  // its prepared inversion in RowShape::cut (when one was prepared)
    bool prepared = false;
  };
  // Exact path: what a row's drive (signal, background, centre) decides: its threshold and window,
  // the columns certain to have fired by each sampling (core ranges) and the band pixels. With
  // certain intervals, consecutive rows of a frame access with the same drive share one (a plane
  // puts the same drive on every row); without, every row makes its own from every window pixel.
  // At sampling k a row holds its shape's columns core_first[k-1]..core_last[k-1] and the band
  // pixels whose first firing is 1..k (a band pixel's own sampling decides, even inside a core range).
  struct RowShape {
    double signal_V = 0, background_V = 0, centre_px = 0;
    int first = 0, last = -1;
    double threshold_V = 0;
    std::vector<int> core_first, core_last;
    // Union of the core ranges of samplings 1..k at k - 1 (they are nested: all centred on the spot),
    // which is what the latch holds of them by sampling k; none: first = INT_MAX, last = -1.
    std::vector<int> held_first, held_last;
    std::vector<BandPixel> band;  // ascending columns
    // Per band pixel: its column and the first sampling whose held range covers it (N + 1: none).
    std::vector<int> band_column_from;
    std::vector<double> cut;  // the band pixels' prepared inversions (ExactActivation::prepare_inversion)
    bool by_uniform = false;  // its random band pixels are drawn by inversion of a keyed uniform
    // What every row of the shape repeats (plan_draws): the band's first firings with 0 at the pixels
    // drawn by a keyed uniform, their band positions and columns (ascending; their cuts follow one
    // another in `cut`), and base_k as a memo key (kNoPattern: a band of 8 or more pixels). A shape
    // with random band pixels and no inversion draws them one by one (one_by_one).
    std::vector<std::uint8_t> base_k;  // (8 bytes to spare at the end)
    std::vector<int> drawn_at;
    std::vector<std::uint32_t> drawn_column;
    // Per drawn pixel, when one sampling k alone is random (the usual case: the samplings before
    // fire with f = 0, those after with f = 1): its cuts (fires below lo, not at or above hi) and its
    // first firing either way (k, and k + 1 or never); drawn_single[t] = 0: several are random.
    std::vector<double> drawn_lo, drawn_hi;
    std::vector<std::uint8_t> drawn_single, drawn_fire, drawn_else;
    std::uint64_t base_key = 0;
    bool one_by_one = false;
    // fill_extents' memo: kMemo slots of the frame's extent patterns by the band's packed first firings.
    static constexpr std::size_t kMemo = 16;
    static constexpr std::uint64_t kNoPattern = ~std::uint64_t{0};  // an empty slot (no key has 0xff on top)
    std::array<std::uint64_t, kMemo> memo_key{};
    std::array<std::uint32_t, kMemo> memo_pattern{};
    static std::size_t memo_slot(std::uint64_t key) {
      return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ULL) >> 60) % kMemo;
    }
  };

  double cut_swing_V(double threshold_V);  // smallest mean swing at t_N worth simulating (memoised)
  double compute_cut_swing_V(double threshold_V) const;
  void set_window(const RowIllumination& in, RowState& row);  // threshold and simulated window
  // The exact path (pixel_array_exact.cpp): the frame access's reset in passes over the runs of rows
  // of one shape, around the frame's batch of uniforms; and the latch of sampling k.
  void reset_exact();
  void start_run(const ExactRun& run, std::uint64_t* rc);  // rc: the run's first uniform key
  // N samplings (0: any count)
  template <int N>
  void finish_run(const ExactRun& run);
  const ExactRun& run_of(int r) const;  // the run that holds row r
  // The rows of shape s have memo keys that hold their first firings (fewer than 8 band pixels, all
  // certain or drawn by inversion): finish_run writes them from the keys.
  static bool keyed_rows(const RowShape& s) { return s.base_key != RowShape::kNoPattern && !s.one_by_one; }
  const RowShape& shape_of(int r) const { return shapes_[static_cast<std::size_t>(run_of(r).shape)]; }
  template <int N, bool Keyed>  // Keyed: into the rows' memo keys (keyed_rows)
  void draw_run(const ExactRun& run, const RowShape& s, std::size_t R, std::uint64_t* out);
  template <int N, bool Keyed>  // drawn pixels t0 .. t1 - 1 of the shape
  void invert_run(const RowShape& s, std::size_t R, const double* u, std::uint64_t* out, std::size_t t0,
                  std::size_t t1);
  int make_shape(int r, const RowIllumination& in, RowState& row);
  void plan_draws(RowShape& s) const;
  void core_ranges(const RowCertainty& c, double x0, RowShape& shape) const;
  BandPixel look_at(int i, const RowIllumination& in, ThresholdEntry& e) const;
  int draw(int r, const RowShape& s, const BandPixel& p, ThresholdEntry& e);
  void sample_exact(int k);
  // What the exact path's latch holds (pixel_array_extents.cpp): a row's extents at every sampling
  // from the first firings drawn at the reset, and its bits at the current sampling (row()).
  void hold_ranges(RowShape& shape) const;  // held_first / held_last and band_column_from
  void fill_extents(int r, RowShape& s, const std::uint8_t* fk, std::uint64_t key);  // key: the memo's
  void extents_from_bits(int* first, int* last, const RowShape& s, const std::uint8_t* fk);  // a row with a hole
  void build_row(int r) const;
  void set_row_bits(ActivationRow& act, const RowShape& s, const std::uint8_t* fk, int k) const;
  // A noisy pixel's comparator input at a sampling, the per-sampling path's expression (both
  // per-sampling paths share it): the swing from its electrons so far, one more Poisson step drawn
  // (shot noise on), or else `swing_V()`, the noise-free swing; then the frozen kTC offset,
  // saturation and read noise.
  template <class Swing>
  double noisy_input_V(Pixel& p, Swing swing_V) {
    double v;
    if (options_.noise.shot) {
      p.electrons += p.mean_step_e > 0 ? static_cast<double>(p.shot(p.rng)) : 0.0;
      v = p.electrons / electrons_per_V_;
    } else {
      v = swing_V();
    }
    return config_.pixel.source_follower_gain *
           (std::min(v + p.offset_V, config_.pixel.saturation_voltage_V) + p.read_V);
  }
  // The per-pixel path (pixel_array_pixelwise.cpp).
  void reset_row_pixels(int r, const RowIllumination& in, RowState& row);
  void sample_pixels(int k);

  LsConventionalConfig config_;                    // sensor
  PixelArrayOptions options_;                      // noise, seed, sparse
  StimulusSource source_;                          // optics: stimulus per frame access
  FrameStimulus stimulus_;                         // the current frame access
  std::vector<RowState> rows_;                     // per row
  mutable std::vector<ActivationRow> act_;         // latched per row (sized at a reset; exact path: by row())
  mutable std::vector<std::uint64_t> act_at_;      // exact path: the generation_ each row's bits were made at
  std::uint64_t generation_ = 1;                   // exact path: counts resets and samplings
  bool lazy_bits_ = false;                         // this frame access takes the exact path
  std::vector<std::uint32_t> row_pattern_;         // exact path: row r's extents are this pattern's ..
  std::vector<int> pattern_first_, pattern_last_;  // .. at sampling k at p N + k - 1 (extent_patterns)
  std::size_t patterns_ = 0;                       // .. of the frame access's first patterns_ ..
  std::vector<std::uint64_t> pattern_key_;         // .. and the memo key each was made from (keyed rows)
  std::uint64_t frame_ = 0;                        // current frame access
  bool have_frame_ = false;                        // reset_frame ran at least once
  bool per_pixel_ = false;                         // this frame access takes the per-pixel path
  double band_max_offset_V_ = 0;                   // per-pixel path: the band's largest comparator offset
  int sampling_ = 0;                               // last sampling latched (0 after reset)
  double dark_V_ = 0;                              // V_dark = I_dark T / C
  double electrons_per_V_ = 0;                     // C / q
  double ktc_V_ = 0, read_V_ = 0;                  // noise rms
  long long pixels_simulated_ = 0;                 // statistics
  long long pixels_drawn_ = 0;                     // statistics
  long long pixels_examined_ = 0;                  // statistics
  int first_row_ = 0;                              // the band's first row in the array
  std::uint64_t frame_key_ = 0;                    // frame_stream_key(seed, frame)
  std::unique_ptr<ExactActivation> exact_;         // the exact path (null: per-sampling draws)
  std::unique_ptr<CertainIntervals> intervals_;    // certain pixels by intervals (null: every window pixel)
  bool inversion_ = false;                         // uncertain pixels drawn by inversion where it applies
  std::vector<ExactRun> runs_;                     // exact path: the frame access's runs of rows, in order
  std::vector<RowShape> shapes_;                   // exact path: this frame access's row shapes ..
  int shapes_used_ = 0;                            // .. the first shapes_used_ of them (kept for reuse)
  std::vector<std::uint8_t> band_k_;               // exact path: first firing of every row's band pixels
  std::vector<std::uint64_t> draw_rc_;             // exact path: row and column of each short run's uniform
  std::vector<double> uniforms_;                   // .. and the uniforms (keyed_uniforms)
  ThresholdEntry* finish_entry_ = nullptr;         // finish_run: the run's threshold entry ..
  std::vector<std::uint64_t> k_scratch_;           // .. and its rows' first firings (invert_run, not keyed) ..
  std::vector<std::uint64_t> keys_;                // .. and memo keys (keyed_rows)
  std::vector<double> column_u_;                   // draw_run: a long run's uniforms, one drawn pixel's
  double memo_threshold_V_ = -1, memo_cut_V_ = 0;  // last cut_swing_V
};

}  // namespace rangesim::systemc
