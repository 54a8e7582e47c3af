#pragma once
// Reading and writing verilated SystemC ports whatever their C++ type: Verilator picks bool
// (1 bit), uint32_t (2..32), uint64_t (33..64) or sc_bv<N> (wider) by width,
// so harnesses that serve several instances of one module go through these overloads.
#include <cstdint>
#include <string>
#include <systemc>
#include <type_traits>
#include <utility>
#include <vector>

namespace rangesim::tb {

// sc_in/sc_out<T>::data_type of a verilated port member.
template <class Port>
using PortData = typename std::decay_t<Port>::data_type;

inline std::uint64_t low_mask(int width) { return width >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << width) - 1; }

// Bits [lo, lo + width) of a port value (width <= 64).
inline std::uint64_t port_field(bool v, int lo, int width) { return lo == 0 && width >= 1 ? (v ? 1U : 0U) : 0U; }
inline std::uint64_t port_field(std::uint32_t v, int lo, int width) {
  return lo >= 32 ? 0 : (std::uint64_t{v} >> lo) & low_mask(width);
}
inline std::uint64_t port_field(std::uint64_t v, int lo, int width) {
  return lo >= 64 ? 0 : (v >> lo) & low_mask(width);
}
template <int W>
std::uint64_t port_field(const sc_dt::sc_bv<W>& v, int lo, int width) {
  std::uint64_t out = 0;
  for (int i = 0; i < width && lo + i < W; ++i) {
    const int b = lo + i;
    out |= static_cast<std::uint64_t>((v.get_word(b / 32) >> (b % 32)) & 1U) << i;
  }
  return out;
}
template <class T>
bool port_bit(const T& v, int bit) {
  return port_field(v, bit, 1) != 0;
}

// A port value from 32-bit words, bit i = words[i / 32] bit i % 32 (missing words are zero).
inline void port_from_words(const std::vector<std::uint32_t>& w, bool& v) { v = !w.empty() && (w[0] & 1U); }
inline void port_from_words(const std::vector<std::uint32_t>& w, std::uint32_t& v) { v = w.empty() ? 0 : w[0]; }
inline void port_from_words(const std::vector<std::uint32_t>& w, std::uint64_t& v) {
  v = (w.size() > 0 ? w[0] : 0) | (w.size() > 1 ? std::uint64_t{w[1]} << 32 : 0);
}
template <int W>
void port_from_words(const std::vector<std::uint32_t>& w, sc_dt::sc_bv<W>& v) {
  for (int i = 0; i < (W + 31) / 32; ++i)
    v.set_word(i, i < static_cast<int>(w.size()) ? w[static_cast<std::size_t>(i)] : 0U);
}

// `width` bits of a port as lower-case hex, zero-padded to ceil(width / 4) digits: the format of
// Verilog's %h, so the Icarus and Verilator dumps compare as text.
template <class T>
std::string port_hex(const T& v, int width) {
  static const char* digits = "0123456789abcdef";
  std::string s;
  for (int d = (width + 3) / 4 - 1; d >= 0; --d) {
    const int lo = 4 * d;
    s.push_back(digits[port_field(v, lo, width - lo < 4 ? width - lo : 4)]);
  }
  return s;
}

}  // namespace rangesim::tb
