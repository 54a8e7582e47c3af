// The co-simulation targets of ls-conventional (tb/common/cosim_target.h): its readout (small and
// full size) and its blocks, with the address search it shares with ls-demodulation. The
// runners adapt CosimOptions to their harness.
#include <algorithm>
#include <string>

#include "tb/common/address_search_cosim.h"
#include "tb/common/cosim_target.h"
#include "tb/ls_conventional/block_cosim.h"
#include "tb/common/rtl_build.h"
#include "tb/ls_conventional/cosim.h"
#include "tb/ls_conventional/verilog_parameters.h"

namespace rangesim::tb {
namespace {

CosimReport run_ls(const CosimOptions& o, bool full) {
  LsConventionalCosimOptions lo = ls_conventional_options(o, ls_conventional_instance_config(full));
  lo.full_size = full;
  return run_ls_conventional_cosim(lo).report;
}

// `rangesim cosim <ls-conventional preset>`: the readout at the preset's parameters.
RtlBuildSpec preset_readout(const ParamSet& preset) {
  return {"ls_conventional",
          "ls_conventional_readout",
          verilog_parameters(ls_conventional_from_params(preset), preset.origin()),
          "tb/ls_conventional/cosim_harness.h",
          "rangesim::tb::run_ls_conventional_preset",
          {}};
}
CosimReport run_ls_small(const CosimOptions& o) { return run_ls(o, false); }
CosimReport run_ls_full(const CosimOptions& o) { return run_ls(o, true); }

CosimReport run_address_search(const CosimOptions& o) {
  const AddressSearchShape p = address_search_shape(AddressSearchInstance::Small);
  AddressSearchCosimOptions ao;
  ao.instance = AddressSearchInstance::Small;
  ao.seed = o.seed;
  ao.rows_per_frame = 100;
  // An operation takes 1 + S + 2B cycles (S if nothing found) plus a gap of 0..2: S + 2B is a
  // lower bound of the mean, so the run covers at least the cycles asked for.
  const long long per_frame = ao.rows_per_frame * (p.search_cycles + 2 * p.address_bits);  // low: rounds up
  ao.frames = static_cast<int>(std::max<long long>(1, (static_cast<long long>(o.cycles) + per_frame - 1) / per_frame));
  if (o.inject_fault == "address_bit_flip") {
    ao.fault_operation = ao.frames * ao.rows_per_frame / 2;
    ao.fault_bit = 1;
  } else if (o.inject_fault == "start_while_busy") {
    ao.restart_operation = 3;
    ao.restart_cycle = 2;
  }
  ao.trace_path = o.trace_path;
  const AddressSearchCosimReport a = run_address_search_cosim(ao);
  CosimReport r;
  r.target = "address_search";
  r.cycles = static_cast<std::uint64_t>(a.cycles);
  r.transactions = static_cast<std::uint64_t>(a.transactions_compared);
  r.mismatches = static_cast<std::uint64_t>(a.mismatch_count) + (a.rtl_assertion_failed ? 1 : 0) + (a.finished ? 0 : 1);
  r.checks["address_search"] = {r.transactions, static_cast<std::uint64_t>(a.mismatch_count)};
  if (!a.finished) r.checks["run"].mismatches = 1;
  if (a.rtl_assertion_failed) r.checks["rtl_assertion"].mismatches = 1;
  for (const std::string& m : a.mismatches) r.first_mismatches.push_back({"address_search", -1, -1, -1, 0, "", m});
  if (!a.finished) r.first_mismatches.push_back({"run", -1, -1, -1, 0, "all operations done", "stalled"});
  if (a.rtl_assertion_failed)
    r.first_mismatches.push_back({"rtl_assertion", -1, -1, -1, r.cycles, "no assertion fails",
                                  "a Verilog assertion fired (its $error message names it)"});
  r.rtl_assertions_failed = a.rtl_assertion_failed ? 1 : 0;
  r.sc_errors = a.sc_errors;
  if (ao.fault_operation >= 0 && a.fault_frame >= 0) {
    r.fault_injected = true;
    r.fault_site = "frame " + std::to_string(a.fault_frame) + " row " + std::to_string(a.fault_row) + ": stream bit " +
                   std::to_string(ao.fault_bit) + " flipped";
  }
  if (ao.restart_operation >= 0) {
    r.fault_injected = true;
    r.fault_site = "operation " + std::to_string(ao.restart_operation) + " cycle " + std::to_string(ao.restart_cycle) +
                   ": start_i while busy";
  }
  return r;
}

}  // namespace

std::vector<CosimTarget> ls_conventional_cosim_targets() {
  return {
      {"ls-conventional",
       "ls-conventional readout RTL (8 x 16, 4 samplings) vs the clock-level model and golden, random scenes",
       ls_conventional_faults(), run_ls_small},
      {"ls-conventional-full",
       "full-size ls-conventional readout RTL (375 x 365, 4 samplings, uninstrumented) vs the clock-level model",
       ls_conventional_faults(), run_ls_full},
      {"address_search",
       "row address search RTL (16 columns) vs its SystemC model, random rows",
       {"address_bit_flip", "start_while_busy"},
       run_address_search},
      {"centre_processor",
       "row centre processor RTL vs its cycle kernel, random address streams and clears",
       {"centre_off_by_one", "count_wrap"},
       run_centre_processor_cosim},
      {"multisampling_sequencer",
       "ls-conventional frame sequencer RTL vs its cycle kernel, random reset pulses",
       {"search_start_late"},
       run_multisampling_sequencer_cosim},
  };
}

std::vector<PresetCosim> ls_conventional_preset_cosims() {
  return {{"ls-conventional", "ls-conventional", "rtl/ls_conventional/instances/small.toml", &preset_readout}};
}

}  // namespace rangesim::tb
