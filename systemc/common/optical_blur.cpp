#include "systemc/common/optical_blur.h"

#include <cmath>
#include <map>
#include <utility>

namespace rangesim::systemc {

namespace {

constexpr double kDropBelow = 1e-12;

double phi(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// Pixel-integrated 1-D Gaussian weights w(-n..n).
std::vector<double> pixel_weights(double sigma_px, int& half) {
  if (!(sigma_px > 0)) {
    half = 0;
    return {1.0};
  }
  half = static_cast<int>(std::ceil(8 * sigma_px + 0.5));
  std::vector<double> w(static_cast<std::size_t>(2 * half + 1));
  for (int k = -half; k <= half; ++k)
    w[static_cast<std::size_t>(k + half)] = phi((k + 0.5) / sigma_px) - phi((k - 0.5) / sigma_px);
  return w;
}

}  // namespace

std::vector<BlurTap> blur_taps(const BlurConfig& blur) {
  int half = 0;
  const std::vector<double> w = pixel_weights(blur.psf_sigma_px(), half);
  const double f = blur.crosstalk_fraction;
  const std::pair<int, int> cross[5] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  const double cross_w[5] = {1 - f, f / 4, f / 4, f / 4, f / 4};
  std::map<std::pair<int, int>, double> sum;
  for (int i = -half; i <= half; ++i)
    for (int j = -half; j <= half; ++j) {
      const double psf = w[static_cast<std::size_t>(i + half)] * w[static_cast<std::size_t>(j + half)];
      if (psf < kDropBelow) continue;
      for (int x = 0; x < 5; ++x)
        if (cross_w[x] > 0) sum[{i + cross[x].first, j + cross[x].second}] += psf * cross_w[x];
    }
  std::vector<BlurTap> taps;
  for (const auto& [d, v] : sum)
    if (v >= kDropBelow) taps.push_back({d.first, d.second, v});
  return taps;
}

std::vector<double> blur_image(const std::vector<double>& image, int rows, int columns,
                               const std::vector<BlurTap>& taps) {
  std::vector<double> out(image.size(), 0.0);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      double v = 0;
      for (const BlurTap& t : taps)
        v += t.w * image[static_cast<std::size_t>(blur_source_index(r, c, t, rows, columns))];
      out[static_cast<std::size_t>(r) * columns + c] = v;
    }
  return out;
}

}  // namespace rangesim::systemc
