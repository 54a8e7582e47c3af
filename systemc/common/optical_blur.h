#pragma once
// The optics' point spread and the pixels' crosstalk as a small 2-D kernel on the pixel grid
// (core/nonideal.h BlurConfig): the light meant for pixel (r, c) lands on (r + dr, c + dc) with
// weight w. The PSF is a Gaussian of sigma pixels on the focal plane integrated over each pixel's
// square (separable: w(dr) w(dc) with w(k) = Phi((k + 1/2) / sigma) - Phi((k - 1/2) / sigma)),
// then the crosstalk moves the fraction f of each pixel's charge to its four neighbours (f / 4
// each). Weights below 1e-12 are dropped (a diffraction-limited PSF of a few hundredths of a
// pixel is then exactly the identity). At the array's border the scene is taken to continue its
// edge pixels (a source beyond the edge is the nearest edge pixel), so a uniform scene stays
// uniform and no light is lost or gained there.
#include <vector>

#include "core/nonideal.h"

namespace rangesim::systemc {

struct BlurTap {
  int dr = 0, dc = 0;  // from the source pixel to the receiving one
  double w = 1;        // share of the source pixel's light
};

// The kernel of `blur`, weights summing to 1 (to the dropped weights).
std::vector<BlurTap> blur_taps(const BlurConfig& blur);

// The source pixel of receiving pixel (r, c) through `t`, clamped into the array.
inline int blur_source_index(int r, int c, const BlurTap& t, int rows, int columns) {
  const int rr = r - t.dr < 0 ? 0 : r - t.dr >= rows ? rows - 1 : r - t.dr;
  const int cc = c - t.dc < 0 ? 0 : c - t.dc >= columns ? columns - 1 : c - t.dc;
  return rr * columns + cc;
}

// `image` (rows x columns, row-major) spread by `taps`.
std::vector<double> blur_image(const std::vector<double>& image, int rows, int columns,
                               const std::vector<BlurTap>& taps);

}  // namespace rangesim::systemc
