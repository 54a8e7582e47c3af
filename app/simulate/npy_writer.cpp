#include "app/simulate/npy_writer.h"

#include <fcntl.h>
#include <limits.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
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

std::string matrix_header(MatrixRows rows, std::size_t columns) {
  for (const auto& r : rows)
    if (r.size() != columns) throw std::logic_error("npy_matrix: ragged rows");
  return header("'<f8'", "(" + std::to_string(rows.size()) + ", " + std::to_string(columns) + ")");
}

using Kind = systemc::Table::Kind;

const char* npy_type(Kind k) {
  switch (k) {
    case Kind::Integer: return "<i8";
    case Kind::Index: return "<i4";
    case Kind::Flag: return "|b1";
    case Kind::Real: break;
  }
  return "<f8";
}

std::size_t cell_bytes(Kind k) { return k == Kind::Flag ? 1 : k == Kind::Index ? 4 : 8; }

std::string table_header(const systemc::Table& t) {
  std::string descr = "[";
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    descr += (c ? ", ('" : "('") + t.columns[c].name + "', '" + npy_type(t.columns[c].kind) + "')";
  descr += "]";
  return header(descr, "(" + std::to_string(t.rows()) + ",)");
}

std::size_t record_bytes(const systemc::Table& t) {
  std::size_t n = 0;
  for (const auto& c : t.columns) n += cell_bytes(c.kind);
  return n;
}

// One cell of kind `k` as its record bytes at `p`; returns the bytes written. An Index outside
// int32 is a bug in the run that declared it (a logic_error: the staged output is discarded).
std::size_t put_cell(Kind k, double v, char* p) {
  switch (k) {
    case Kind::Real: std::memcpy(p, &v, 8); return 8;
    case Kind::Integer: {
      const auto i = static_cast<std::int64_t>(v);
      std::memcpy(p, &i, 8);
      return 8;
    }
    case Kind::Index: {
      if (!(std::fabs(v) < 2147483648.0)) throw std::logic_error("npy_table: an index column's value outside int32");
      const auto i = static_cast<std::int32_t>(v);
      std::memcpy(p, &i, 4);
      return 4;
    }
    case Kind::Flag: *p = v != 0 ? 1 : 0; return 1;
  }
  return 0;
}

// n whole rows of `t`'s cells (row-major) as packed records at `p`.
void table_bytes(const systemc::Table& t, const double* cells, std::size_t n, char* p) {
  const std::size_t C = t.columns.size();
  for (std::size_t r = 0; r < n; ++r, cells += C)
    for (std::size_t c = 0; c < C; ++c) p += put_cell(t.columns[c].kind, cells[c], p);
}

