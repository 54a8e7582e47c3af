// The pixel array's per-pixel path (pixel_array_kernel.h): each pixel with its own drive, dark
// swing and comparator offset (the chip's fixed pattern, a spread spot), its noise drawn at every
// sampling as on the per-sampling path.
#include <algorithm>
#include <cassert>
#include <cmath>

#include "golden/common/pixel.h"
#include "golden/common/quantiser.h"
#include "golden/common/spot.h"
#include "systemc/common/random_stream.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"

namespace rangesim::systemc {

void PixelArrayKernel::reset_row_pixels(int r, const RowIllumination& in, RowState& row) {
  const int C = columns(), N = config_.multisampling.samplings, ar = first_row_ + r;
  const PixelPattern* pat = stimulus_.pattern;
  const std::size_t at = static_cast<std::size_t>(ar) * static_cast<std::size_t>(C);
  const bool gain = pat && !pat->gain.empty(), dark = pat && !pat->dark_V.empty();
  const bool offset = pat && !pat->offset_V.empty(), spread = !stimulus_.signal_px_V.empty();
  row.threshold_V = golden::comparator_threshold_V(config_, in.background_V);
  // The band's most favourable comparator bounds every pixel's: below its cut none can fire.
  const double easiest_V = row.threshold_V - band_max_offset_V_;
  const double cut_V = options_.sparse ? cut_swing_V(easiest_V) : -1.0;
  // Beyond reach_px the spot adds less than half an ulp of the background, so the pixel's swing is
  // the background's to the bit and the profile is not evaluated (the exp is most of a row's cost).
  const double reach_px = spread || !(in.signal_V > 0) ? -1.0
                          : in.background_V > 0
                              ? golden::spot_half_width_px(config_.spot, std::ldexp(in.background_V, -55) / in.signal_V)
                              : 1e300;
  row.pixels.clear();
  for (int i = 0; i < C; ++i) {
    const std::size_t x = at + static_cast<std::size_t>(i);
    const double d = i - in.centre_px;
    const double spot_V = spread                     ? stimulus_.signal_px_V[x]
                          : std::fabs(d) <= reach_px ? in.signal_V * golden::spot_profile(config_.spot, d)
                                                     : 0.0;
    const double swing = (gain ? pat->gain[x] : 1.0) * (spot_V + in.background_V) + (dark ? pat->dark_V[x] : dark_V_);
    if (swing < cut_V) continue;
    Pixel& p = row.pixels.emplace_back();
    p.column = i;
    p.swing_T_V = swing;
    p.comparator_V = offset ? pat->offset_V[x] : 0.0;
    p.electrons = 0;
    p.offset_V = p.read_V = p.mean_step_e = 0;
    if (!options_.noise.any()) continue;
    p.rng = pixel_stream(pixel_key_in_frame(frame_key_, static_cast<std::uint32_t>(ar), static_cast<std::uint32_t>(i)));
    double ktc = 0, read = 0;
    standard_normal_pair(p.rng, ktc, read);
    p.offset_V = options_.noise.reset_ktc ? ktc * ktc_V_ : 0.0;
    p.read_V = options_.noise.read ? read * read_V_ : 0.0;
    p.mean_step_e = swing * electrons_per_V_ / N;
    p.shot = PoissonSampler(p.mean_step_e);
  }
  const long long W = static_cast<long long>(row.pixels.size());
  row.first = W > 0 ? row.pixels.front().column : 0;
  row.last = W > 0 ? row.pixels.back().column : -1;
  pixels_simulated_ += W;
  pixels_drawn_ += options_.noise.any() ? W : 0;
}

void PixelArrayKernel::sample_pixels(int k) {
  const int N = config_.multisampling.samplings;
  const double A = config_.pixel.source_follower_gain, vsat = config_.pixel.saturation_voltage_V;
  const double t_over_T = static_cast<double>(k) / N;
  const bool noisy = options_.noise.any();
  for (int r = 0; r < rows(); ++r) {
    RowState& row = rows_[static_cast<std::size_t>(r)];
    ActivationRow& act = act_[static_cast<std::size_t>(r)];
    for (Pixel& p : row.pixels) {
      if (act.test(p.column)) continue;  // latched
      const double input_V =
          noisy ? noisy_input_V(p, [&] { return p.swing_T_V * t_over_T; }) : A * std::min(p.swing_T_V * t_over_T, vsat);
      if (input_V + p.comparator_V >= row.threshold_V) act.set(p.column);
    }
  }
}

}  // namespace rangesim::systemc
