#include "systemc/tof_lockin/sensor.h"

#include "systemc/common/waveform.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rangesim::systemc::lockin {

TofLockinSensor::TofLockinSensor(sc_core::sc_module_name name, const TofLockinConfig& cfg, const LockinSimOptions& opt,
                                 int sim_rows, int sim_columns, std::vector<LockinPixelStimulus> stimulus,
                                 long long frames, const std::vector<TracePixel>& traced)
    : sc_core::sc_module(name), kernel_(cfg, opt, sim_rows, sim_columns, std::move(stimulus), frames) {
  for (const TracePixel& p : traced) {
    probes_.push_back(std::make_unique<PixelProbe>());
    probes_.back()->at = p;
  }
  SC_THREAD(run);
}

void TofLockinSensor::drive() {
  const auto& g = kernel_.gates();
  const bool acc = kernel_.phase() == LockinPhase::Phase1 || kernel_.phase() == LockinPhase::Phase2 ||
                   kernel_.phase() == LockinPhase::Phase3;
  tx1_o.write(acc && g.tx1());
  tx2_o.write(acc && g.tx2());
  txd_o.write(acc && g.txd());
  light_o.write(acc && g.light() && kernel_.led_on());
  phase_o.write(static_cast<int>(kernel_.phase()));
  frame_o.write(static_cast<int>(kernel_.frame()));
  row_o.write(kernel_.readout_row());
  done_o.write(kernel_.done());
  gate_cycles.write(kernel_.gate_cycles());
  readout_cycles.write(kernel_.readout_cycles());
  // Output follows the conversion of readout_row() in frame(): its codes are final.
  const bool converted = kernel_.phase() == LockinPhase::Output && kernel_.readout_row() < kernel_.rows();
  for (const auto& p : probes_) {
    const LockinPixelKernel& px = kernel_.pixel(p->at.row, p->at.column);
    for (int k = 0; k < 2; ++k) {
      p->fd_e[k].write(px.fd_e(k));
      if (!converted) continue;
      const int code = static_cast<int>(kernel_.code(kernel_.frame(), kernel_.readout_row(), p->at.column, k));
      p->column_code[k].write(code);
      if (kernel_.readout_row() == p->at.row) p->code[k].write(code);
    }
  }
}

void TofLockinSensor::run() {
  const sc_core::sc_time t_start = sc_core::sc_time_stamp();
  while (!kernel_.done()) {
    // Enter the state that the next step starts from (Idle -> the frame's first
    // phase).
    kernel_.step();
    drive();
    // Absolute target time: no rounding accumulates over the steps.
    const sc_core::sc_time target = t_start + sc_core::sc_time(kernel_.time_s(), sc_core::SC_SEC);
    if (target > sc_core::sc_time_stamp()) sc_core::wait(target - sc_core::sc_time_stamp());
  }
  finish_s_ = sc_core::sc_time_stamp().to_seconds();
}

LockinScRun run_tof_lockin_systemc(TofLockinSensor*& sensor_out, const TofLockinConfig& cfg,
                                   const LockinSimOptions& opt, int sim_rows, int sim_columns,
                                   std::vector<LockinPixelStimulus> stimulus, long long frames, double time_limit_s,
                                   const std::string& vcd_path, const std::vector<TracePixel>& traced) {
  static sc_core::sc_signal<bool> tx1("tx1"), tx2("tx2"), txd("txd"), light("light"), done("done");
  static sc_core::sc_signal<int> phase("phase"), frame("frame"), row("row");
  auto* s = new TofLockinSensor("tof_lockin", cfg, opt, sim_rows, sim_columns, std::move(stimulus), frames,
                                vcd_path.empty() ? std::vector<TracePixel>{} : traced);
  s->tx1_o(tx1), s->tx2_o(tx2), s->txd_o(txd), s->light_o(light), s->phase_o(phase), s->frame_o(frame), s->row_o(row),
      s->done_o(done);
  sensor_out = s;
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  std::string base = vcd_path;
  if (base.size() > 4 && base.compare(base.size() - 4, 4, ".vcd") == 0) base.resize(base.size() - 4);
  Waveform wave(base);
  Waveform::ValueNames phases;
  for (int p = 0; p <= static_cast<int>(LockinPhase::Output); ++p)
    phases.push_back({p, phase_name(static_cast<LockinPhase>(p))});
  wave.add(phase, "tof_lockin.sequencer", "phase", phases);
  wave.add(frame, "tof_lockin.sequencer", "frame");
  wave.add(row, "tof_lockin.sequencer", "row");
  wave.add(done, "tof_lockin.sequencer", "done");
  wave.add(s->gate_cycles, "tof_lockin.sequencer", "gate_cycles");
  wave.add(s->readout_cycles, "tof_lockin.sequencer", "readout_cycles");
  wave.add(tx1, "tof_lockin.gates", "tx1");
  wave.add(tx2, "tof_lockin.gates", "tx2");
  wave.add(txd, "tof_lockin.gates", "txd");
  wave.add(light, "tof_lockin.gates", "light");
  std::vector<int> adc_columns;  // one scope per column ADC, however many of its pixels are traced
  for (const auto& p : s->probes()) {
    const bool new_column = std::find(adc_columns.begin(), adc_columns.end(), p->at.column) == adc_columns.end();
    if (new_column) adc_columns.push_back(p->at.column);
    const std::string px = fmt::format("tof_lockin.pixel_{}_{}", p->at.row, p->at.column);
    const std::string adc = fmt::format("tof_lockin.column_adc_{}", p->at.column);
    for (int k = 0; k < 2; ++k) wave.add(p->fd_e[k], px, fmt::format("fd{}_e", k + 1));
    for (int k = 0; k < 2; ++k) wave.add(p->code[k], px, fmt::format("adc_code{}", k + 1));
    for (int k = 0; new_column && k < 2; ++k) wave.add(p->column_code[k], adc, fmt::format("code{}", k + 1));
  }
  sc_core::sc_start(sc_core::sc_time(time_limit_s, sc_core::SC_SEC));
  wave.close();
  LockinScRun r;
  r.finished = s->kernel().done();
  r.end_time_s = s->finish_time_s();
  if (!r.finished) {
    // Counted, not thrown out of here (outside a process the default action
    // would throw).
    try {
      SC_REPORT_ERROR("tof_lockin", "simulation did not finish within its time limit");
    } catch (const sc_core::sc_report&) {
    }
  }
  r.sc_errors = sc_core::sc_report_handler::get_count(sc_core::SC_ERROR);
  return r;
}

}  // namespace rangesim::systemc::lockin
