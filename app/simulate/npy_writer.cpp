#include "app/simulate/npy_writer.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace rangesim::app {

namespace {

static_assert(sizeof(double) == 8 && sizeof(std::int64_t) == 8, "npy: 8-byte cells");
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "npy_writer writes the host's bytes and declares them little-endian ('<')"
#endif

// Magic, version 1.0, header length, then the header dict padded with spaces and ended by '\n' so
// that the data starts on a 64-byte boundary (what numpy itself writes; v1.0 asks for 16).
std::string header(const std::string& descr, const std::string& shape) {
  std::string dict = "{'descr': " + descr + ", 'fortran_order': False, 'shape': " + shape + ", }";
  const std::size_t prefix = 10;  // magic (6) + version (2) + length (2)
  std::size_t total = prefix + dict.size() + 1;
  total = (total + 63) / 64 * 64;
  const std::size_t len = total - prefix;
  if (len > 65535) throw std::runtime_error("npy: header too long for format 1.0");
  dict.append(len - dict.size() - 1, ' ');
  dict += '\n';
  std::string h("\x93NUMPY\x01\x00", 8);
  h += static_cast<char>(len & 0xff);
  h += static_cast<char>(len >> 8);
  return h + dict;
}

}  // namespace

std::string npy_matrix(const std::vector<std::vector<double>>& rows, std::size_t columns) {
  std::string out = header("'<f8'", "(" + std::to_string(rows.size()) + ", " + std::to_string(columns) + ")");
  const std::size_t at = out.size();
  out.resize(at + rows.size() * columns * 8);
  char* p = out.data() + at;
  for (const auto& r : rows) {
    if (r.size() != columns) throw std::logic_error("npy_matrix: ragged rows");
    std::memcpy(p, r.data(), columns * 8);
    p += columns * 8;
  }
  return out;
}

std::string npy_table(const systemc::Table& t) {
  std::string descr = "[";
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    descr += (c ? ", ('" : "('") + t.columns[c].name + (t.columns[c].integer ? "', '<i8')" : "', '<f8')");
  descr += "]";
  std::string out = header(descr, "(" + std::to_string(t.rows()) + ",)");
  const std::size_t at = out.size(), C = t.columns.size();
  out.resize(at + t.cells.size() * 8);
  char* p = out.data() + at;
  for (std::size_t i = 0; i < t.cells.size(); ++i, p += 8) {
    if (t.columns[i % C].integer) {
      const auto v = static_cast<std::int64_t>(t.cells[i]);
      std::memcpy(p, &v, 8);
    } else {
      std::memcpy(p, &t.cells[i], 8);
    }
  }
  return out;
}

}  // namespace rangesim::app
