#include "app/simulate/map_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__x86_64__)
#include <immintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "app/simulate/bitmap_font.h"
#include "app/simulate/png_writer.h"

namespace rangesim::app {

namespace {

constexpr std::uint8_t kWhite = 0, kBlack = 1, kRamp0 = 2;  // palette: paper, ink, then the colour ramp
constexpr int kRampSize = 254;
constexpr int kText = 2;                             // glyph scale
constexpr int kAdvance = (kGlyphWidth + 1) * kText;  // per character
constexpr int kLine = kGlyphHeight * kText;          // text height

// The stops of plot_style's palettes (viridis; the diverging blue-white-red).
constexpr std::uint32_t kViridis[] = {0x440154, 0x482878, 0x3e4989, 0x31688e, 0x26828e,
                                      0x1f9e89, 0x35b779, 0x6ece58, 0xb5de2b, 0xfde725};
constexpr std::uint32_t kDiverging[] = {0x2166ac, 0x67a9cf, 0xd1e5f0, 0xf7f7f7, 0xfddbc7, 0xef8a62, 0xb2182b};

template <std::size_t N>
void set_ramp(IndexedImage& im, const std::uint32_t (&stops)[N]) {
  for (int i = 0; i < kRampSize; ++i) {
    const double x = static_cast<double>(i) / (kRampSize - 1) * (N - 1);
    const std::size_t a = std::min(static_cast<std::size_t>(x), N - 2);
    const double f = x - static_cast<double>(a);
    for (int ch = 0; ch < 3; ++ch) {
      const int sh = 16 - 8 * ch;
      const double v = (1 - f) * ((stops[a] >> sh) & 0xff) + f * ((stops[a + 1] >> sh) & 0xff);
      im.palette[static_cast<std::size_t>(kRamp0 + i)][static_cast<std::size_t>(ch)] =
          static_cast<std::uint8_t>(std::lround(v));
    }
  }
}

class Canvas {
 public:
  explicit Canvas(IndexedImage& im) : im_(im) {}
  void fill(int x, int y, int w, int h, std::uint8_t c) {
    for (int j = std::max(0, y); j < std::min(im_.height, y + h); ++j)
      for (int i = std::max(0, x); i < std::min(im_.width, x + w); ++i) im_.at(i, j) = c;
  }
  int text_width(const std::string& s) const { return static_cast<int>(s.size()) * kAdvance - kText; }
  // Left to right from (x, y) = the text's top-left corner.
  void text(int x, int y, const std::string& s) {
    for (std::size_t n = 0; n < s.size(); ++n) glyph(s[n], x + static_cast<int>(n) * kAdvance, y, false);
  }
  // Bottom to top (rotated a quarter turn anticlockwise) from (x, y) = its bottom-left corner.
  void text_up(int x, int y, const std::string& s) {
    for (std::size_t n = 0; n < s.size(); ++n) glyph(s[n], x, y - static_cast<int>(n) * kAdvance, true);
  }

