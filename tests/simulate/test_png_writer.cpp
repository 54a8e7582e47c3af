// encode_png (app/simulate/png_writer.cpp) read back by an independent decoder written here:
// every chunk's CRC against a bit-by-bit CRC-32, the IDAT stream inflated (fixed-Huffman blocks,
// RFC 1951 3.2.6, the only kind the encoder writes) back to the very scanlines, and the zlib
// trailer against a byte-by-byte Adler-32. Image widths cover every tail of the encoder's 8-byte
// match compare, 8-byte CRC and 16-byte Adler steps; the contents cover literals, runs, copies of
// the row above and their mixtures.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/simulate/png_writer.h"

namespace {

using rangesim::app::encode_png;
using rangesim::app::IndexedImage;

std::uint32_t crc_bitwise(const std::string& s, std::size_t from, std::size_t to) {
  std::uint32_t c = 0xffffffffU;
  for (std::size_t i = from; i < to; ++i) {
    c ^= static_cast<std::uint8_t>(s[i]);
    for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xedb88320U ^ (c >> 1) : c >> 1;
  }
  return c ^ 0xffffffffU;
}

std::uint32_t adler_bytewise(const std::vector<std::uint8_t>& d) {
  std::uint32_t a = 1, b = 0;
  for (std::uint8_t x : d) a = (a + x) % 65521, b = (b + a) % 65521;
  return (b << 16) | a;
}

std::uint32_t be32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = v << 8 | static_cast<std::uint8_t>(s[at + static_cast<std::size_t>(i)]);
  return v;
}

// A fixed-Huffman-only inflater.
class Inflater {
 public:
  explicit Inflater(const std::string& z) : z_(z) {}
  std::vector<std::uint8_t> run() {
    std::vector<std::uint8_t> out;
    bool last = false;
    while (!last) {
      last = bits(1) == 1;
      if (bits(2) != 1) throw std::runtime_error("not a fixed-Huffman block");
      for (;;) {
        const int sym = literal_length();
        if (sym < 256) {
          out.push_back(static_cast<std::uint8_t>(sym));
          continue;
        }
        if (sym == 256) break;
        static const int base[] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                   31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
        static const int extra[] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                    2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
        const int l = sym - 257;
        const int len = base[l] + static_cast<int>(bits(extra[l]));
        if (l == 27 && len == 258) throw std::runtime_error("length 258 as code 284 (RFC 1951: 285)");
        int dcode = 0;
        for (int i = 0; i < 5; ++i) dcode = dcode << 1 | static_cast<int>(bits(1));
        const int dextra = dcode < 4 ? 0 : dcode / 2 - 1;
        const int dbase = dcode < 4 ? dcode + 1 : (2 + (dcode & 1)) << dextra | 1;
        const std::size_t dist = static_cast<std::size_t>(dbase + static_cast<int>(bits(dextra)));
        if (dist > out.size()) throw std::runtime_error("distance beyond the start");
        for (int i = 0; i < len; ++i) out.push_back(out[out.size() - dist]);
      }
    }
    return out;
  }

 private:
  std::uint32_t bits(int n) {  // least significant first
    std::uint32_t v = 0;
    for (int i = 0; i < n; ++i, ++pos_) {
      if (pos_ / 8 >= z_.size()) throw std::runtime_error("stream ends early");
      v |= static_cast<std::uint32_t>((static_cast<std::uint8_t>(z_[pos_ / 8]) >> (pos_ % 8)) & 1U) << i;
    }
    return v;
  }
  int literal_length() {  // RFC 1951 3.2.6: 7-, 8- or 9-bit codes, most significant bit first
    int code = 0;
    for (int i = 0; i < 7; ++i) code = code << 1 | static_cast<int>(bits(1));
    if (code <= 0x17) return 256 + code;
    code = code << 1 | static_cast<int>(bits(1));
    if (code >= 0x30 && code <= 0xbf) return code - 0x30;
    if (code >= 0xc0 && code <= 0xc7) return 280 + code - 0xc0;
    code = code << 1 | static_cast<int>(bits(1));
    return 144 + code - 0x190;
  }
  const std::string& z_;
  std::size_t pos_ = 0;
};

// Decodes `png`, checking it on the way; returns the inflated scanlines.
std::vector<std::uint8_t> decode(const std::string& png, int width, int height) {
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  std::string idat;
  std::vector<std::string> types;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::size_t n = be32(png, at);
    const std::string type = png.substr(at + 4, 4);
    types.push_back(type);
    EXPECT_EQ(be32(png, at + 8 + n), crc_bitwise(png, at + 4, at + 8 + n)) << type;
    if (type == "IHDR") {
      EXPECT_EQ(be32(png, at + 8), static_cast<std::uint32_t>(width));
      EXPECT_EQ(be32(png, at + 12), static_cast<std::uint32_t>(height));
    }
    if (type == "IDAT") idat += png.substr(at + 8, n);
    at += 12 + n;
  }
  EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "PLTE", "IDAT", "IEND"}));
  EXPECT_GE(idat.size(), 6U);
  EXPECT_EQ(idat.substr(0, 2), std::string("\x78\x01", 2));
  const std::string deflated = idat.substr(2, idat.size() - 6);
  std::vector<std::uint8_t> lines = Inflater(deflated).run();
  EXPECT_EQ(be32(idat, idat.size() - 4), adler_bytewise(lines));
  return lines;
}

// Rows of random indices, runs and copies of the row above, mixed in one image.
IndexedImage pattern_image(int w, int h, std::uint64_t seed) {
  IndexedImage im(w, h);
  std::mt19937_64 g(seed);
  for (int y = 0; y < h; ++y) {
    const int kind = static_cast<int>(g() % 4);
    for (int x = 0; x < w; ++x) {
      std::uint8_t v = static_cast<std::uint8_t>(g() % 256);
      if (kind == 1) v = static_cast<std::uint8_t>(x / 11);         // runs
      if (kind == 2 && y > 0) v = im.at(x, y - 1);                  // the row above
      if (kind == 3 && y > 0 && g() % 8 != 0) v = im.at(x, y - 1);  // the row above, mostly
      if (kind == 0 && g() % 3 == 0 && x > 0) v = im.at(x - 1, y);  // short runs
      im.at(x, y) = v;
    }
  }
  return im;
}

TEST(PngWriter, DecodesToTheScanlinesAtEveryTailLength) {
  std::string png;
  for (int w = 1; w <= 40; ++w)
    for (int h : {1, 2, 3, 7}) {
      const IndexedImage im = pattern_image(w, h, static_cast<std::uint64_t>(w * 31 + h));
      encode_png(im, png);
      EXPECT_EQ(decode(png, w, h), im.scanlines) << w << " x " << h;
    }
}

TEST(PngWriter, DecodesAMapSizedImageWithLongRunsAndCopies) {
  std::string png;
  IndexedImage im = pattern_image(603, 477, 7);
  for (int x = 0; x < 603; ++x) im.at(x, 5) = 9;  // runs longer than a match's 258 bytes
  encode_png(im, png);
  EXPECT_EQ(decode(png, 603, 477), im.scanlines);
  EXPECT_LT(png.size(), im.scanlines.size());  // the runs and copies were matched
  // Every match the greedy rule finds, none lost: the size of the one-position-at-a-time encoder
  // (before the literal scan, the sixteen-byte compares and the one-kind matches).
  EXPECT_EQ(png.size(), 114043U);
  // The buffer reused for a smaller image holds only that image.
  const IndexedImage small = pattern_image(5, 3, 1);
  encode_png(small, png);
  EXPECT_EQ(decode(png, 5, 3), small.scanlines);
}

}  // namespace
