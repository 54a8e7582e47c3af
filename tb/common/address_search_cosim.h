#pragma once
// Co-simulation of the row address search: the verilated RTL (rangesim_rtl) and the SystemC
// model (rangesim::systemc::AddressSearch) side by side on the same random stimulus, with a
// scoreboard that compares, cycle by cycle, the output pins and the ordered transactions
// (frame, row, kind, address, cycle). Elaborates SystemC, so call it once per process.
#include <cstdint>
#include <string>
#include <vector>

namespace rangesim::tb {

enum class AddressSearchInstance {
  Default,  // Vaddress_search: rtl/ls_conventional/instances/full.toml (375 columns, 9-bit addresses)
  Small,    // Vaddress_search_small: rtl/ls_conventional/instances/small.toml (16 columns: corner cases come often)
};

// The sizes an instance was verilated with: those of its instance preset.
struct AddressSearchShape {
  const char* prefix;  // verilated class name
  int columns;         // COLUMNS
  int address_bits;    // ADDRESS_BITS
  int search_cycles;   // SEARCH_CYCLES
};
AddressSearchShape address_search_shape(AddressSearchInstance instance);

struct AddressSearchCosimOptions {
  AddressSearchInstance instance = AddressSearchInstance::Small;
  int frames = 5;  // rows are tagged (frame, row); operations = frames * rows
  int rows_per_frame = 100;
  std::uint64_t seed = 1;  // stimulus and Verilator's random initial state
  int max_gap_cycles = 2;  // idle cycles between operations, uniform in [0, max]
  // Fault injection (negative tests): flip stream bit `fault_bit` (0 = left MSB) of the RTL
  // output seen by the scoreboard, in the first operation from index `fault_operation` on that
  // streams (-1: no fault). The report says where it went.
  int fault_operation = -1;
  int fault_bit = 0;
  // Protocol fault: raise start_i again in cycle k = `restart_cycle` (>= 1) of operation
  // `restart_operation` (-1: off); the RTL assertion a_start_while_busy must fire.
  int restart_operation = -1;
  int restart_cycle = 1;
  long long cycle_limit = 0;  // 0: enough for all operations plus slack
  std::string trace_path;     // non-empty: the RTL's VCD with the model's pins under "expected"
};

struct AddressSearchCosimReport {
  int operations_done = 0;               // operations completed by the RTL
  long long cycles = 0;                  // clock cycles simulated
  long long transactions_compared = 0;   // scoreboard transactions checked
  long long mismatch_count = 0;          // all mismatches (pins + transactions)
  std::vector<std::string> mismatches;   // the first few, readable
  int fault_frame = -1, fault_row = -1;  // where the bit flip was injected (-1: nowhere)
  bool rtl_assertion_failed = false;     // a Verilog assertion fired ($error)
  bool finished = false;                 // all operations done within the cycle limit
  int sc_errors = 0;                     // SC_ERROR reports during the run
};

AddressSearchCosimReport run_address_search_cosim(const AddressSearchCosimOptions& options);

}  // namespace rangesim::tb
