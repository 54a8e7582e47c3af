#pragma once
// The verilated RTL of the whole ls-conventional readout (rtl/ls_conventional/ls_conventional_readout.sv,
// instance Vls_conventional_readout: 365 x 375, the preset): its own frame sequencer, per-row
// comparator latches, address searches and centre processors. Driven under SystemC with nothing
// but reset and the comparator decisions cmp_i that the model's pixel array produced for the
// same frames (written at the first latch cycle of each sampling, as the chip's comparators
// change only there). A monitor decodes every row's bit-serial address stream into transactions
// stamped with the cycles (since reset release) of their first and last bit, and reads every
// row's centre at frame_done. Elaborates SystemC: run it in a child process
// (bench_util.h run_in_child).
#include <cstdint>
#include <vector>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_conventional/sensor_kernel.h"

namespace rangesim::app::bench {

// One row's address stream in one sampling.
struct StreamTxn {
  int frame = 0, sampling = 0, row = 0;
  int bits = 0;  // streamed bits (2 B when complete)
  int left = 0, right = 0;
  long long first_cycle = 0, last_cycle = 0;  // cycles since reset release of its first and last bit
  bool operator==(const StreamTxn& o) const {
    return frame == o.frame && sampling == o.sampling && row == o.row && bits == o.bits && left == o.left &&
           right == o.right && first_cycle == o.first_cycle && last_cycle == o.last_cycle;
  }
};

// act[(f * N + (k - 1)) * rows + r]: activation row of row r after sampling k of frame access f.
struct ReadoutStimulus {
  int frames = 0;
  std::vector<systemc::ActivationRow> act;
};

// The model's streams: AddressSearchKernel::evaluate on each row's activations (the
// event-skipping path of the sensor kernel) at the sequencer's search start, found rows only.
// Ordered by (frame, sampling, row).
std::vector<StreamTxn> model_streams(const LsConventionalConfig& cfg, const ReadoutStimulus& stim);

struct RtlReadoutResult {
  std::vector<StreamTxn> streams;            // ordered by (frame, sampling, row)
  std::vector<systemc::FrameResult> frames;  // centres at frame_done, end_cycle (no phase counts)
  long long cycles = 0;                      // clock cycles simulated after reset release
  double wall_s = 0;                         // sc_start of the frames (elaboration excluded)
  double cpu_s = 0;                          // CPU time of the same
  double elaboration_s = 0;                  // building the verilated readout and the cmp_i values
  long long sc_errors = 0;
  bool assertion_failed = false;  // a Verilog assertion fired
};

// Throws std::invalid_argument if the configuration is not the verilated instance's (rows,
// columns, address bits, samplings, cycle counts).
RtlReadoutResult run_rtl_readout(const LsConventionalConfig& cfg, const ReadoutStimulus& stim);

}  // namespace rangesim::app::bench
