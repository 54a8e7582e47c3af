#pragma once
// The verilated RTL of the ls-conventional row readout (rtl/address_search.sv, instance
// Vaddress_search: 375 columns, 9 address bits), one instance per row as on the chip
// (row-parallel), driven under SystemC with the readout sequencer's exact schedule
// (systemc/readout_sequencer_kernel.h): search start in the last latch cycle of every sampling,
// the row's activation bits on act_i. A monitor decodes each row's bit-serial address stream into
// transactions stamped with the cycle (since reset release) of done_o. Elaborates SystemC: run it
// in a child process (bench_util.h run_in_child).
#include <cstdint>
#include <vector>

#include "core/ls_conventional_config.h"
#include "systemc/address_search_kernel.h"

namespace rangesim::app::bench {

struct ReadoutTxn {
  int frame = 0, sampling = 0, row = 0;
  bool found = false;
  int left = 0, right = 0;
  long long done_cycle = 0;  // cycle since reset release in which done_o was high
  bool operator==(const ReadoutTxn& o) const {
    return frame == o.frame && sampling == o.sampling && row == o.row && found == o.found && left == o.left &&
           right == o.right && done_cycle == o.done_cycle;
  }
};

// act[(f * N + (k - 1)) * rows + r]: activation row of row r after sampling k of frame access f.
struct ReadoutStimulus {
  int frames = 0;
  std::vector<systemc::ActivationRow> act;
};

// Start cycle (since reset release) of the search of sampling k (1..N) in frame access f.
long long readout_start_cycle(const LsConventionalConfig& cfg, int frame, int sampling);

// The model's transactions: AddressSearchKernel::evaluate on each row (the event-skipping path
// of the sensor kernel), stamped start + done_cycle. Ordered by (frame, sampling, row).
std::vector<ReadoutTxn> model_readout(const LsConventionalConfig& cfg, const ReadoutStimulus& stim);

struct RtlReadoutResult {
  std::vector<ReadoutTxn> txns;  // ordered by (frame, sampling, row)
  long long cycles = 0;          // clock cycles simulated after reset release
  double wall_s = 0;             // sc_start of the frames (elaboration excluded)
  double cpu_s = 0;              // CPU time of the same
  double elaboration_s = 0;      // building the 365 verilated instances
  long long sc_errors = 0;
  bool assertion_failed = false;  // a Verilog assertion fired
};

// Throws std::invalid_argument if the configuration is not the verilated instance's (columns,
// address bits, search cycles).
RtlReadoutResult run_rtl_readout(const LsConventionalConfig& cfg, const ReadoutStimulus& stim);

}  // namespace rangesim::app::bench
