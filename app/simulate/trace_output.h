#pragma once
// `rangesim simulate --trace FILE.vcd|FILE.fst`, shared by every sensor. SystemC writes VCD only,
// so the model always traces into a temporary VCD beside the target; for .fst that VCD is
// converted with vcd2fst (Debian package gtkwave). With it come a GTKWave save file FILE.gtkw and
// its translate filters (systemc/common/waveform.h). The folder of FILE is created. Nothing
// appears beside FILE until commit(): a failed run, a failed conversion or an exception leaves
// no trace file, no temporary and no folder the run created.
#include <string>

namespace rangesim::app {

class TraceOutput {
 public:
  // `path` = --trace ("" = tracing off: everything below is a no-op). Throws UserError (exit 2)
  // when the name does not end in .vcd or .fst, the directory is missing or not writable, the
  // harness is the bare kernels (no waveform), or vcd2fst is missing for .fst.
  TraceOutput(const std::string& path, bool kernel_only);
  ~TraceOutput();  // removes the temporaries unless committed
  TraceOutput(const TraceOutput&) = delete;
  TraceOutput& operator=(const TraceOutput&) = delete;

  bool enabled() const { return !path_.empty(); }
  // Base name for sc_create_vcd_trace_file (which appends ".vcd"); "" when tracing is off.
  const std::string& vcd_base() const { return vcd_base_; }
  // Converts the finished VCD to its final format under a temporary name (call before the
  // output folder is committed, so a failure leaves nothing written). Throws std::runtime_error.
  void finish();
  // Renames the finished trace to FILE. After finish(); returns FILE ("" when off).
  std::string commit();

 private:
  std::string path_;       // --trace
  std::string stem_;       // its file name without the extension
  std::string staging_;    // folder beside it holding the trace, save file and filters until commit
  std::string vcd_base_;   // <staging>/<stem>: the model writes <stem>.vcd there
  std::string finished_;   // temporary in the final format, ready to rename
  std::string made_root_;  // the highest folder this run created for FILE ("" = none): removed if left empty
  bool committed_ = false;
  int staging_slot_ = -1;  // app/run_control.h: the staging folder is removed when a signal ends the run
};

}  // namespace rangesim::app