// A file written in calls of 64 KB or more: in 4 KB ones (stdio's default here; a map's rows are
// 3 KB) the file system's work per call cost several times the copying (9.3 against 2.5 ms for
// 9.6 MB, measured). Small pieces gather in a 256 KB buffer; a large one goes out as it is (stdio
// would copy it into its buffer first).
//
// A file of 2 MB or more has its blocks reserved in one call before the writes (`bytes`, the size
// it will have): without it ext4 reserves and maps them page by page as the writes arrive (9.6 MB
// written in 256 KB calls and renamed over the previous file: 3.6 and 4.2 against 2.7 and 3.1 ms
// of CPU, medians of 15 in two runs, measured). Reserved blocks are real ones, which cost more to
// free when the next run replaces the file; below about 2 MB that outweighs the gain (writing and
// replacing a 1.1 MB map: 0.77 to 0.81 ms without, 0.87 to 0.92 ms with; 4.4 MB: 2.62 to 2.68
// against 2.38 to 2.43 ms; medians of 37, measured). The reservation does not change the file's
// size, so a file written short shows no zeros; where the file system cannot reserve, the writes
// go on without it.
class File {
 public:
  File(const std::string& path, std::size_t bytes)
      : path_(path), fd_(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666)) {
    if (fd_ < 0) fail();
    buffer_.reserve(kBuffer);
    if (bytes >= kReserveFrom) (void)::fallocate(fd_, FALLOC_FL_KEEP_SIZE, 0, static_cast<off_t>(bytes));
  }
  ~File() {
    if (fd_ >= 0) ::close(fd_);
  }
  void put(const void* data, std::size_t n) {
    const char* c = static_cast<const char*>(data);
    if (n >= kDirect) {
      flush();  // what came before goes first
      write_all(c, n);
      return;
    }
    if (buffer_.size() + n > kBuffer) flush();
    buffer_.insert(buffer_.end(), c, c + n);
  }
  // Pieces that stay where they are (a matrix's rows), in as few calls as the system takes
  // (writev, IOV_MAX pieces a call), after what was buffered.
  void put_pieces(std::vector<iovec> pieces) {
    flush();
    for (std::size_t at = 0; at < pieces.size();) {
      const int count = static_cast<int>(std::min<std::size_t>(pieces.size() - at, IOV_MAX));
      ssize_t w = ::writev(fd_, &pieces[at], count);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) fail();
      for (; at < pieces.size() && static_cast<std::size_t>(w) >= pieces[at].iov_len; ++at)
        w -= static_cast<ssize_t>(pieces[at].iov_len);
      if (at < pieces.size()) {  // a piece written in part
        pieces[at].iov_base = static_cast<char*>(pieces[at].iov_base) + w;
        pieces[at].iov_len -= static_cast<std::size_t>(w);
      }
    }
  }
  void close() {
    flush();
    const int rc = ::close(fd_);
    fd_ = -1;
    if (rc != 0) fail();
  }

 private:
  static constexpr std::size_t kBuffer = std::size_t{1} << 18, kDirect = std::size_t{1} << 16,
                               kReserveFrom = std::size_t{1} << 21;
  void flush() {
    write_all(buffer_.data(), buffer_.size());
    buffer_.clear();
  }
  void write_all(const char* p, std::size_t n) {
    while (n > 0) {
      const ssize_t w = ::write(fd_, p, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) fail();
      p += w;
      n -= static_cast<std::size_t>(w);
    }
  }
  [[noreturn]] void fail() const { throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno)); }
  std::string path_;
  int fd_;
  std::vector<char> buffer_;
};

}  // namespace

void write_npy_matrix(const std::string& path, MatrixRows rows, std::size_t columns) {
  const std::string h = matrix_header(rows, columns);
  File f(path, h.size() + rows.size() * columns * 8);
  f.put(h.data(), h.size());
  // The rows from where they are: through the buffer they were copied once more. A full map's
  // 1.1 MB inside `simulate` (the job's CPU, medians of 15 runs, several runs): 0.51 to 0.61 ms
  // through the buffer, 0.37 to 0.48 ms without.
  std::vector<iovec> pieces;
  pieces.reserve(rows.size());
  for (const auto& r : rows)
    if (columns > 0) pieces.push_back({const_cast<double*>(r.data()), columns * 8});
  f.put_pieces(std::move(pieces));
  f.close();
}

void write_npy_table(const std::string& path, const systemc::Table& t) {
  const std::string h = table_header(t);
  const std::size_t R = record_bytes(t);
  File f(path, h.size() + t.rows() * R);
  f.put(h.data(), h.size());
  // Whole rows at a time, about 256 KB of cells (180 KB of records for 13 columns) a piece: the
  // converted records never exist whole in memory.
  const std::size_t C = std::max<std::size_t>(t.columns.size(), 1), chunk_rows = std::max<std::size_t>(32768 / C, 1);
  std::vector<char> buf(chunk_rows * R);
  std::size_t written = 0;
  t.for_each_block([&](const double* cells, std::size_t rows) {
    for (std::size_t r = 0; r < rows; r += chunk_rows) {
      const std::size_t n = std::min(chunk_rows, rows - r);
      table_bytes(t, cells + r * C, n, buf.data());
      f.put(buf.data(), n * R);
    }
    written += rows;
  });
  if (written != t.rows()) throw std::logic_error("npy_table: the table produced a different number of rows");
  f.close();
}

}  // namespace rangesim::app
