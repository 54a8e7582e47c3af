#pragma once
// Journal of a sweep (evaluate --trials today; bench and cosim can use it the same way): every
// finished grid point is appended as one record, written with a single write() and fsync()ed, so
// a sweep killed at any instant (SIGKILL, power loss) keeps every point it finished. A restarted
// sweep (--resume) reads the records back and only computes the missing points; since the records
// hold the exact results (payloads are the caller's text, doubles as hex floats), the final output
// is byte-identical to an uninterrupted run.
//
// File format (text, one record per line):
//   rangesim-sweep-journal 1 <fingerprint hash, 16 hex digits>
//   <fingerprint, escaped to one line>
//   P <index> <payload length> <payload> <FNV-1a hash of "index payload", 16 hex digits>
// A last line cut short by a kill (no newline, wrong length or hash) is dropped on reading and
// truncated away before new records are appended.
#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include "app/run_control.h"

namespace rangesim::app {

class SweepJournal {
 public:
  // Opens `path` for the sweep described by `fingerprint` (the preset's resolved values and every
  // option that changes results). resume = false: a journal must not exist yet (UserError telling
  // to add `resume_flag` or remove it: never silently discards finished work); it is created.
  // resume = true: an existing journal is read back (UserError if its fingerprint differs, naming
  // the first differing line); a missing one starts empty.
  SweepJournal(const std::string& path, const std::string& fingerprint, bool resume,
               const std::string& resume_flag = "--resume");
  ~SweepJournal();
  SweepJournal(const SweepJournal&) = delete;
  SweepJournal& operator=(const SweepJournal&) = delete;

  // Records read back at opening (resume), by point index.
  const std::map<long long, std::string>& done() const { return done_; }
  // Appends one finished point (thread-safe); `payload` must not contain a newline.
  void append(long long index, const std::string& payload);
  // Deletes the journal file (after the sweep's output has been committed).
  void remove();

  const std::string& path() const { return path_; }
  static std::uint64_t hash(const std::string& text);  // FNV-1a 64

 private:
  std::string path_;
  int fd_ = -1;
  std::mutex mutex_;
  std::map<long long, std::string> done_;
};

// Ctrl-C (or SIGTERM, SIGHUP, a memory budget) during a sweep: app/run_control.h. The names the
// sweeps used before the other signals were handled the same way.
inline constexpr int kExitInterrupted = 130;
using SigintGuard = StopGuard;
inline std::atomic<bool>& sigint_flag() { return stop_flag(); }

}  // namespace rangesim::app