 private:
  void glyph(char c, int x, int y, bool up) {
    const unsigned char* rows = glyph_rows(c);
    for (int gy = 0; gy < kGlyphHeight; ++gy)
      for (int gx = 0; gx < kGlyphWidth; ++gx)
        if (rows[gy] & (16 >> gx)) {
          if (up)
            fill(x + gy * kText, y - (gx + 1) * kText, kText, kText, kBlack);
          else
            fill(x + gx * kText, y + gy * kText, kText, kText, kBlack);
        }
  }
  IndexedImage& im_;
};

// The ramp's colour of value v on [lo, lo + span]: x = (v - lo) / span clamped to [0, 1], then
// x (kRampSize - 1) rounded half up, as std::lround does for x >= 0, without its library call or a
// branch on the fraction (y - k is exact, and 2 (y - k) truncates to 1 from 0.5 on).
std::uint8_t ramp_index(double v, double lo, double span) {
  const double y = std::min(std::max((v - lo) / span, 0.0), 1.0) * (kRampSize - 1);
  const int k = static_cast<int>(y);
  return static_cast<std::uint8_t>(kRamp0 + k + static_cast<int>(2 * (y - k)));
}

// Tick values: a step of 1, 2 or 5 times a power of ten giving at most `most` ticks over [lo, hi].
std::vector<double> ticks(double lo, double hi, int most) {
  const double span = std::max(hi - lo, 1e-300);
  double step = std::pow(10.0, std::floor(std::log10(span / most)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (span / (m * step) <= most) {
      step *= m;
      break;
    }
  std::vector<double> t;
  for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) t.push_back(v);
  return t;
}

// The text in the font's characters: a UTF-8 dash as '-', any other non-ASCII character as one '?'.
std::string ascii(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    std::size_t n = 1;
    while (i + n < s.size() && (static_cast<unsigned char>(s[i + n]) & 0xc0) == 0x80) ++n;
    const bool dash = n == 3 && c == 0xe2 && static_cast<unsigned char>(s[i + 1]) == 0x80 &&
                      (static_cast<unsigned char>(s[i + 2]) == 0x93 || static_cast<unsigned char>(s[i + 2]) == 0x94);
    out += dash ? '-' : '?';
    i += n;
  }
  return out;
}

// The text in lines of at most `chars` characters, broken at spaces where it can be (at most 3).
std::vector<std::string> wrap(const std::string& text, std::size_t chars) {
  chars = std::max<std::size_t>(chars, 1);
  std::vector<std::string> lines;
  std::size_t at = 0;
  while (at < text.size() && lines.size() < 3) {
    std::size_t end = std::min(text.size(), at + chars);
    if (end < text.size()) {
      const std::size_t space = text.rfind(' ', end);
      if (space != std::string::npos && space > at) end = space;
    }
    lines.push_back(text.substr(at, end - at));
    at = end;
    while (at < text.size() && text[at] == ' ') ++at;
  }
  return lines;
}

std::string fit(const std::string& s, std::size_t chars) {
  const std::string a = ascii(s);
  return a.size() <= chars ? a : a.substr(0, chars);
}

}  // namespace

#if defined(__x86_64__)
// Four cells' indices as int32, 0 (kWhite) where a value is not finite (the SSE2 pair's steps).
__attribute__((target("avx2"), always_inline)) inline __m128i four_colours(const double* p, __m256d lo, __m256d span) {
  const __m256d x = _mm256_loadu_pd(p);
  const __m256d magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
  const __m256d finite =  // false for NaN and inf
      _mm256_cmp_pd(_mm256_and_pd(x, magnitude), _mm256_set1_pd(std::numeric_limits<double>::max()), _CMP_LE_OQ);
  const __m256d y = _mm256_mul_pd(
      _mm256_min_pd(
          _mm256_max_pd(_mm256_div_pd(_mm256_sub_pd(_mm256_and_pd(finite, x), lo), span), _mm256_setzero_pd()),
          _mm256_set1_pd(1.0)),
      _mm256_set1_pd(kRampSize - 1));
  const __m128i k = _mm256_cvttpd_epi32(y);
  const __m128i f = _mm256_cvttpd_epi32(_mm256_mul_pd(_mm256_set1_pd(2.0), _mm256_sub_pd(y, _mm256_cvtepi32_pd(k))));
  const __m128i keep = _mm256_castsi256_si128(
      _mm256_permutevar8x32_epi32(_mm256_castpd_si256(finite), _mm256_setr_epi32(0, 2, 4, 6, 0, 0, 0, 0)));
  return _mm_and_si128(_mm_add_epi32(_mm_add_epi32(_mm_set1_epi32(kRamp0), k), f), keep);
}

// map_row_colours's vector steps eight cells at a time on AVX2, the same operations in the same
// order: a full map's 137,000 cells in 0.125 against 0.20 to 0.22 ms with SSE2 (fastest of 200, pinned).
// Returns the cells done.
__attribute__((target("avx2"))) int row_colours_avx2(const double* v, int n, double lo, double span,
                                                     std::uint8_t* out) {
  const __m256d lo4 = _mm256_set1_pd(lo), span4 = _mm256_set1_pd(span);
  int c = 0;
  for (; c + 8 <= n; c += 8) {
    const __m128i words = _mm_packs_epi32(four_colours(v + c, lo4, span4), four_colours(v + c + 4, lo4, span4));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + c), _mm_packus_epi16(words, words));
  }
  return c;
}
#endif

