#include "app/simulate/png_writer.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "png_writer stores the bit accumulator's low bytes first and finds mismatches by the lowest byte"
#endif

namespace rangesim::app {

namespace {

// Bits, least significant first, into `out` sized beforehand for the worst case (8 bytes at a time
// without a capacity check); finish() cuts it to what was written. No branch: every put stores the
// accumulator's 8 bytes and moves on by its whole bytes (when to flush was a mispredicted branch
// per symbol).
class BitWriter {
 public:
  BitWriter(std::string& out, std::size_t max_bytes) : out_(out), at_(out.size()) { out_.resize(at_ + max_bytes + 16); }
  void put(std::uint64_t value, int bits) {  // bits <= 56
    acc_ |= value << n_;
    n_ += bits;
    std::memcpy(&out_[at_], &acc_, 8);  // little-endian: the low bits first
    at_ += static_cast<std::size_t>(n_ >> 3);
    acc_ >>= n_ & ~7;  // n_ <= 63 here
    n_ &= 7;
  }
  void finish() {  // the last bits, padded to a whole byte
    if (n_ > 0) out_[at_++] = static_cast<char>(acc_ & 0xff);
    n_ = 0;
    out_.resize(at_);
  }

 private:
  std::string& out_;
  std::size_t at_;
  std::uint64_t acc_ = 0;
  int n_ = 0;
};

std::uint32_t reversed(std::uint32_t code, int bits) {  // a Huffman code is sent most significant bit first
  std::uint32_t r = 0;
  for (int i = 0; i < bits; ++i) r |= ((code >> i) & 1U) << (bits - 1 - i);
  return r;
}

// The fixed Huffman code of every literal/length symbol (RFC 1951, 3.2.6) and the 5-bit distance
// codes, bit-reversed for the least-significant-first writer.
struct FixedCode {
  std::uint16_t bits[288];
  std::uint8_t length[288];
  std::uint8_t distance[30];
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
      bits[sym] = static_cast<std::uint16_t>(reversed(static_cast<std::uint32_t>(code), n));
      length[sym] = static_cast<std::uint8_t>(n);
    }
    for (int d = 0; d < 30; ++d) distance[d] = static_cast<std::uint8_t>(reversed(static_cast<std::uint32_t>(d), 5));
  }
};

const FixedCode kCode;

void put_symbol(BitWriter& w, int sym) { w.put(kCode.bits[sym], kCode.length[sym]); }

constexpr int kLengthBase[] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                               31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr int kLengthExtra[] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr int kDistBase[] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
                             193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr int kDistExtra[] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                              6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

// A match distance as its bit-reversed 5-bit code and extra bits, worked out once per distance.
struct Distance {
  std::uint32_t code = 0, extra = 0;
  int extra_bits = 0;
  explicit Distance(int distance) {
    int d = 29;
    while (kDistBase[d] > distance) --d;
    code = kCode.distance[d];
    extra_bits = kDistExtra[d];
    extra = static_cast<std::uint32_t>(distance - kDistBase[d]);
  }
};

// Every match length 3..258 as its length symbol's code followed by its extra bits, as sent.
struct LengthCodes {
  std::uint32_t bits[259] = {};
  std::uint8_t count[259] = {};
  LengthCodes() {
    for (int len = 3, l = 0; len <= 258; ++len) {
      while (l < 28 && kLengthBase[l + 1] <= len) ++l;
      const int sym = 257 + l;
      bits[len] = kCode.bits[sym] | static_cast<std::uint32_t>(len - kLengthBase[l]) << kCode.length[sym];
      count[len] = static_cast<std::uint8_t>(kCode.length[sym] + kLengthExtra[l]);
    }
  }
};

const LengthCodes kLength;

// A match in one put: its length's code and extra bits (at most 13), then the distance's (at most
// 18).
void put_match(BitWriter& w, int length, const Distance& d) {
  const int n = kLength.count[length];
  w.put(kLength.bits[length] | static_cast<std::uint64_t>(d.code | d.extra << 5) << n, n + 5 + d.extra_bits);
}

// How many bytes from i on (at most 258, not past n) equal those `distance` before them; eight at
// a time (the first differing byte is the lowest set byte of the XOR on a little-endian host).
std::size_t match_length(const std::uint8_t* data, std::size_t n, std::size_t i, std::size_t distance) {
  if (i < distance) return 0;
  const std::size_t end = std::min(n, i + 258);
  std::size_t j = i;
#if defined(__SSE2__)
  for (; j + 16 <= end; j += 16) {  // sixteen at a time where it can: margins are 258-byte matches
    const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + j));
    const __m128i y = _mm_loadu_si128(reinterpret_cast<const __m128i*>(data + j - distance));
    const auto same = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(x, y)));
    if (same != 0xffffU) return j - i + static_cast<std::size_t>(__builtin_ctz(~same));
  }
