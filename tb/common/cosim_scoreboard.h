#pragma once
// Scoreboard helpers shared by the tof-lockin / column ADC co-simulation targets
// (tb/lockin_gate_generator_cosim.cpp, tb/column_adc_cosim.cpp, tb/tof_lockin_cosim.cpp):
// collect mismatches into a CosimReport as readable records and count them as SC_ERRORs
// (display only, so a run goes on and reports everything), plus the Verilator context setup
// every target repeats.
#include <verilated.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <systemc>

#include "tb/common/cosim_target.h"

namespace rangesim::tb {

class CosimScoreboard {
 public:
  static constexpr std::size_t kMaxStored = 20;  // CosimReport keeps the first 20

  CosimScoreboard(CosimReport& report, const char* msg_type) : r_(report), type_(msg_type) {
    sc_core::sc_report_handler::set_actions(type_, sc_core::SC_ERROR, sc_core::SC_DISPLAY);
  }

  // One compared transaction (counted); a mismatch if expected != actual.
  template <class T>
  bool expect(const char* check, long long frame, long long row, long long column,
              std::uint64_t cycle, const T& expected, const T& actual) {
    ++r_.transactions;
    if (expected == actual) return true;
    mismatch(check, frame, row, column, cycle, to_text(expected), to_text(actual));
    return false;
  }
  // Per-cycle pin comparison: not a transaction, but a mismatch like one.
  template <class T>
  bool pin(const char* name, long long frame, std::uint64_t cycle, const T& expected,
           const T& actual) {
    if (expected == actual) return true;
    mismatch(name, frame, -1, -1, cycle, to_text(expected), to_text(actual));
    return false;
  }

  void mismatch(const std::string& check, long long frame, long long row, long long column,
                std::uint64_t cycle, const std::string& expected, const std::string& actual) {
    ++r_.mismatches;
    if (r_.first_mismatches.size() >= kMaxStored) return;
    r_.first_mismatches.push_back({check, frame, row, column, cycle, expected, actual});
    const std::string text = format(r_.first_mismatches.back());
    SC_REPORT_ERROR(type_, text.c_str());
  }

  static std::string format(const CosimMismatch& m) {
    std::ostringstream s;
    if (m.frame >= 0) s << "frame " << m.frame << " ";
    if (m.row >= 0) s << "row " << m.row << " ";
    if (m.column >= 0) s << "column " << m.column << " ";
    s << "cycle " << m.cycle << ": " << m.check << " expected " << m.expected << " got "
      << m.actual;
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
inline VerilatedContext* cosim_verilator_context(const CosimOptions& o) {
  VerilatedContext* ctx = Verilated::defaultContextp();
  ctx->randReset(2);
  ctx->randSeed(static_cast<int>(o.seed & 0x7fffffff));
  ctx->fatalOnError(false);
  if (!o.trace_path.empty()) ctx->traceEverOn(true);
  return ctx;
}

// Closes a report: SC errors and whether a Verilog assertion fired (counted as a mismatch).
inline void finish_cosim_report(CosimReport& r, VerilatedContext* ctx) {
  r.rtl_assertions_failed = ctx->gotError() ? 1 : 0;
  r.mismatches += static_cast<std::uint64_t>(r.rtl_assertions_failed);
  r.sc_errors = static_cast<int>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
}

}  // namespace rangesim::tb