// With SSE2, four cells a step with the same operations in the same order as ramp_index, so the
// same bytes (test: MapImage.RowColoursEqualTheScalarRamp); the scalar loop took 0.5 ms of a full
// map's 137,000 cells (its clamps are branches). AVX2 first where the processor has it.
void map_row_colours(const double* v, int n, double lo, double span, std::uint8_t* out) {
  int c = 0;
#if defined(__x86_64__)
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) c = row_colours_avx2(v, n, lo, span, out);
#endif
#if defined(__SSE2__)
  const __m128d lo2 = _mm_set1_pd(lo), span2 = _mm_set1_pd(span), zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  const __m128d top = _mm_set1_pd(kRampSize - 1), two = _mm_set1_pd(2.0);
  const __m128d largest = _mm_set1_pd(std::numeric_limits<double>::max());
  const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  const __m128i ramp0 = _mm_set1_epi32(kRamp0);
  // Two cells' indices as int32 in the low lanes; 0 (kWhite) where a value is not finite.
  auto pair = [&](const double* p) {
    const __m128d x = _mm_loadu_pd(p);
    const __m128d finite = _mm_cmple_pd(_mm_and_pd(x, magnitude), largest);  // false for NaN and inf
    const __m128d y =
        _mm_mul_pd(_mm_min_pd(_mm_max_pd(_mm_div_pd(_mm_sub_pd(_mm_and_pd(finite, x), lo2), span2), zero), one), top);
    const __m128i k = _mm_cvttpd_epi32(y);
    const __m128i f = _mm_cvttpd_epi32(_mm_mul_pd(two, _mm_sub_pd(y, _mm_cvtepi32_pd(k))));
    const __m128i keep = _mm_shuffle_epi32(_mm_castpd_si128(finite), _MM_SHUFFLE(3, 3, 2, 0));
    return _mm_and_si128(_mm_add_epi32(_mm_add_epi32(ramp0, k), f), keep);
  };
  for (; c + 4 <= n; c += 4) {
    const __m128i four = _mm_unpacklo_epi64(pair(v + c), pair(v + c + 2));
    const __m128i bytes = _mm_packus_epi16(_mm_packs_epi32(four, four), _mm_setzero_si128());
    const int packed = _mm_cvtsi128_si32(bytes);
    std::memcpy(out + c, &packed, 4);
  }
#endif
  for (; c < n; ++c) out[c] = std::isfinite(v[c]) ? ramp_index(v[c], lo, span) : kWhite;
}

