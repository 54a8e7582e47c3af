#include "app/cli_checks.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <limits>

namespace rangesim::app {

namespace {

using Wide = __int128;

std::string wide_text(Wide v) {
  if (v == 0) return "0";
  const bool negative = v < 0;
  std::string s;
  for (; v != 0; v /= 10) s.insert(s.begin(), static_cast<char>('0' + static_cast<int>(negative ? -(v % 10) : v % 10)));
  return negative ? "-" + s : s;
}

// The integer `text` stands for; false when it is not one. Values far beyond 64 bits saturate
// (they are out of every range anyway).
bool parse_wide(const std::string& text, Wide& value) {
  std::size_t i = text[0] == '+' || text[0] == '-' ? 1 : 0;
  if (i < text.size() && text.find_first_not_of("0123456789", i) == std::string::npos) {
    const Wide cap = static_cast<Wide>(1) << 100;
    Wide v = 0;
    for (; i < text.size(); ++i) v = v > cap ? v : v * 10 + (text[i] - '0');
    value = text[0] == '-' ? -v : v;
    return true;
  }
  // 1e3, 2.0: a number whose value is an integer (exactly representable up to 2^53).
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (*end != '\0' || std::isspace(static_cast<unsigned char>(text[0])) || !std::isfinite(d) || d != std::floor(d))
    return false;
  if (std::fabs(d) > 0x1p100) {
    value = d < 0 ? -(static_cast<Wide>(1) << 100) : static_cast<Wide>(1) << 100;
    return true;
  }
  value = static_cast<Wide>(d);
  return true;
}

std::string check_wide(std::string& text, Wide lo, Wide hi) {
  const std::string range = fmt::format("allowed an integer in [{}, {}]", wide_text(lo), wide_text(hi));
  Wide v = 0;
  if (text.empty() || !parse_wide(text, v)) return fmt::format("'{}' is not an integer; {}", text, range);
  if (v < lo || v > hi) return fmt::format("{} is out of range; {}", text, range);
  text = wide_text(v);
  return "";
}

}  // namespace

std::string check_integer_text(std::string& text, long long lo, long long hi) { return check_wide(text, lo, hi); }

std::string check_unsigned_text(std::string& text, std::uint64_t lo, std::uint64_t hi) {
  return check_wide(text, static_cast<Wide>(lo), static_cast<Wide>(hi));
}

std::string check_real_text(const std::string& text, double lo, bool lo_exclusive, double hi, const std::string& unit) {
  const std::string range = fmt::format("allowed a number in {}{:g}, {:g}]{}", lo_exclusive ? "(" : "[", lo, hi,
                                        unit.empty() ? "" : " " + unit);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || std::isspace(static_cast<unsigned char>(text[0])))
    return fmt::format("'{}' is not a number; {}", text, range);
  if (!std::isfinite(v) || (lo_exclusive ? !(v > lo) : !(v >= lo)) || !(v <= hi))
    return fmt::format("{} is out of range; {}", text, range);
  return "";
}

std::string check_path_text(const std::string& text) {
  return text.empty() ? "the name is empty; allowed a file or directory name" : "";
}

std::string check_memory_text(const std::string& text, std::uint64_t& bytes) {
  constexpr double kMin = 16.0 * (1 << 20), kMax = 1024.0 * (1ull << 40);
  const std::string range = "allowed 16M .. 1024T (bytes, or a number with K, M, G or T, e.g. 512M, 1.5G)";
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  const std::string suffix = end ? std::string(end) : std::string();
  double scale = 0;
  if (suffix.empty())
    scale = 1;
  else if (suffix.size() == 1 || (suffix.size() == 2 && (suffix[1] == 'B' || suffix[1] == 'b')))
    switch (std::toupper(static_cast<unsigned char>(suffix[0]))) {
      case 'K': scale = 1024.0; break;
      case 'M': scale = 1024.0 * 1024; break;
      case 'G': scale = 1024.0 * 1024 * 1024; break;
      case 'T': scale = 1024.0 * 1024 * 1024 * 1024; break;
      default: break;
    }
  if (text.empty() || end == text.c_str() || scale == 0 || std::isspace(static_cast<unsigned char>(text[0])))
    return fmt::format("'{}' is not a memory size; {}", text, range);
  const double b = v * scale;
  if (!std::isfinite(b) || b < kMin || b > kMax) return fmt::format("{} is out of range; {}", text, range);
  bytes = static_cast<std::uint64_t>(b);
  return "";
}

}  // namespace rangesim::app
