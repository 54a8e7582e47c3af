#pragma once
// A depth map read from an image file, for `target.shape = "depth_map"` scenes (scene.h).
//   PGM (binary P5 or ASCII P2; maxval <= 255: 8-bit, <= 65535: 16-bit big-endian): gray level g
//     maps linearly to distance, g = 0 -> depth_near_m, g = maxval -> depth_far_m.
//   PFM (grayscale "Pf"): float distances in metres; the scale's sign gives the byte order;
//     rows are stored bottom-to-top (the PFM convention) and flipped here.
// Written here (no image library): both formats are a few lines of header and a raster.
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace rangesim::scene {

struct DepthMap {
  std::string file;             // resolved path (for messages)
  int width = 0, height = 0;    // image size in pixels
  std::vector<double> depth_m;  // row-major, row 0 = top of the image

  double at(int x, int y) const { return depth_m[static_cast<std::size_t>(y) * width + x]; }
  // Bilinear resampling of the image onto a rows x columns pixel grid: pixel centres are mapped
  // to image coordinates so that the image covers the whole array (corners to corners of pixels).
  double sample(int row, int column, int rows, int columns) const;
  std::vector<double> resample(int rows, int columns) const;  // row-major
};

// Reads a depth map. `key` names the scene key for messages (e.g. "scene.toml: target.depth_map_file").
// PGM needs near/far (metres, near != far allowed either way round); PFM ignores them. Every
// distance must lie in [min_m, max_m]. Throws UserError naming the file, the key and the range.
DepthMap load_depth_map(const std::string& path, const std::string& key, double near_m, double far_m, double min_m,
                        double max_m);
// The same for the image's bytes (`path` only names it in messages); the fuzzer's entry point.
DepthMap parse_depth_map(std::string_view bytes, const std::string& path, const std::string& key, double near_m,
                         double far_m, double min_m, double max_m);

// Depth along one row of a resampled map (`z`: the row's n pixel depths), linear between pixel
// centres and clamped at the row's ends: the profile a sheet beam meets on that row.
inline double row_depth_m(const double* z, int n, double c) {
  const int c0 = std::max(0, std::min(n - 1, static_cast<int>(std::floor(c))));
  const int c1 = std::min(n - 1, c0 + 1);
  const double t = std::max(0.0, std::min(1.0, c - c0));
  return (1 - t) * z[c0] + t * z[c1];
}

// The lit point of a row under a sheet beam over a depth map: the first column c (from the left)
// where the stripe of the depth seen at c lands on c itself, a root of g(c) = c - stripe(depth(c)).
// Scans the columns 0 .. n-1 for the first sign change of g, then bisects the piece (60 halvings
// reach a double's resolution). Returns c, or -1 when g has no root: the beam misses the map on
// this row. One root finder for every light-section sensor with a depth-map scene.
template <class G>
double first_lit_column(int n, const G& g) {
  double prev = g(0.0);
  if (prev == 0) return 0.0;
  for (int c = 1; c < n; ++c) {
    const double cur = g(static_cast<double>(c));
    if ((prev < 0) != (cur < 0) || cur == 0) {
      double lo = c - 1, hi = c;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        if ((g(mid) < 0) == (prev < 0))
          lo = mid;
        else
          hi = mid;
      }
      return 0.5 * (lo + hi);
    }
    prev = cur;
  }
  return -1;
}

}  // namespace rangesim::scene