namespace {

// The k-th smallest (from 0) of v, v reordered.
float kth_smallest(std::vector<float>& v, std::size_t k) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// How many cells of a row have a finite |a - b| (in single precision), how many of those lie below
// t and how many equal it; those above it are appended to `above`.
struct Split {
  std::size_t finite = 0, below = 0, equal = 0;
};
void split_row(const double* a, const double* b, std::size_t n, float t, Split& s, std::vector<float>& above) {
  std::size_t c = 0;
#if defined(__SSE2__)
  const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  const __m128d largest = _mm_set1_pd(std::numeric_limits<double>::max());
  const __m128 t4 = _mm_set1_ps(t);
  __m128i fin = _mm_setzero_si128(), lt = _mm_setzero_si128(), eq = _mm_setzero_si128();  // minus the counts
  alignas(16) float e4[4];
  for (; c + 4 <= n; c += 4) {
    const __m128d lo = _mm_and_pd(_mm_sub_pd(_mm_loadu_pd(a + c), _mm_loadu_pd(b + c)), magnitude);
    const __m128d hi = _mm_and_pd(_mm_sub_pd(_mm_loadu_pd(a + c + 2), _mm_loadu_pd(b + c + 2)), magnitude);
    // Not finite -> NaN, which is neither below, equal to nor above t.
    const __m128 e = _mm_movelh_ps(_mm_cvtpd_ps(_mm_or_pd(lo, _mm_cmpnle_pd(lo, largest))),
                                   _mm_cvtpd_ps(_mm_or_pd(hi, _mm_cmpnle_pd(hi, largest))));
    fin = _mm_sub_epi32(fin, _mm_castps_si128(_mm_cmpord_ps(e, e)));
    lt = _mm_sub_epi32(lt, _mm_castps_si128(_mm_cmplt_ps(e, t4)));
    eq = _mm_sub_epi32(eq, _mm_castps_si128(_mm_cmpeq_ps(e, t4)));
    if (const int gt = _mm_movemask_ps(_mm_cmpgt_ps(e, t4)); gt != 0) {
      _mm_store_ps(e4, e);
      for (int m = gt; m != 0; m &= m - 1) above.push_back(e4[__builtin_ctz(static_cast<unsigned>(m))]);
    }
  }
  alignas(16) std::int32_t f[4], l[4], q[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(f), fin);
  _mm_store_si128(reinterpret_cast<__m128i*>(l), lt);
  _mm_store_si128(reinterpret_cast<__m128i*>(q), eq);
  s.finite += static_cast<std::size_t>(f[0]) + static_cast<std::size_t>(f[1]) + static_cast<std::size_t>(f[2]) +
              static_cast<std::size_t>(f[3]);
  s.below += static_cast<std::size_t>(l[0]) + static_cast<std::size_t>(l[1]) + static_cast<std::size_t>(l[2]) +
             static_cast<std::size_t>(l[3]);
  s.equal += static_cast<std::size_t>(q[0]) + static_cast<std::size_t>(q[1]) + static_cast<std::size_t>(q[2]) +
             static_cast<std::size_t>(q[3]);
#endif
  for (; c < n; ++c) {
    const double d = std::fabs(a[c] - b[c]);
    if (!std::isfinite(d)) continue;
    const auto e = static_cast<float>(d);
    ++s.finite;
    s.below += e < t;
    s.equal += e == t;
    if (e > t) above.push_back(e);
  }
}

// A value of the cells' |a - b| with, where q is the 99th percentile of a map's errors, a few
// percent of the values above it: from every kStride-th finite one, the element 4 standard
// deviations of its rank below q. False when the map is small or the rank falls below 0.
constexpr std::size_t kStride = 32;
bool sample_threshold(MatrixRows a, MatrixRows b, double q, float& t) {
  std::vector<float> sample;
  for (std::size_t r = 0, at = 0; r < a.size() && r < b.size(); ++r) {
    const std::size_t n = std::min(a[r].size(), b[r].size());
    for (; at < n; at += kStride)
      if (const double d = std::fabs(a[r][at] - b[r][at]); std::isfinite(d)) sample.push_back(static_cast<float>(d));
    at -= n;  // the stride runs on across rows
  }
  const double m = static_cast<double>(sample.size());
  const double rank = q * (m - 1) - 4 * std::sqrt(m * q * (1 - q)) - 1;
  if (sample.size() < 64 || rank < 0) return false;
  t = kth_smallest(sample, static_cast<std::size_t>(rank));
  return true;
}

}  // namespace

// The element of rank k among the finite |a - b|, without storing them all: a sampled threshold t
// (sample_threshold), then one pass (split_row) counting the values below t and equal to it and
// keeping those above. The element is t, or the (k - below - equal)-th of those above; unless k is
// below t (the sample misled) or the map is small, when every value is stored and ordered. Errors of
// a quantised centre tie: on a full plane map 20% of them equal the threshold. Exact either way
// (test: MapImage.DifferenceQuantileOfAFullMapIsTheKthSmallest). A full map, fastest of 300
// (pinned): 0.23 ms, against 0.28 ms storing every value first and splitting those; what is left is
// reading the two maps (2.2 MB).
double abs_difference_quantile(MatrixRows a, MatrixRows b, double q) {
  const auto split_maps = [&](float t, std::vector<float>& above) {
    Split s;
    for (std::size_t r = 0; r < a.size() && r < b.size(); ++r)
      split_row(a[r].data(), b[r].data(), std::min(a[r].size(), b[r].size()), t, s, above);
    return s;
  };
  const std::size_t cells = a.size() * (a.empty() ? 0 : a[0].size());
  std::vector<float> above;
  float t = 0;
  if (sample_threshold(a, b, q, t)) {
    above.reserve(cells / 16);
    const Split s = split_maps(t, above);
    if (s.finite == 0) return -1;
    const auto k = static_cast<std::size_t>(q * static_cast<double>(s.finite - 1));
    if (k >= s.below && k < s.below + s.equal) return t;
    if (k >= s.below + s.equal) return kth_smallest(above, k - s.below - s.equal);
    above.clear();
  }
  // Every finite value lies above -1: all of them are kept and ordered.
  above.reserve(cells);
  const Split s = split_maps(-1.0F, above);
  if (s.finite == 0) return -1;
  return kth_smallest(above, static_cast<std::size_t>(q * static_cast<double>(s.finite - 1)));
}

