#include "app/simulate/map_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

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

struct MapImageWriter::Buffers {
  IndexedImage image{1, 1};
  std::vector<double> values;  // one map row
  std::string png;
};

MapImageWriter::MapImageWriter() : b_(std::make_unique<Buffers>()) {}
MapImageWriter::~MapImageWriter() = default;

void MapImageWriter::write(const std::string& path, int rows, int cols,
                           const std::function<void(int, double*)>& row_values, const MapImageSpec& spec) {
  const int s = std::clamp(400 / std::max({cols, rows, 1}), 1, 8);
  const int W = std::max(cols, 1) * s, H = std::max(rows, 1) * s;
  const double span = std::max(spec.hi - spec.lo, 1e-300);
  const int decimals = std::clamp(static_cast<int>(std::ceil(-std::log10(span / 5))), 0, 9);
  const std::vector<double> cticks = ticks(spec.lo, spec.hi, 5);
  std::size_t clabel = 1;
  for (double v : cticks) clabel = std::max(clabel, fmt::format("{:.{}f}", v, decimals).size());
  const std::vector<double> yt = ticks(spec.first_row, spec.first_row + std::max(rows - 1, 0), 8);
  const int left = 12 + kLine + 10 + static_cast<int>(std::to_string(spec.first_row + rows).size() + 1) * kAdvance;
  const int bar_x = left + W + 20, right = 20 + 20 + 8 + static_cast<int>(clabel) * kAdvance + 10 + kLine + 12;
  const int width = left + W + right;
  const std::vector<std::string> title = wrap(ascii(spec.title), static_cast<std::size_t>((width - 24) / kAdvance));
  const int top = 12 + static_cast<int>(title.size()) * (kLine + 4) + 8, bottom = 8 + kLine + 10 + kLine + 10;
  IndexedImage& im = b_->image;
  im.reset(width, top + H + bottom);
  im.palette[kWhite] = {255, 255, 255};
  im.palette[kBlack] = {0, 0, 0};
  if (spec.palette == MapPalette::Viridis)
    set_ramp(im, kViridis);
  else
    set_ramp(im, kDiverging);
  auto colour = [&](double v) {
    // x (kRampSize - 1) rounded half up, as std::lround does for x >= 0, without its library call
    // or a branch on the fraction (y - k is exact, and 2 (y - k) truncates to 1 from 0.5 on).
    const double y = std::min(std::max((v - spec.lo) / span, 0.0), 1.0) * (kRampSize - 1);
    const int k = static_cast<int>(y);
    return static_cast<std::uint8_t>(kRamp0 + k + static_cast<int>(2 * (y - k)));
  };
  Canvas cv(im);
  // The map, row 0 at the bottom.
  std::vector<double>& vals = b_->values;
  vals.assign(static_cast<std::size_t>(std::max(cols, 1)), NAN);
  for (int r = 0; r < rows; ++r) {
    // One scanline of the row's squares, copied to its s lines.
    std::uint8_t* line = im.row(top + H - (r + 1) * s) + left;
    row_values(r, vals.data());
    for (int c = 0; c < cols; ++c) {
      const double v = vals[static_cast<std::size_t>(c)];
      if (std::isfinite(v)) std::fill_n(line + c * s, s, colour(v));
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
