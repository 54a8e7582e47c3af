#pragma once
// The scoreboard of every co-simulation target: collects mismatches into a CosimReport as
// readable records (the first kKeptMismatches kept, all counted) and, given a message type,
// also reports them as SC_ERRORs (display only, so a run goes on and reports everything); plus
// the Verilator context setup and the report closing every target repeats.
#include <verilated.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <systemc>
#include <utility>

#include "tb/common/cosim_target.h"

namespace rangesim::tb {

class CosimScoreboard {
 public:
  // msg_type nullptr: mismatches are only recorded (sc_errors stays the count of other errors).
  explicit CosimScoreboard(CosimReport& report, const char* msg_type = nullptr) : r_(report), type_(msg_type) {
    if (type_) sc_core::sc_report_handler::set_actions(type_, sc_core::SC_ERROR, sc_core::SC_DISPLAY);
  }

  // One compared transaction (counted); a mismatch if expected != actual.
  template <class T>
  bool expect(const char* check, long long frame, long long row, long long column, std::uint64_t cycle,
              const T& expected, const T& actual) {
    count(check);
    if (expected == actual) return true;
    mismatch(check, frame, row, column, cycle, to_text(expected), to_text(actual));
    return false;
  }
  // Per-cycle pin comparison: not a transaction, but a mismatch like one.
  template <class T>
  bool pin(const char* name, long long frame, std::uint64_t cycle, const T& expected, const T& actual) {
    if (expected == actual) return true;
    mismatch(name, frame, -1, -1, cycle, to_text(expected), to_text(actual));
    return false;
  }

  // Transactions a harness compared itself (its mismatches come through add()).
  void count(const std::string& check, std::uint64_t n = 1) {
    r_.transactions += n;
    r_.checks[check].transactions += n;
  }

  void mismatch(const std::string& check, long long frame, long long row, long long column, std::uint64_t cycle,
                const std::string& expected, const std::string& actual) {
    add({check, frame, row, column, cycle, expected, actual});
  }
  void add(CosimMismatch m) {
    ++r_.mismatches;
    ++r_.checks[m.check].mismatches;
    if (r_.first_mismatches.size() >= kKeptMismatches) return;
    r_.first_mismatches.push_back(std::move(m));
    if (!type_) return;
    const std::string text = format(r_.first_mismatches.back());
    SC_REPORT_ERROR(type_, text.c_str());
  }

  static std::string format(const CosimMismatch& m) {
    std::ostringstream s;
    if (m.frame >= 0) s << "frame " << m.frame << " ";
    if (m.row >= 0) s << "row " << m.row << " ";
    if (m.column >= 0) s << "column " << m.column << " ";
    s << "cycle " << m.cycle << ": " << m.check << " expected " << m.expected << " got " << m.actual;
    return s.str();
  }

 private:
  template <class T>
  static std::string to_text(const T& v) {
    std::ostringstream s;
    s << v;
    return s.str();
  }
  CosimReport& r_;
  const char* type_;
};

// Verilator context for one co-simulation run: random initial state (the reset must clear
// everything that matters), seeded; failing assertions are counted, not fatal.
inline VerilatedContext* cosim_verilator_context(std::uint64_t seed, const std::string& trace_path) {
  VerilatedContext* ctx = Verilated::defaultContextp();
  ctx->randReset(2);
  ctx->randSeed(static_cast<int>(seed & 0x7fffffff));
  ctx->fatalOnError(false);
  if (!trace_path.empty()) ctx->traceEverOn(true);
  return ctx;
}
inline VerilatedContext* cosim_verilator_context(const CosimOptions& o) {
  return cosim_verilator_context(o.seed, o.trace_path);
}

// The mismatch recorded when a Verilog assertion fired (Verilator counts, not names, them).
inline CosimMismatch rtl_assertion_mismatch(std::uint64_t cycle) {
  return {"rtl_assertion",
          -1,
          -1,
          -1,
          cycle,
          "no assertion fails",
          "a Verilog assertion fired (its $error message names it)"};
}

// Closes a report: SC errors and whether a Verilog assertion fired (counted as a mismatch).
inline void finish_cosim_report(CosimReport& r, VerilatedContext* ctx) {
  r.rtl_assertions_failed = ctx->gotError() ? 1 : 0;
  r.mismatches += static_cast<std::uint64_t>(r.rtl_assertions_failed);
  r.sc_errors = static_cast<int>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
}

}  // namespace rangesim::tb