struct MapImageWriter::Buffers {
  IndexedImage image{1, 1};
  std::vector<double> values;  // one map row
  std::string png;
};

namespace {

// Where everything goes in the image of a rows x cols map: one cell an s x s square, the map
// W x H px at (left, top), the colour bar at bar_x, the whole width x height.
struct Layout {
  int s = 1, W = 1, H = 1, decimals = 0, left = 0, bar_x = 0, width = 1, top = 0, bottom = 0;
  std::size_t clabel = 1;          // the longest colour-bar value, characters
  std::vector<double> cticks, yt;  // colour-bar and row ticks
  std::vector<std::string> title;  // its lines
  int height() const { return top + H + bottom; }
};

Layout layout(int rows, int cols, const MapImageSpec& spec) {
  Layout L;
  L.s = std::clamp(400 / std::max({cols, rows, 1}), 1, 8);
  L.W = std::max(cols, 1) * L.s, L.H = std::max(rows, 1) * L.s;
  const double span = std::max(spec.hi - spec.lo, 1e-300);
  L.decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(span / 5))), 0, 9);
  L.cticks = ticks(spec.lo, spec.hi, 5);
  for (double v : L.cticks) L.clabel = std::max(L.clabel, fmt::format("{:.{}f}", v, L.decimals).size());
  L.yt = ticks(spec.first_row, spec.first_row + std::max(rows - 1, 0), 8);
  L.left = 12 + kLine + 10 + static_cast<int>(std::to_string(spec.first_row + rows).size() + 1) * kAdvance;
  L.bar_x = L.left + L.W + 20;
  const int right = 20 + 20 + 8 + static_cast<int>(L.clabel) * kAdvance + 10 + kLine + 12;
  L.width = L.left + L.W + right;
  L.title = wrap(ascii(spec.title), static_cast<std::size_t>((L.width - 24) / kAdvance));
  L.top = 12 + static_cast<int>(L.title.size()) * (kLine + 4) + 8, L.bottom = 8 + kLine + 10 + kLine + 10;
  return L;
}

}  // namespace

MapImageWriter::MapImageWriter() : b_(std::make_unique<Buffers>()) {}
MapImageWriter::~MapImageWriter() = default;

void MapImageWriter::reserve(int rows, int cols, const MapImageSpec& spec) {
  const Layout L = layout(rows, cols, spec);
  // Colour-bar values up to 12 characters longer than those of spec's range, and three title lines.
  const std::size_t width = static_cast<std::size_t>(L.width + 12 * kAdvance) + 1;
  const std::size_t pixels = width * static_cast<std::size_t>(L.height() + 3 * (kLine + 4));
  b_->image.scanlines.reserve(pixels);
  b_->values.reserve(static_cast<std::size_t>(std::max(cols, 1)));
  b_->png.reserve(pixels + pixels / 8 + 4096);  // encode_png's worst case: 9 bits a byte, the chunks
}

