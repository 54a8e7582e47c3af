// The point spread and crosstalk kernel (systemc/common/optical_blur.h).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "systemc/common/optical_blur.h"

namespace rangesim::systemc {
namespace {

double total(const std::vector<BlurTap>& taps) {
  return std::accumulate(taps.begin(), taps.end(), 0.0, [](double s, const BlurTap& t) { return s + t.w; });
}

TEST(OpticalBlur, DiffractionAtF14IsTheIdentityAndAGaussianConservesLight) {
  BlurConfig airy;
  airy.psf = PsfKind::Airy;
  airy.wavelength_m = 870e-9, airy.f_number = 1.4, airy.pitch_m = 15e-6;
  EXPECT_NEAR(airy.psf_sigma_px(), 0.42 * 870e-9 * 1.4 / 15e-6, 1e-15);
  EXPECT_EQ(blur_taps(airy).size(), 1u);  // 0.034 px: nothing reaches a neighbour above 1e-12
  BlurConfig g;
  g.psf = PsfKind::Gaussian;
  g.gaussian_sigma_px = 0.7;
  g.crosstalk_fraction = 0.1;
  const std::vector<BlurTap> taps = blur_taps(g);
  EXPECT_NEAR(total(taps), 1.0, 1e-9);
  // Pixel-integrated Gaussian: w0 = Phi(0.5/0.7) - Phi(-0.5/0.7) per direction, w1 the next pixel's
  // share; the centre keeps 90 % of its own w0^2 and gets 2.5 % of each neighbour's w0 w1.
  const double w0 = std::erf(0.5 / 0.7 / std::sqrt(2.0));
  const double w1 = 0.5 * (std::erf(1.5 / 0.7 / std::sqrt(2.0)) - w0);
  double centre = 0;
  for (const BlurTap& t : taps)
    if (t.dr == 0 && t.dc == 0) centre = t.w;
  EXPECT_NEAR(centre, 0.9 * w0 * w0 + 0.1 * w0 * w1, 1e-9);
  // A uniform scene stays uniform, edges included (the scene continues past the array).
  const std::vector<double> flat(6 * 7, 2.5);
  for (double v : blur_image(flat, 6, 7, taps)) EXPECT_NEAR(v, 2.5, 1e-9);
}

TEST(OpticalBlur, AStepBecomesARamp) {
  BlurConfig g;
  g.psf = PsfKind::Gaussian;
  g.gaussian_sigma_px = 1.0;
  std::vector<double> img(10, 0.0);
  for (int c = 5; c < 10; ++c) img[static_cast<std::size_t>(c)] = 1.0;
  const std::vector<double> out = blur_image(img, 1, 10, blur_taps(g));
  // Pixel 4 gets the share of its right neighbours: 1 - Phi(0.5) of a pixel-integrated sigma-1 spread.
  EXPECT_NEAR(out[4], 0.5 * std::erfc(0.5 / std::sqrt(2.0)), 1e-9);
  EXPECT_NEAR(out[4] + out[5], 1.0, 1e-9);
  EXPECT_LT(out[3], out[4]);
}

}  // namespace
}  // namespace rangesim::systemc
