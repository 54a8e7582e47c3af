#include "scene/depth_map.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fmt/format.h>

#include "core/input_file.h"
#include "core/user_error.h"

namespace rangesim::scene {

namespace {

// Header tokens of a PNM file: whitespace separated, '#' comments to end of line. Leaves `pos`
// on the single whitespace byte that ends the last token (the raster starts after it).
struct HeaderReader {
  const std::string& data;
  std::size_t pos = 0;
  std::string token() {
    for (;;) {
      while (pos < data.size() && std::isspace(static_cast<unsigned char>(data[pos]))) ++pos;
      if (pos < data.size() && data[pos] == '#') {
        while (pos < data.size() && data[pos] != '\n') ++pos;
        continue;
      }
      break;
    }
    const std::size_t start = pos;
    while (pos < data.size() && !std::isspace(static_cast<unsigned char>(data[pos]))) ++pos;
    return data.substr(start, pos - start);
  }
  long long number(const std::string& what, const std::string& where, long long lo, long long hi) {
    const std::string t = token();
    char* end = nullptr;
    const long long v = std::strtoll(t.c_str(), &end, 10);
    if (t.empty() || *end != '\0' || v < lo || v > hi)
      throw UserError(
          fmt::format("{}: image header {} = '{}'; allowed an integer in [{}, {}]", where, what, t, lo, hi));
    return v;
  }
};

constexpr long long kMaxSide = 16384;  // image side limit: keeps a bad header from allocating gigabytes
constexpr std::uintmax_t kMaxFileBytes = 4ull * kMaxSide * kMaxSide + 4096;  // the largest PFM plus a header

}  // namespace

double DepthMap::sample(int row, int column, int rows, int columns) const {
  // Pixel centre -> continuous image coordinate (image pixel centres at integer + 0.5).
  const double x = (column + 0.5) * width / columns - 0.5;
  const double y = (row + 0.5) * height / rows - 0.5;
  const double xc = std::clamp(x, 0.0, static_cast<double>(width - 1));
  const double yc = std::clamp(y, 0.0, static_cast<double>(height - 1));
  const int x0 = std::min(static_cast<int>(xc), width - 1), y0 = std::min(static_cast<int>(yc), height - 1);
  const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
  const double fx = xc - x0, fy = yc - y0;
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

std::vector<double> DepthMap::resample(int rows, int columns) const {
  std::vector<double> out(static_cast<std::size_t>(rows) * columns);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) out[static_cast<std::size_t>(r) * columns + c] = sample(r, c, rows, columns);
  return out;
}

DepthMap load_depth_map(const std::string& path, const std::string& key, double near_m, double far_m, double min_m,
                        double max_m) {
  const std::string where = fmt::format("{} ({})", key, path);
  // A regular file of bounded size only: /dev/zero, a FIFO or a directory would hang or exhaust
  // memory before any header check could run.
  const std::string data = read_input_file(path, "the depth-map image", kMaxFileBytes, where);
  return parse_depth_map(data, path, key, near_m, far_m, min_m, max_m);
}

DepthMap parse_depth_map(std::string_view bytes, const std::string& path, const std::string& key, double near_m,
                         double far_m, double min_m, double max_m) {
  const std::string where = fmt::format("{} ({})", key, path);
  const std::string data(bytes);
  HeaderReader h{data};
  const std::string magic = h.token();
  DepthMap m;
  m.file = path;
  if (magic == "P2" || magic == "P5") {
    m.width = static_cast<int>(h.number("width", where, 1, kMaxSide));
    m.height = static_cast<int>(h.number("height", where, 1, kMaxSide));
    const long long maxval = h.number("maxval", where, 1, 65535);
    const std::size_t n = static_cast<std::size_t>(m.width) * m.height;
    // Allocate only what the data can hold (a header alone must not reserve gigabytes).
    const std::size_t min_bytes = magic == "P2" ? 2 * n - 1 : n * (maxval > 255 ? 2 : 1);
    if (data.size() < h.pos || data.size() - h.pos < min_bytes)
      throw UserError(fmt::format("{}: PGM raster too short for {} x {} pixels", where, m.width, m.height));
    m.depth_m.resize(n);
    auto gray_to_m = [&](long long g) {
      return near_m + (far_m - near_m) * static_cast<double>(g) / static_cast<double>(maxval);
    };
    if (magic == "P2") {
      for (std::size_t i = 0; i < n; ++i) {
        const std::string t = h.token();
        char* end = nullptr;
        const long long g = std::strtoll(t.c_str(), &end, 10);
        if (t.empty()) throw UserError(fmt::format("{}: ASCII PGM ends after {} of {} gray levels", where, i, n));
        if (*end != '\0' || g < 0 || g > maxval)
          throw UserError(fmt::format("{}: gray level '{}' at pixel {}; allowed an integer in [0, {}] (maxval)", where,
                                      t, i, maxval));
        m.depth_m[i] = gray_to_m(g);
      }
    } else {
      const std::size_t bytes = maxval > 255 ? 2 : 1;
      const std::size_t start = h.pos + 1;  // one whitespace byte after maxval
      if (start > data.size() || data.size() - start < n * bytes)
        throw UserError(fmt::format("{}: binary PGM raster too short: {} bytes for {} x {} pixels of {} byte(s)", where,
                                    data.size() > start ? data.size() - start : 0, m.width, m.height, bytes));
      for (std::size_t i = 0; i < n; ++i) {
        const auto* p = reinterpret_cast<const unsigned char*>(data.data() + start + i * bytes);
        const long long g = bytes == 2 ? (p[0] << 8 | p[1]) : p[0];  // 16-bit PGM is big-endian
        if (g > maxval)
          throw UserError(fmt::format("{}: gray level {} at pixel {} exceeds maxval {}", where, g, i, maxval));
        m.depth_m[i] = gray_to_m(g);
      }
    }
  } else if (magic == "Pf") {
    m.width = static_cast<int>(h.number("width", where, 1, kMaxSide));
    m.height = static_cast<int>(h.number("height", where, 1, kMaxSide));
    const std::string st = h.token();
    char* end = nullptr;
    const double scale = std::strtod(st.c_str(), &end);
    if (st.empty() || *end != '\0' || scale == 0 || !std::isfinite(scale))
      throw UserError(fmt::format("{}: PFM scale '{}'; allowed a non-zero number (< 0: little-endian)", where, st));
    const std::size_t n = static_cast<std::size_t>(m.width) * m.height, start = h.pos + 1;
    if (start > data.size() || data.size() - start < n * 4)
      throw UserError(fmt::format("{}: PFM raster too short for {} x {} floats", where, m.width, m.height));
    const bool little = scale < 0;
    m.depth_m.resize(n);
    for (int y = 0; y < m.height; ++y)
      for (int x = 0; x < m.width; ++x) {
        unsigned char b[4];
        std::memcpy(b, data.data() + start + (static_cast<std::size_t>(y) * m.width + x) * 4, 4);
        const std::uint32_t u =
            little ? (std::uint32_t{b[3]} << 24 | std::uint32_t{b[2]} << 16 | std::uint32_t{b[1]} << 8 | b[0])
                   : (std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 | std::uint32_t{b[2]} << 8 | b[3]);
        float f;
        std::memcpy(&f, &u, 4);
        m.depth_m[static_cast<std::size_t>(m.height - 1 - y) * m.width + x] = f;  // PFM rows go bottom to top
      }
  } else {
    throw UserError(fmt::format("{}: not a depth-map image: magic '{}'; allowed PGM (P2, P5) or grayscale PFM (Pf)",
                                where, magic.substr(0, 8)));
  }
  for (std::size_t i = 0; i < m.depth_m.size(); ++i) {
    const double z = m.depth_m[i];
    if (!std::isfinite(z) || z < min_m || z > max_m)
      throw UserError(fmt::format("{}: distance {:g} m at pixel (x {}, y {}) is out of range; allowed [{:g}, {:g}] m",
                                  where, z, i % m.width, i / m.width, min_m, max_m));
  }
  return m;
}

}  // namespace rangesim::scene