void MapImageWriter::write(const std::string& path, int rows, int cols,
                           const std::function<void(int, double*)>& row_values, const MapImageSpec& spec) {
  const Layout L = layout(rows, cols, spec);
  const int s = L.s, W = L.W, H = L.H, decimals = L.decimals, left = L.left, bar_x = L.bar_x, top = L.top;
  const double span = std::max(spec.hi - spec.lo, 1e-300);
  const std::size_t clabel = L.clabel;
  const std::vector<double>& cticks = L.cticks;
  const std::vector<double>& yt = L.yt;
  const std::vector<std::string>& title = L.title;
  IndexedImage& im = b_->image;
  im.reset(L.width, L.height());
  im.palette[kWhite] = {255, 255, 255};
  im.palette[kBlack] = {0, 0, 0};
  if (spec.palette == MapPalette::Viridis)
    set_ramp(im, kViridis);
  else
    set_ramp(im, kDiverging);
  auto colour = [&](double v) { return ramp_index(v, spec.lo, span); };
  Canvas cv(im);
  // The map, row 0 at the bottom.
  std::vector<double>& vals = b_->values;
  vals.assign(static_cast<std::size_t>(std::max(cols, 1)), NAN);
  for (int r = 0; r < rows; ++r) {
    // One scanline of the row's squares, copied to its s lines.
    std::uint8_t* line = im.row(top + H - (r + 1) * s) + left;
    row_values(r, vals.data());
    if (s == 1) {
      map_row_colours(vals.data(), cols, spec.lo, span, line);
    } else {
      for (int c = 0; c < cols; ++c) {
        const double v = vals[static_cast<std::size_t>(c)];
        if (std::isfinite(v)) std::fill_n(line + c * s, s, colour(v));
      }
    }
    for (int j = 1; j < s; ++j) std::copy_n(line, W, im.row(top + H - (r + 1) * s + j) + left);
  }
  // Frame, ticks and their values.
  cv.fill(left - 1, top - 1, W + 2, 1, kBlack);
  cv.fill(left - 1, top + H, W + 2, 1, kBlack);
  cv.fill(left - 1, top - 1, 1, H + 2, kBlack);
  cv.fill(left + W, top - 1, 1, H + 2, kBlack);
  for (double v : ticks(0, std::max(cols - 1, 0), 8)) {
    const int x = left + static_cast<int>(v) * s + s / 2;
    const std::string t = fmt::format("{:.0f}", v);
    cv.fill(x, top + H + 1, 1, 5, kBlack);
    cv.text(x - cv.text_width(t) / 2, top + H + 8, t);
  }
  for (double v : yt) {
    const int y = top + H - (static_cast<int>(v) - spec.first_row) * s - s / 2 - 1;
    const std::string t = fmt::format("{:.0f}", v);
    cv.fill(left - 6, y, 5, 1, kBlack);
    cv.text(left - 10 - cv.text_width(t), y - kLine / 2, t);
  }
  // Colour bar with its values.
  for (int y = 0; y < H; ++y) cv.fill(bar_x, top + y, 20, 1, colour(spec.hi - span * (y + 0.5) / H));
  cv.fill(bar_x - 1, top - 1, 22, 1, kBlack);
  cv.fill(bar_x - 1, top + H, 22, 1, kBlack);
  cv.fill(bar_x - 1, top - 1, 1, H + 2, kBlack);
  cv.fill(bar_x + 20, top - 1, 1, H + 2, kBlack);
  for (double v : cticks) {
    const int y = top + static_cast<int>(std::lround((spec.hi - v) / span * (H - 1)));
    cv.fill(bar_x + 21, y, 5, 1, kBlack);
    cv.text(bar_x + 28, y - kLine / 2, fmt::format("{:.{}f}", v, decimals));
  }
  // Title and labels.
  for (std::size_t n = 0; n < title.size(); ++n)
    cv.text(std::max(12, (im.width - cv.text_width(title[n])) / 2), 12 + static_cast<int>(n) * (kLine + 4), title[n]);
  const std::string xl = fit(spec.x_label, static_cast<std::size_t>(std::max(1, W / kAdvance)));
  cv.text(left + (W - cv.text_width(xl)) / 2, top + H + 8 + kLine + 10, xl);
  const std::string yl = fit(spec.y_label, static_cast<std::size_t>(std::max(1, H / kAdvance)));
  cv.text_up(12, top + (H + cv.text_width(yl)) / 2, yl);
  const std::string cl = fit(spec.colour_label, static_cast<std::size_t>(std::max(1, H / kAdvance)));
  cv.text_up(bar_x + 28 + static_cast<int>(clabel) * kAdvance + 10, top + (H + cv.text_width(cl)) / 2, cl);
  encode_png(im, b_->png);
  write_file(path, b_->png);
}

}  // namespace rangesim::app
