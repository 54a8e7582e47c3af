#pragma once
// A PNG writer for the map images (app/simulate/map_image.h): 8-bit indexed colour with a palette,
// compressed in-process with no library. The deflate stream uses the fixed Huffman code and two
// kinds of match only, a run of the byte before (distance 1) and the same bytes one scanline up
// (distance = stride): a heat map drawn in squares of pixels is made of both. Format: PNG
// (ISO/IEC 15948), zlib (RFC 1950) and deflate (RFC 1951).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace rangesim::app {

struct IndexedImage {
  int width = 0, height = 0;
  // Palette indices row by row, top row first, each row led by its PNG filter byte (0: none), so
  // the encoder compresses this very buffer.
  std::vector<std::uint8_t> scanlines;
  std::array<std::array<std::uint8_t, 3>, 256> palette{};  // RGB
  IndexedImage(int w, int h) { reset(w, h); }
  // A blank (index 0) w x h image, in the same memory where it fits.
  void reset(int w, int h) {
    width = w, height = h;
    scanlines.assign((static_cast<std::size_t>(w) + 1) * static_cast<std::size_t>(h), 0);
  }
  std::size_t stride() const { return static_cast<std::size_t>(width) + 1; }
  std::uint8_t* row(int y) { return &scanlines[static_cast<std::size_t>(y) * stride() + 1]; }
  std::uint8_t& at(int x, int y) { return row(y)[x]; }
};

// The image as PNG file bytes, into `png` (its memory reused).
void encode_png(const IndexedImage& image, std::string& png);
// Writes bytes to `path`; throws std::runtime_error naming the path when it cannot.
void write_file(const std::string& path, const std::string& bytes);

}  // namespace rangesim::app
