#pragma once
// A depth map read from an image file, for `target.shape = "depth_map"` scenes (scene.h).
//   PGM (binary P5 or ASCII P2; maxval <= 255: 8-bit, <= 65535: 16-bit big-endian): gray level g
//     maps linearly to distance, g = 0 -> depth_near_m, g = maxval -> depth_far_m.
//   PFM (grayscale "Pf"): float distances in metres; the scale's sign gives the byte order;
//     rows are stored bottom-to-top (the PFM convention) and flipped here.
// Written here (no image library): both formats are a few lines of header and a raster.
#include <string>
#include <string_view>
#include <vector>

namespace rangesim::scene {

struct DepthMap {
  std::string file;            // resolved path (for messages)
  int width = 0, height = 0;   // image size in pixels
  std::vector<double> depth_m; // row-major, row 0 = top of the image

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

}  // namespace rangesim::scene