#endif
  for (; j + 8 <= end; j += 8) {
    std::uint64_t x, y;
    std::memcpy(&x, data + j, 8);
    std::memcpy(&y, data + j - distance, 8);
    if (x != y) return j - i + static_cast<std::size_t>(__builtin_ctzll(x ^ y) / 8);
  }
  while (j < end && data[j] == data[j - distance]) ++j;
  return j - i;
}

// The literals before the next match among the 30 positions from i on (i >= stride, i + 32 <= n),
// 30 when none starts there, and the lengths of the runs (distance 1) and copies of the line above
// (distance stride) that start after them, 0 for one shorter than 3 bytes. Bit j of a 32-bit mask
// says byte i + j equals the byte `distance` before it; a match starts at j where bits j, j + 1 and
// j + 2 are set, and lasts as far as the set bits from j: only a match that reaches the 32 bytes'
// end is measured on (match_length). Inside a heat map literals and short matches alternate: one
// look finds the next match and both its lengths, where each position took two match attempts.
// With the 16-byte compares, a full map's image encoded in 0.57-0.59 ms against 0.86-0.89 ms; with
// the lengths read from the masks, a match sent in one put and no branch in the bit writer,
// 0.45-0.46 ms against 0.57-0.59 (fastest of 200, pinned, interleaved runs).
struct Ahead {
  std::size_t literals;  // 30: no match starts in the 30
  std::size_t run, above;
};
#if defined(__SSE2__)
std::uint32_t equal_mask(const std::uint8_t* p, std::size_t distance) {
  const auto load = [](const std::uint8_t* q) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(q)); };
  const auto lo = static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(load(p), load(p - distance))));
  const auto hi = static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_cmpeq_epi8(load(p + 16), load(p + 16 - distance))));
  return lo | hi << 16;
}
Ahead look_ahead(const std::uint8_t* data, std::size_t n, std::size_t i, std::size_t stride) {
  const std::uint32_t a = equal_mask(data + i, 1), b = equal_mask(data + i, stride);
  const std::uint32_t a3 = a & a >> 1 & a >> 2 & 0x3fffffffU, b3 = b & b >> 1 & b >> 2 & 0x3fffffffU;
  if ((a3 | b3) == 0) return {30, 0, 0};
  const int k = __builtin_ctz(a3 | b3);
  const auto length = [&](std::uint32_t equal, std::uint32_t starts, std::size_t distance) -> std::size_t {
    if (((starts >> k) & 1U) == 0) return 0;
    const auto len = static_cast<std::size_t>(__builtin_ctzll(~(static_cast<std::uint64_t>(equal) >> k)));
    return len < static_cast<std::size_t>(32 - k) ? len
                                                  : match_length(data, n, i + static_cast<std::size_t>(k), distance);
  };
  return {static_cast<std::size_t>(k), length(a, a3, 1), length(b, b3, stride)};
}
constexpr bool kLiteralScan = true;
#else
Ahead look_ahead(const std::uint8_t*, std::size_t, std::size_t, std::size_t) { return {0, 0, 0}; }
constexpr bool kLiteralScan = false;
#endif

// One fixed-Huffman block appended to `out`: literals, runs (distance 1) and copies of the
// scanline above, the longer of the two where one reaches 3 bytes.
void deflate(const std::vector<std::uint8_t>& image, std::size_t stride, std::string& out) {
  const std::size_t n = image.size();
  const std::uint8_t* data = image.data();
  BitWriter w(out, n * 9 / 8 + 8);  // 9 bits a literal at most; a match is shorter than its bytes
  w.put(1, 1);                      // BFINAL
  w.put(1, 2);                      // BTYPE = 01, fixed Huffman
  const Distance run(1), above(static_cast<int>(std::min<std::size_t>(stride, 32768)));
  for (std::size_t i = 0; i < n;) {
    std::size_t a, b;  // the run's and the copy's lengths from i
    if (kLiteralScan && stride <= 32768 && i >= stride && i + 32 <= n) {
      const Ahead ahead = look_ahead(data, n, i, stride);
      for (const std::size_t end = i + ahead.literals; i < end; ++i) put_symbol(w, data[i]);
      if (ahead.literals == 30) continue;  // no match starts in the 30: look again from there
      a = ahead.run, b = ahead.above;
    } else {
      a = match_length(data, n, i, 1), b = stride <= 32768 ? match_length(data, n, i, stride) : 0;
    }
    const std::size_t len = std::max(a, b);
    if (len >= 3) {
      put_match(w, static_cast<int>(len), b >= a ? above : run);
      i += len;
    } else {
      put_symbol(w, data[i]);
      ++i;
    }
  }
  put_symbol(w, 256);
  w.finish();
}

