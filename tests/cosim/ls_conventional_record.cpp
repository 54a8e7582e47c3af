// Records a small ls-conventional co-simulation for the Icarus replay (tests/cosim, label
// iverilog): usage ls_conventional_record STIM OUT FRAMES SEED. Prints the number of recorded
// clock periods; exit 0 only if the Verilator run itself had no mismatch.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <systemc>

#include "tb/ls_conventional/cosim.h"

int sc_main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s STIM OUT FRAMES SEED\n", argv[0]);
    return 2;
  }
  rangesim::tb::LsConventionalCosimOptions o;
  o.record_stimulus_path = argv[1];
  o.record_outputs_path = argv[2];
  o.frames = std::atoll(argv[3]);
  o.seed = std::strtoull(argv[4], nullptr, 10);
  const auto r = rangesim::tb::run_ls_conventional_cosim(o);
  std::printf("%d\n", r.recorded_cycles);
  return r.report.mismatches == 0 ? 0 : 1;
}
