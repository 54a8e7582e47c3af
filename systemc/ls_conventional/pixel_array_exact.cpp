// The pixel array's exact path (pixel_array_kernel.h, activation_sampler.h): each window pixel's
// first firing sampling decided at the reset, certain ones without a draw; with certain intervals
// (certain_intervals.h) only the band between them is looked at one by one. What the latch then
// holds (extents and bits): pixel_array_extents.cpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "golden/common/pixel.h"
#include "golden/common/spot.h"
#include "systemc/common/keyed_uniforms.h"
#include "systemc/common/random_stream.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"

namespace rangesim::systemc {

void PixelArrayKernel::reset_row_exact(int r, const RowIllumination& in, RowState& row) {
  // A row with the previous row's drive has its shape; anything else makes a new one.
  const bool same = intervals_ && shapes_used_ > 0 && shapes_[shapes_used_ - 1].signal_V == in.signal_V &&
                    shapes_[shapes_used_ - 1].background_V == in.background_V &&
                    shapes_[shapes_used_ - 1].centre_px == in.centre_px;
  row.shape = same ? shapes_used_ - 1 : make_shape(r, in, row);
  const RowShape& s = shapes_[static_cast<std::size_t>(row.shape)];
  row.first = s.first, row.last = s.last, row.threshold_V = s.threshold_V;
  pixels_simulated_ += std::max(0, s.last - s.first + 1);
  row.band_at = band_k_.size();
  row.uniforms = 0;
  if (!intervals_) {  // every window pixel was looked at and decided in make_shape
    for (const BandPixel& p : s.band) band_k_.push_back(static_cast<std::uint8_t>(p.certain));
    return;
  }
  pixels_examined_ += static_cast<long long>(s.band.size());
  for (const BandPixel& p : s.band) {
    int k = p.certain;
    if (k < 0 && s.by_uniform) {  // drawn in finish_row_exact, once every row's uniform is made
      draw_rc_.push_back(row_column(static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(p.column)));
      ++row.uniforms;
      k = 0;
    } else if (k < 0) {
      k = draw(r, s, p, *shape_entry_);
    }
    band_k_.push_back(static_cast<std::uint8_t>(k));
  }
}

void PixelArrayKernel::finish_row_exact(int r, const double*& u) {
  // The row's uniforms (keyed_uniforms, in the order reset_row_exact asked for them) inverted, as
  // draw() would one by one; then its extents.
  const RowState& row = rows_[static_cast<std::size_t>(r)];
  RowShape& s = shapes_[static_cast<std::size_t>(row.shape)];
  std::uint8_t* fk = band_k_.data() + row.band_at;
  if (row.uniforms > 0) {
    if (row.shape != finish_shape_) {  // rows of one shape share its threshold entry
      finish_shape_ = row.shape;
      finish_entry_ = &exact_->entry(s.threshold_V);
    }
    ThresholdEntry& e = *finish_entry_;
    pixels_drawn_ += row.uniforms;
    for (std::size_t j = 0; j < s.band.size(); ++j) {
      const BandPixel& p = s.band[j];
      if (p.certain >= 0) continue;
      fk[j] = static_cast<std::uint8_t>(p.prepared ? exact_->invert_prepared(p.drive, e, s.cut.data() + p.cut_at, *u)
                                                   : exact_->invert_first_firing(p.drive, e, *u));
      ++u;
    }
  }
  fill_extents(r, s, fk);
}

int PixelArrayKernel::make_shape(int r, const RowIllumination& in, RowState& row) {
  const int N = config_.multisampling.samplings;
  if (static_cast<int>(shapes_.size()) <= shapes_used_) shapes_.emplace_back();
  RowShape& s = shapes_[static_cast<std::size_t>(shapes_used_)];
  set_window(in, row);
  s.signal_V = in.signal_V, s.background_V = in.background_V, s.centre_px = in.centre_px;
  s.first = row.first, s.last = row.last, s.threshold_V = row.threshold_V;
  s.core_first.assign(static_cast<std::size_t>(N), 0);
  s.core_last.assign(static_cast<std::size_t>(N), -1);
  s.held_first.assign(static_cast<std::size_t>(N), std::numeric_limits<int>::max());
  s.held_last.assign(static_cast<std::size_t>(N), -1);
  s.band.clear();
  s.cut.clear();
  s.by_uniform = false;
  s.memo_key.fill(RowShape::kNoPattern);
  s.memo_first.resize(RowShape::kMemo * static_cast<std::size_t>(N));
  s.memo_last.resize(RowShape::kMemo * static_cast<std::size_t>(N));
  if (s.last >= s.first) {
    ThresholdEntry& e = exact_->entry(s.threshold_V);
    shape_entry_ = &e;
    if (!intervals_) {
      // Every window pixel one by one; the certain ones draw nothing. Only those that fire are kept.
      pixels_examined_ += s.last - s.first + 1;
      for (int i = s.first; i <= s.last; ++i) {
        BandPixel p = look_at(i, in, e);
        if (p.certain < 0) p.certain = draw(r, s, p, e);
        if (p.certain > 0) s.band.push_back(p);
      }
    } else {
      // Certain pixels by intervals; the band pixels (r_1 < d < s_N on either side) one by one.
      const RowCertainty& c = intervals_->of(in.signal_V, in.background_V, e.b);
      const double x0 = in.centre_px;
      core_ranges(c, x0, s);
      const double inner = std::max(c.fired_within.front(), 0.0), outer = c.never_beyond.back();
      auto col = [&](double x) {
        return static_cast<int>(std::clamp(x, static_cast<double>(s.first), static_cast<double>(s.last)));
      };
      const int left_lo = outer == RowCertainty::kAll ? s.first : col(std::floor(x0 - outer));
      const int left_hi = col(std::ceil(x0 - inner));
      const int right_lo = std::max(col(std::floor(x0 + inner)), left_hi + 1);
      const int right_hi = outer == RowCertainty::kAll ? s.last : col(std::ceil(x0 + outer));
      s.by_uniform = inversion_ && ExactActivation::inversion_applies(e);
      for (int i = left_lo; i <= right_hi; i = (i == left_hi && right_lo > i + 1) ? right_lo : i + 1) {
        if (c.classify(std::fabs(i - x0)) >= 0) continue;
        BandPixel p = look_at(i, in, e);
        if (p.certain < 0 && inversion_ && ExactActivation::inversion_applies(e)) {
          // Every row with this drive draws it against the same f~ values: look them up once.
          p.prepared = true;
          p.cut_at = s.cut.size();
          s.cut.resize(s.cut.size() + 2 * static_cast<std::size_t>(N));
          exact_->prepare_inversion(p.drive, e, s.cut.data() + p.cut_at);
        }
        s.band.push_back(p);
      }
    }
  }
  hold_ranges(s);
  return shapes_used_++;
}

void PixelArrayKernel::core_ranges(const RowCertainty& c, double x0, RowShape& s) const {
  // Columns with |i - x0| <= r_k, found exactly as classify() sees them (the same d = |i - x0|).
  for (std::size_t k = 0; k < c.fired_within.size(); ++k) {
    const double rk = c.fired_within[k];
    if (rk < 0) continue;
    int a = s.first, b = s.last;
    if (rk != RowCertainty::kAll) {
      a = static_cast<int>(std::clamp(std::ceil(x0 - rk), s.first - 1.0, s.last + 1.0));
      b = static_cast<int>(std::clamp(std::floor(x0 + rk), s.first - 1.0, s.last + 1.0));
      while (a <= b && std::fabs(a - x0) > rk) ++a;
      while (a - 1 >= s.first && std::fabs(a - 1 - x0) <= rk) --a;
      while (b >= a && std::fabs(b - x0) > rk) --b;
      while (b + 1 <= s.last && std::fabs(b + 1 - x0) <= rk) ++b;
      a = std::max(a, s.first);
      b = std::min(b, s.last);
    }
    s.core_first[k] = a;
    s.core_last[k] = b;
  }
}

PixelArrayKernel::BandPixel PixelArrayKernel::look_at(int i, const RowIllumination& in, ThresholdEntry& e) const {
  const int N = config_.multisampling.samplings;
  BandPixel p;
  p.column = i;
  p.drive = {in.signal_V, golden::spot_profile(config_.spot, i - in.centre_px), in.background_V, dark_V_, 0.0};
  // The per-sampling path's mean per interval, expression for expression.
  p.drive.mean_step_e =
      golden::pixel_swing_V(in.signal_V, p.drive.profile, in.background_V, dark_V_, 1.0) * electrons_per_V_ / N;
  p.certain = exact_->certain_first_firing(p.drive, e.b);
  return p;
}

int PixelArrayKernel::draw(int r, const RowShape& s, const BandPixel& p, ThresholdEntry& e) {
  ++pixels_drawn_;
  const std::uint64_t key =
      pixel_key_in_frame(frame_key_, static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(p.column));
  if (p.prepared) return exact_->invert_prepared(p.drive, e, s.cut.data() + p.cut_at, keyed_uniform(key));
  if (inversion_ && ExactActivation::inversion_applies(e))
    return exact_->invert_first_firing(p.drive, e, keyed_uniform(key));
  pcg32 rng = pixel_stream(key);
  return exact_->draw_first_firing(p.drive, e.threshold_V, rng);
}

void PixelArrayKernel::sample_exact(int) {
  // The firing samplings were decided at the reset: the rows' extents are ready, their bits are made
  // when asked for (row()).
  ++generation_;
}

}  // namespace rangesim::systemc
