#include "systemc/ls_conventional/pixel_array_kernel.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>

#include "golden/common/pixel.h"
#include "golden/common/quantiser.h"
#include "golden/common/spot.h"
#include "systemc/common/keyed_uniforms.h"
#include "systemc/common/random_stream.h"

namespace rangesim::systemc {

PixelArrayKernel::PixelArrayKernel(const LsConventionalConfig& config, const PixelArrayOptions& options,
                                   StimulusSource source)
    : config_(config), options_(options), source_(std::move(source)) {
  if (config.comparator.adc_bits != 1)
    throw std::invalid_argument(
        "PixelArrayKernel: comparator.adc_bits must be 1 (the in-pixel comparator of "
        "ls-conventional), got " +
        std::to_string(config.comparator.adc_bits));
  if (config.pixel.rows < 1 || config.pixel.columns < 1)
    throw std::invalid_argument("PixelArrayKernel: rows and columns must be >= 1");
  if (config.multisampling.samplings < 1) throw std::invalid_argument("PixelArrayKernel: samplings must be >= 1");
  if (!source_) throw std::invalid_argument("PixelArrayKernel: no stimulus source");
  first_row_ = options.first_row;
  const int band = options.row_count < 0 ? config.pixel.rows - first_row_ : options.row_count;
  if (first_row_ < 0 || band < 1 || first_row_ + band > config.pixel.rows)
    throw std::invalid_argument("PixelArrayKernel: rows " + std::to_string(first_row_) + " + " + std::to_string(band) +
                                " outside the array's " + std::to_string(config.pixel.rows));
  rows_.resize(static_cast<std::size_t>(band));
  act_.resize(static_cast<std::size_t>(band));  // given their width at a frame's reset (exact path: by row())
  act_at_.assign(static_cast<std::size_t>(band), 0);
  dark_V_ = golden::dark_voltage_V(config.pixel);
  electrons_per_V_ = golden::electrons_per_volt(config.pixel);
  ktc_V_ = golden::ktc_noise_V(config.pixel);
  read_V_ = config.pixel.read_noise_V;
  if (config.simulation.exact_activation_sampling && options_.noise.any()) {
    ActivationModel m;
    m.shot = options_.noise.shot;
    m.ktc_V = options_.noise.reset_ktc ? ktc_V_ : 0.0;
    m.read_V = options_.noise.read ? read_V_ : 0.0;
    m.electrons_per_V = electrons_per_V_;
    m.gain = config.pixel.source_follower_gain;
    m.saturation_V = config.pixel.saturation_voltage_V;
    m.samplings = config.multisampling.samplings;
    exact_ = std::make_unique<ExactActivation>(m);
    inversion_ = config.simulation.inversion_draw;
    if (config.simulation.certain_intervals && options_.sparse)
      intervals_ = std::make_unique<CertainIntervals>(config.spot, dark_V_, electrons_per_V_, m.samplings);
  }
}

bool PixelArrayKernel::control(bool pix_reset, std::uint64_t frame, int sampling) {
  if (pix_reset) {
    if (have_frame_ && frame == frame_) return false;
    reset_frame(frame);
    return true;
  }
  if (sampling >= 1 && sampling != sampling_ && have_frame_) {
    sample(sampling);
    return true;
  }
  return false;
}

double PixelArrayKernel::cut_swing_V(double threshold_V) {
  // Rows usually share their threshold (same background): one-entry memo.
  if (threshold_V == memo_threshold_V_) return memo_cut_V_;
  memo_threshold_V_ = threshold_V;
  memo_cut_V_ = compute_cut_swing_V(threshold_V);
  return memo_cut_V_;
}

double PixelArrayKernel::compute_cut_swing_V(double threshold_V) const {
  // Smallest mean swing at t_N for which a pixel is simulated. Below it, P(activated) < 1e-16 by
  // a closed-form bound (cheap, so it can be evaluated per row and frame):
  //   P(n + R >= theta) <= P(n >= mu + a) + P(R >= theta - mu - a)
  // with Bernstein's bound P(n >= mu + a) <= exp(-a^2 / (2 (mu + a / 3))) = 5e-17 at
  // a = (25 + sqrt(625 + 300 mu)) / 2, and P(R >= 8.3 sigma) = Phi(-8.3) < 5e-17 for the Gaussian
  // static noise R (kTC + read). So mu is skipped when mu + a(mu) + 8.3 sigma < theta, in electrons.
  const double A = config_.pixel.source_follower_gain;
  const double thr_V = threshold_V / A;  // swing the pixel must reach (noise-free)
  if (!options_.noise.any()) return thr_V * (1 - 1e-9);
  const double sigma_V = std::hypot(options_.noise.reset_ktc ? ktc_V_ : 0.0, options_.noise.read ? read_V_ : 0.0);
  if (!options_.noise.shot) return std::max(0.0, thr_V - 9.5 * sigma_V);  // Phi(-9.5) = 1e-21
  const double room_e = (thr_V - 8.3 * sigma_V) * electrons_per_V_;       // mu + a(mu) must stay below
  auto reach = [](double mu) { return mu + 0.5 * (25 + std::sqrt(625 + 300 * mu)); };
  if (!(reach(0) < room_e)) return 0;
  double lo = 0, hi = room_e;  // reach(lo) < room_e <= reach(hi)
  for (int i = 0; i < 64; ++i) {
    const double mid = 0.5 * (lo + hi);
    (reach(mid) < room_e ? lo : hi) = mid;
  }
  return lo / electrons_per_V_;
}

void PixelArrayKernel::set_window(const RowIllumination& in, RowState& row) {
  // The pixels that can activate: all, or with the sparse window those within the spot's reach.
  const int C = config_.pixel.columns;
  row.threshold_V = golden::comparator_threshold_V(config_, in.background_V);
  row.first = 0;
  row.last = C - 1;
  if (!options_.sparse) return;
  const double rest = cut_swing_V(row.threshold_V) - in.background_V - dark_V_;
  if (!(rest > 0)) return;
  const double h = in.signal_V > 0 ? golden::spot_half_width_px(config_.spot, rest / in.signal_V) : -1;
  if (h < 0) {
    row.last = -1;  // nothing on this row can activate
  } else {
    row.first = static_cast<int>(std::max<double>(0, std::ceil(in.centre_px - h) - 1));
    row.last = static_cast<int>(std::min<double>(C - 1, std::floor(in.centre_px + h) + 1));
  }
}

void PixelArrayKernel::reset_frame(std::uint64_t frame) {
  stimulus_.rows.resize(static_cast<std::size_t>(config_.pixel.rows));
  stimulus_.first_row = first_row_;
  stimulus_.row_count = rows();
  source_(frame, stimulus_);
  if (static_cast<int>(stimulus_.rows.size()) != config_.pixel.rows)
    throw std::invalid_argument("PixelArrayKernel: stimulus has " + std::to_string(stimulus_.rows.size()) +
                                " rows, expected " + std::to_string(config_.pixel.rows));
  frame_ = frame;
  frame_key_ = frame_stream_key(options_.seed, frame);
  have_frame_ = true;
  sampling_ = 0;
  const int N = config_.multisampling.samplings;
  per_pixel_ = stimulus_.per_pixel();
  lazy_bits_ = exact_ && !per_pixel_;
  ++generation_;
  if (per_pixel_) {
    const std::size_t want = static_cast<std::size_t>(config_.pixel.rows) * static_cast<std::size_t>(columns());
    if (!stimulus_.signal_px_V.empty() && stimulus_.signal_px_V.size() != want)
      throw std::invalid_argument("PixelArrayKernel: per-pixel spot swings of the wrong size");
    // The band's largest comparator offset bounds every pixel's: one cut per threshold (memoised).
    band_max_offset_V_ = 0;
    const PixelPattern* pat = stimulus_.pattern;
    if (pat && !pat->offset_V.empty())
      band_max_offset_V_ =
          *std::max_element(pat->max_offset_V.begin() + first_row_, pat->max_offset_V.begin() + first_row_ + rows());
    for (int r = 0; r < rows(); ++r) {
      act_[static_cast<std::size_t>(r)].clear_to_width(columns());
      reset_row_pixels(r, stimulus_.rows[static_cast<std::size_t>(first_row_ + r)], rows_[static_cast<std::size_t>(r)]);
    }
    return;
  }
  if (exact_) {
    reset_exact();
    return;
  }
  for (int r = 0; r < rows(); ++r) {
    const RowIllumination& in = stimulus_.rows[static_cast<std::size_t>(first_row_ + r)];
    RowState& row = rows_[static_cast<std::size_t>(r)];
    act_[static_cast<std::size_t>(r)].clear_to_width(columns());
    set_window(in, row);
    const int W = std::max(0, row.last - row.first + 1);
    row.pixels.resize(static_cast<std::size_t>(W));
    pixels_simulated_ += W;
    pixels_drawn_ += options_.noise.any() ? W : 0;
    for (int j = 0; j < W; ++j) {
      const int i = row.first + j;
      Pixel& p = row.pixels[static_cast<std::size_t>(j)];
      p.profile = golden::spot_profile(config_.spot, i - in.centre_px);
      p.electrons = 0;
      if (options_.noise.any()) {
        p.rng = pixel_stream(
            pixel_key_in_frame(frame_key_, static_cast<std::uint32_t>(first_row_ + r), static_cast<std::uint32_t>(i)));
        double ktc = 0, read = 0;
        standard_normal_pair(p.rng, ktc, read);  // always drawn
        p.offset_V = options_.noise.reset_ktc ? ktc * ktc_V_ : 0.0;
        p.read_V = options_.noise.read ? read * read_V_ : 0.0;
        p.mean_step_e =
            golden::pixel_swing_V(in.signal_V, p.profile, in.background_V, dark_V_, 1.0) * electrons_per_V_ / N;
        // Every sampling interval has the same mean: one sampler per pixel and frame.
        p.shot = PoissonSampler(p.mean_step_e);
      } else {
        p.offset_V = p.read_V = p.mean_step_e = 0;
      }
    }
  }
}

void PixelArrayKernel::sample(int k) {
  assert(have_frame_ && k == sampling_ + 1 && k <= config_.multisampling.samplings && "samplings in order");
  sampling_ = k;
  const int N = config_.multisampling.samplings;
  const double A = config_.pixel.source_follower_gain, vsat = config_.pixel.saturation_voltage_V;
  const double t_over_T = static_cast<double>(k) / N;
  const bool noisy = options_.noise.any();
  if (per_pixel_) {
    sample_pixels(k);
    return;
  }
  if (exact_) {  // the firing samplings were decided at the reset: latch this one's
    sample_exact(k);
    return;
  }
  for (int r = 0; r < rows(); ++r) {
    RowState& row = rows_[static_cast<std::size_t>(r)];
    const RowIllumination& in = stimulus_.rows[static_cast<std::size_t>(first_row_ + r)];
    ActivationRow& act = act_[static_cast<std::size_t>(r)];
    for (int j = 0, W = static_cast<int>(row.pixels.size()); j < W; ++j) {
      const int i = row.first + j;
      if (act.test(i)) continue;  // latched: stays activated
      Pixel& p = row.pixels[static_cast<std::size_t>(j)];
      bool fires;
      if (!noisy) {
        // The golden expression (golden::direct_estimate), clamped at saturation.
        const double swing =
            std::min(golden::pixel_swing_V(in.signal_V, p.profile, in.background_V, dark_V_, t_over_T), vsat);
        fires = A * swing >= row.threshold_V;
      } else {
        const double input_V = noisy_input_V(
            p, [&] { return golden::pixel_swing_V(in.signal_V, p.profile, in.background_V, dark_V_, t_over_T); });
        fires = input_V >= row.threshold_V;
      }
      if (fires) act.set(i);
    }
  }
}

}  // namespace rangesim::systemc
