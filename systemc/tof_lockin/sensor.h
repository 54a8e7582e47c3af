#pragma once
// Thin sc_module around TofLockinSensorKernel: one SC_THREAD steps the kernel
// event by event (or cycle by cycle) and waits until the kernel's simulated
// time, so sc_time_stamp() is the sensor's time; the ports show the gate
// pattern, phase, frame and readout row. No behaviour lives here.
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "systemc/common/simulate_entry.h"
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

  // What a traced pixel shows: its floating diffusions after every event and its ADC codes when
  // its row's conversion ends; the column ADC's codes of every row of that column.
  struct PixelProbe {
    TracePixel at;
    sc_core::sc_signal<double> fd_e[2];      // electrons on FD1 / FD2
    sc_core::sc_signal<int> code[2];         // the pixel's ADC codes, tap 1 / tap 2 (last conversion)
    sc_core::sc_signal<int> column_code[2];  // its column ADC's codes of the row just converted
  };
  // The sequencer's clock counts, written at every event: the model jumps from edge to edge, so
  // the trace carries the count instead of a free-running clock (millions of edges per frame).
  sc_core::sc_signal<long long> gate_cycles{"gate_cycles"};        // gate-clock cycles since the start
  sc_core::sc_signal<long long> readout_cycles{"readout_cycles"};  // readout-clock cycles since the start

  SC_HAS_PROCESS(TofLockinSensor);
  TofLockinSensor(sc_core::sc_module_name name, const TofLockinConfig& cfg, const LockinSimOptions& opt, int sim_rows,
                  int sim_columns, std::vector<LockinPixelStimulus> stimulus, long long frames,
                  const std::vector<TracePixel>& traced = {});

  const TofLockinSensorKernel& kernel() const { return kernel_; }
  double finish_time_s() const { return finish_s_; }  // sc_time_stamp() when the last frame ended
  const std::vector<std::unique_ptr<PixelProbe>>& probes() const { return probes_; }

 private:
  void run();
  void drive();
  TofLockinSensorKernel kernel_;                     // all behaviour
  std::vector<std::unique_ptr<PixelProbe>> probes_;  // traced pixels
  double finish_s_ = 0;                              // simulated time at the end, seconds
};

// Elaborates a TofLockinSensor with signals (and an optional VCD trace, opened
// after sc_start(SC_ZERO_TIME)), runs it to completion bounded by
// `time_limit_s`, and returns the simulated end time; errors go through
// SC_REPORT_ERROR. One call per process. `traced`: pixels of the window whose
// charges and codes the trace shows.
struct LockinScRun {
  double end_time_s = 0;    // sc_time_stamp() at the end
  bool finished = false;    // all frames done within the limit
  long long sc_errors = 0;  // sc_report_handler::get_count(SC_ERROR)
};
LockinScRun run_tof_lockin_systemc(TofLockinSensor*& sensor_out, const TofLockinConfig& cfg,
                                   const LockinSimOptions& opt, int sim_rows, int sim_columns,
                                   std::vector<LockinPixelStimulus> stimulus, long long frames, double time_limit_s,
                                   const std::string& vcd_path = "", const std::vector<TracePixel>& traced = {});

}  // namespace rangesim::systemc::lockin
