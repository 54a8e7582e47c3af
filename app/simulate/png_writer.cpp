#include "app/simulate/png_writer.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace rangesim::app {

namespace {

class BitWriter {
 public:
  explicit BitWriter(std::string& out) : out_(out) {}
  void put(std::uint32_t value, int bits) {  // least significant bit first, bits <= 32
    acc_ |= static_cast<std::uint64_t>(value) << n_;
    n_ += bits;
    if (n_ >= 32) {  // four bytes at a time
      const char b[4] = {static_cast<char>(acc_), static_cast<char>(acc_ >> 8), static_cast<char>(acc_ >> 16),
                         static_cast<char>(acc_ >> 24)};
      out_.append(b, 4);
      acc_ >>= 32;
      n_ -= 32;
    }
  }
  void put_code(std::uint32_t code, int bits) {  // a Huffman code: most significant bit first
    std::uint32_t r = 0;
    for (int i = 0; i < bits; ++i) r |= ((code >> i) & 1U) << (bits - 1 - i);
    put(r, bits);
  }
  void flush() {  // the last bits, padded to a whole byte
    for (; n_ > 0; n_ -= 8, acc_ >>= 8) out_ += static_cast<char>(acc_ & 0xff);
    n_ = 0;
  }

 private:
  std::string& out_;
  std::uint64_t acc_ = 0;
  int n_ = 0;
};

// The fixed Huffman code of every literal/length symbol (RFC 1951, 3.2.6), bit-reversed for the
// least-significant-first writer.
struct FixedCode {
  std::uint16_t bits[288];
  std::uint8_t length[288];
  FixedCode() {
    for (int sym = 0; sym < 288; ++sym) {
      int code, n;
      if (sym < 144)
        code = 0x30 + sym, n = 8;
      else if (sym < 256)
        code = 0x190 + sym - 144, n = 9;
      else if (sym < 280)
        code = sym - 256, n = 7;
      else
        code = 0xC0 + sym - 280, n = 8;
      int r = 0;
      for (int i = 0; i < n; ++i) r |= ((code >> i) & 1) << (n - 1 - i);
      bits[sym] = static_cast<std::uint16_t>(r);
      length[sym] = static_cast<std::uint8_t>(n);
    }
  }
};

void put_symbol(BitWriter& w, int sym) {
  static const FixedCode code;
  w.put(code.bits[sym], code.length[sym]);
}

constexpr int kLengthBase[] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                               31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr int kLengthExtra[] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr int kDistBase[] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
                             193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr int kDistExtra[] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                              6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

void put_match(BitWriter& w, int length, int distance) {
  int l = 28;
  while (kLengthBase[l] > length) --l;
  put_symbol(w, 257 + l);
  if (kLengthExtra[l]) w.put(static_cast<std::uint32_t>(length - kLengthBase[l]), kLengthExtra[l]);
  int d = 29;
  while (kDistBase[d] > distance) --d;
  w.put_code(static_cast<std::uint32_t>(d), 5);
  if (kDistExtra[d]) w.put(static_cast<std::uint32_t>(distance - kDistBase[d]), kDistExtra[d]);
}

// One fixed-Huffman block appended to `out`: literals, runs (distance 1) and copies of the
// scanline above.
void deflate(const std::vector<std::uint8_t>& data, std::size_t stride, std::string& out) {
  BitWriter w(out);
  w.put(1, 1);  // BFINAL
  w.put(1, 2);  // BTYPE = 01, fixed Huffman
  const std::size_t n = data.size();
  auto run = [&](std::size_t i, std::size_t distance) {
    if (i < distance) return std::size_t{0};
    const std::size_t end = std::min(n, i + 258);
    std::size_t j = i;
    while (j < end && data[j] == data[j - distance]) ++j;
    return j - i;
  };
  for (std::size_t i = 0; i < n;) {
    const std::size_t a = run(i, 1), b = stride <= 32768 ? run(i, stride) : 0;
    const std::size_t len = std::max(a, b);
    if (len >= 3) {
      put_match(w, static_cast<int>(len), static_cast<int>(b >= a ? stride : 1));
      i += len;
    } else {
      put_symbol(w, data[i]);
      ++i;
    }
  }
  put_symbol(w, 256);
  w.flush();
}

std::uint32_t adler32(const std::vector<std::uint8_t>& data) {
  std::uint32_t a = 1, b = 0;
  for (std::size_t i = 0; i < data.size();) {
    const std::size_t end = std::min(data.size(), i + 5552);  // no overflow before the modulo
    for (; i < end; ++i) {
      a += data[i];
      b += a;
    }
    a %= 65521;
    b %= 65521;
  }
  return (b << 16) | a;
}

std::uint32_t crc32(const std::string& bytes, std::size_t from) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xedb88320U ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xffffffffU;
  for (std::size_t i = from; i < bytes.size(); ++i)
    c = table[(c ^ static_cast<std::uint8_t>(bytes[i])) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffU;
}

void put_be32(std::string& s, std::uint32_t v) {
  for (int sh = 24; sh >= 0; sh -= 8) s += static_cast<char>((v >> sh) & 0xff);
}

// A chunk written in place: its length, type and data (appended by `data`), then its CRC.
template <class Data>
void chunk(std::string& png, const char* type, Data data) {
  const std::size_t at = png.size();
  png.append(4, '\0');
  png += type;
  data(png);
  const std::uint32_t n = static_cast<std::uint32_t>(png.size() - at - 8);
  for (int i = 0; i < 4; ++i) png[at + static_cast<std::size_t>(i)] = static_cast<char>((n >> (24 - 8 * i)) & 0xff);
  put_be32(png, crc32(png, at + 4));
}

}  // namespace

void encode_png(const IndexedImage& im, std::string& png) {
  if (im.width < 1 || im.height < 1) throw std::invalid_argument("encode_png: empty image");
  png.assign("\x89PNG\r\n\x1a\n", 8);
  png.reserve(im.scanlines.size() / 2);
  chunk(png, "IHDR", [&](std::string& s) {
    put_be32(s, static_cast<std::uint32_t>(im.width));
    put_be32(s, static_cast<std::uint32_t>(im.height));
    s += std::string("\x08\x03\x00\x00\x00", 5);  // 8 bits, indexed, deflate, filter set 0, no interlace
  });
  chunk(png, "PLTE", [&](std::string& s) {
    for (const auto& c : im.palette) s.append(reinterpret_cast<const char*>(c.data()), 3);
  });
  chunk(png, "IDAT", [&](std::string& s) {
    s += std::string("\x78\x01", 2);  // zlib: deflate, 32 KB window
    deflate(im.scanlines, im.stride(), s);
    put_be32(s, adler32(im.scanlines));
  });
  chunk(png, "IEND", [](std::string&) {});
}

void write_file(const std::string& path, const std::string& bytes) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot write " + path);
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  if (std::fclose(f) != 0 || !ok) throw std::runtime_error("cannot write " + path);
}

}  // namespace rangesim::app
