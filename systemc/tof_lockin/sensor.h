#pragma once
// Thin sc_module around TofLockinSensorKernel: one SC_THREAD steps the kernel
// event by event (or cycle by cycle) and waits until the kernel's simulated
// time, so sc_time_stamp() is the sensor's time; the ports show the gate
// pattern, phase, frame and readout row. No behaviour lives here.
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::systemc::lockin {

class TofLockinSensor : public sc_core::sc_module {
 public:
  sc_core::sc_out<bool> tx1_o{"tx1_o"};      // TX1 open (PHASE1)
  sc_core::sc_out<bool> tx2_o{"tx2_o"};      // TX2 open (PHASE2)
  sc_core::sc_out<bool> txd_o{"txd_o"};      // TXD open (PHASE3)
  sc_core::sc_out<bool> light_o{"light_o"};  // LED pulse emitted (dark in the ambient frame)
  sc_core::sc_out<int> phase_o{"phase_o"};   // LockinPhase as int
  sc_core::sc_out<int> frame_o{"frame_o"};   // frame index
  sc_core::sc_out<int> row_o{"row_o"};       // row in readout
  sc_core::sc_out<bool> done_o{"done_o"};    // all frames done

  SC_HAS_PROCESS(TofLockinSensor);
  TofLockinSensor(sc_core::sc_module_name name, const TofLockinConfig& cfg, const LockinSimOptions& opt, int sim_rows,
                  int sim_columns, std::vector<LockinPixelStimulus> stimulus, long long frames);

  const TofLockinSensorKernel& kernel() const { return kernel_; }
  double finish_time_s() const { return finish_s_; }  // sc_time_stamp() when the last frame ended

 private:
  void run();
  void drive();
  TofLockinSensorKernel kernel_;  // all behaviour
  double finish_s_ = 0;           // simulated time at the end, seconds
};

// Elaborates a TofLockinSensor with signals (and an optional VCD trace, opened
// after sc_start(SC_ZERO_TIME)), runs it to completion bounded by
// `time_limit_s`, and returns the simulated end time; errors go through
// SC_REPORT_ERROR. One call per process.
struct LockinScRun {
  double end_time_s = 0;    // sc_time_stamp() at the end
  bool finished = false;    // all frames done within the limit
  long long sc_errors = 0;  // sc_report_handler::get_count(SC_ERROR)
};
LockinScRun run_tof_lockin_systemc(TofLockinSensor*& sensor_out, const TofLockinConfig& cfg,
                                   const LockinSimOptions& opt, int sim_rows, int sim_columns,
                                   std::vector<LockinPixelStimulus> stimulus, long long frames, double time_limit_s,
                                   const std::string& vcd_path = "");

}  // namespace rangesim::systemc::lockin