// Adler-32 (RFC 1950) 16 bytes at a time: over a block x_0..x_15, a gains sum x_i and b gains
// 16 a + sum (16 - i) x_i, sums without a carried dependency. With SSE2 the blocks of a chunk are
// summed in vector lanes and b takes the a's the chunk's blocks started from at once:
// 16 a_0 m + 16 sum_j S_j + sum_j W_j over its m blocks (S_j the bytes before block j, W_j block
// j's weighted sum), in 64 bits (the scalar sums were 8% of an image's encoding in perf).
std::uint32_t adler32(const std::vector<std::uint8_t>& data) {
  std::uint32_t a = 1, b = 0;
  const std::uint8_t* p = data.data();
  std::size_t left = data.size();
  while (left > 0) {
    std::size_t n = std::min<std::size_t>(left, 5552);  // no overflow before the modulo
    left -= n;
#if defined(__SSE2__)
    if (n >= 16) {
      const __m128i zero = _mm_setzero_si128();
      const __m128i w_lo = _mm_setr_epi16(16, 15, 14, 13, 12, 11, 10, 9), w_hi = _mm_setr_epi16(8, 7, 6, 5, 4, 3, 2, 1);
      __m128i sums = zero, before = zero, weighted = zero;  // 64-bit, 64-bit and 32-bit lanes
      const std::size_t blocks = n / 16;
      for (std::size_t j = 0; j < blocks; ++j, p += 16) {
        const __m128i x = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
        before = _mm_add_epi64(before, sums);
        sums = _mm_add_epi64(sums, _mm_sad_epu8(x, zero));
        weighted = _mm_add_epi32(weighted, _mm_add_epi32(_mm_madd_epi16(_mm_unpacklo_epi8(x, zero), w_lo),
                                                         _mm_madd_epi16(_mm_unpackhi_epi8(x, zero), w_hi)));
      }
      alignas(16) std::uint64_t s[2], bf[2];
      alignas(16) std::uint32_t w[4];
      _mm_store_si128(reinterpret_cast<__m128i*>(s), sums);
      _mm_store_si128(reinterpret_cast<__m128i*>(bf), before);
      _mm_store_si128(reinterpret_cast<__m128i*>(w), weighted);
      const std::uint64_t bb = b + 16 * static_cast<std::uint64_t>(blocks) * a + 16 * (bf[0] + bf[1]) +
                               (static_cast<std::uint64_t>(w[0]) + w[1] + w[2] + w[3]);
      b = static_cast<std::uint32_t>(bb % 65521);
      a = static_cast<std::uint32_t>((a + s[0] + s[1]) % 65521);
      n -= blocks * 16;
    }
#endif
    for (; n >= 16; n -= 16, p += 16) {
      std::uint32_t sum = 0, weighted = 0;
      for (int i = 0; i < 16; ++i) {
        sum += p[i];
        weighted += static_cast<std::uint32_t>(16 - i) * p[i];
      }
      b += 16 * a + weighted;
      a += sum;
    }
    for (; n > 0; --n, ++p) {
      a += *p;
      b += a;
    }
    a %= 65521;
    b %= 65521;
  }
  return (b << 16) | a;
}

// CRC-32 of PNG chunks (ISO 3309), eight bytes a step through eight tables: t[k][n] is the CRC
// of byte n followed by k zero bytes.
struct CrcTables {
  std::uint32_t t[8][256];
  CrcTables() {
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1U) ? 0xedb88320U ^ (c >> 1) : c >> 1;
      t[0][n] = c;
    }
    for (std::uint32_t n = 0; n < 256; ++n)
      for (int k = 1; k < 8; ++k) t[k][n] = (t[k - 1][n] >> 8) ^ t[0][t[k - 1][n] & 0xff];
  }
};

const CrcTables kCrc;

std::uint32_t crc32(const std::string& bytes, std::size_t from) {
  const auto& t = kCrc.t;
  const auto* p = reinterpret_cast<const std::uint8_t*>(bytes.data()) + from;
  std::size_t n = bytes.size() - from;
  std::uint32_t c = 0xffffffffU;
  for (; n >= 8; n -= 8, p += 8) {
    const std::uint32_t lo = c ^ (p[0] | p[1] << 8 | p[2] << 16 | static_cast<std::uint32_t>(p[3]) << 24);
    c = t[7][lo & 0xff] ^ t[6][(lo >> 8) & 0xff] ^ t[5][(lo >> 16) & 0xff] ^ t[4][lo >> 24] ^ t[3][p[4]] ^ t[2][p[5]] ^
        t[1][p[6]] ^ t[0][p[7]];
  }
  for (; n > 0; --n, ++p) c = t[0][(c ^ *p) & 0xff] ^ (c >> 8);
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
