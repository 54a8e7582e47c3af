#include "systemc/ls_demodulation/sensor.h"

#include <chrono>
#include <string>

namespace rangesim::systemc {

DemodSensor::DemodSensor(sc_core::sc_module_name name, const LsDemodulationConfig& cfg, const DemodKernelOptions& opt,
                         DemodStimulusSource source, long long frames, DemodProgress progress)
    : sc_core::sc_module(name),
      kernel_(cfg, opt),
      source_(std::move(source)),
      progress_(std::move(progress)),
      frames_(frames),
      event_skipping_(opt.event_skipping),
      period_(1.0 / cfg.readout.clock_Hz, sc_core::SC_SEC) {
  if (frames_ < 1) throw std::invalid_argument("DemodSensor: frames must be >= 1");
  source_(0, stim_);
  kernel_.start_frame(0, stim_);
  SC_METHOD(on_clock);
  sensitive << clk_i.pos();
  dont_initialize();
}

void DemodSensor::on_clock() {
  if (static_cast<long long>(results_.size()) >= frames_) return;
  // Event skipping: the kernel jumps n edges and the method sleeps until the edge after them
  // (next_trigger on an edge time, also for n = 1: a timed wake-up runs in the first delta of
  // that time, before the clock's posedge delta, which a fall-back to the static sensitivity
  // would catch as a second trigger in the same cycle); otherwise one tick per clock edge.
  const long long n = event_skipping_ ? kernel_.advance() : (kernel_.tick(), 1LL);
  span_end_ = sc_core::sc_time_stamp() + n * period_;
  if (event_skipping_) next_trigger(n * period_);
  phase_o.write(static_cast<int>(kernel_.phase()));
  row_o.write(kernel_.row());
  row_valid_o.write(kernel_.row_valid());
  row_detections_o.write(kernel_.last_row().detections);
  row_centre_px_o.write(kernel_.last_row().centre_px());
  frame_done_o.write(kernel_.frame_done());
  frame_o.write(static_cast<int>(results_.size()));
  decision_o.write(kernel_.decision());
  phase_cycle_o.write(static_cast<int>(kernel_.phase_cycle()));  // the pin is 32 bits (windows of < 2^31 cycles)
  mpy_plus_o.write(kernel_.mpy_plus());
  const AddressSearchPins pins = kernel_.search_pins();
  search_start_o.write(kernel_.phase() == DemodPhase::RowReadout && kernel_.phase_cycle() == 1);
  addr_valid_o.write(pins.addr_valid);
  addr_bit_o.write(pins.addr_bit);
  for (PixelProbe& p : pixel_probes_) {
    const DemodPixelKernel& px = kernel_.pixel(p.at.row, p.at.column);
    p.out_V[0] = px.plus_V(), p.out_V[1] = px.minus_V();
    *p.active = kernel_.active(p.at.row, p.at.column);
  }
  if (!kernel_.frame_done()) return;
  const DemodFrameResult& r = kernel_.result();
  if (r.cycles != kernel_.frame_cycles())
    SC_REPORT_ERROR(name(), ("frame " + std::to_string(r.frame) + " took " + std::to_string(r.cycles) +
                             " cycles, the schedule says " + std::to_string(kernel_.frame_cycles()))
                                .c_str());
  results_.push_back(r);
  if (progress_) progress_(static_cast<long long>(results_.size()));
  const auto next = static_cast<std::uint64_t>(results_.size());
  if (static_cast<long long>(next) >= frames_) {
    sc_core::sc_stop();
    return;
  }
  source_(next, stim_);
  kernel_.start_frame(next, stim_);
}

void DemodSensor::trace(Waveform& w, const std::vector<TracePixel>& pixels) {
  Waveform::ValueNames phases;
  for (int p = 0; p <= static_cast<int>(DemodPhase::Done); ++p)
    phases.push_back({p, to_string(static_cast<DemodPhase>(p))});
  const std::string top = "ls_demodulation", seq = top + ".sequencer", ro = top + ".readout";
  w.add(clk_i, top, "clk");
  w.add(phase_o, seq, "phase", phases);
  w.add(frame_o, seq, "frame");
  w.add(decision_o, seq, "decision");
  w.add(phase_cycle_o, seq, "phase_cycle");
  w.add(mpy_plus_o, seq, "mpy_plus");
  w.add(frame_done_o, seq, "frame_done");
  w.add(row_o, ro, "row");
  w.add(search_start_o, ro, "search_start");
  w.add(addr_valid_o, ro, "addr_valid");
  w.add(addr_bit_o, ro, "addr_bit");
  w.add(row_valid_o, ro, "row_valid");
  w.add(row_detections_o, ro, "row_detections");
  w.add(row_centre_px_o, ro, "row_centre_px");
  if (!w.enabled()) return;
  for (const TracePixel& p : pixels) {
    pixel_probes_.push_back({p, std::make_unique<double[]>(2), std::make_unique<bool>(false)});
    const std::string scope = top + ".pixel_" + std::to_string(p.row) + "_" + std::to_string(p.column);
    w.add(*pixel_probes_.back().active, scope, "active");
    w.add(pixel_probes_.back().out_V[0], scope, "out_plus_V");
    w.add(pixel_probes_.back().out_V[1], scope, "out_minus_V");
  }
}

DemodRunResult run_demod_systemc(const LsDemodulationConfig& cfg, const DemodKernelOptions& opt,
                                 const DemodStimulusSource& source, long long frames, const std::string& vcd_base,
                                 const DemodProgress& progress, const std::vector<TracePixel>& traced) {
  const auto t0 = std::chrono::steady_clock::now();
  const double period_s = 1.0 / cfg.readout.clock_Hz;
  const long long err0 = static_cast<long long>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
  sc_core::sc_clock clk("demod_clk", sc_core::sc_time(period_s, sc_core::SC_SEC));
  sc_core::sc_signal<int> phase("phase"), row("row"), det("det"), frame("frame"), decision("decision"),
      pcycle("phase_cycle");
  sc_core::sc_signal<bool> valid("valid"), done("done"), mpy("mpy_plus"), start("search_start"), avalid("addr_valid"),
      abit("addr_bit");
  sc_core::sc_signal<double> centre("centre");
  DemodSensor dut("demod_sensor", cfg, opt, source, frames, progress);
  dut.frame_o(frame);
  dut.decision_o(decision);
  dut.phase_cycle_o(pcycle);
  dut.mpy_plus_o(mpy);
  dut.search_start_o(start);
  dut.addr_valid_o(avalid);
  dut.addr_bit_o(abit);
  dut.clk_i(clk);
  dut.phase_o(phase);
  dut.row_o(row);
  dut.row_valid_o(valid);
  dut.row_detections_o(det);
  dut.row_centre_px_o(centre);
  dut.frame_done_o(done);
  DemodRunResult out;
  // Informational reports ("simulation stopped by user") go to stdout and would break --json.
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  // Bounded: a time budget of one frame more than the schedule needs.
  const double budget_s = (static_cast<double>(frames) + 1) * static_cast<double>(dut.frame_cycles()) * period_s;
  if (!vcd_base.empty()) sc_core::sc_start(sc_core::SC_ZERO_TIME);  // tracing only after the zero-time start
  Waveform wave(vcd_base);
  dut.trace(wave, traced);
  try {
    sc_core::sc_start(sc_core::sc_time(budget_s, sc_core::SC_SEC));
  } catch (...) {
    wave.close();
    throw;
  }
  wave.close();
  out.frames = dut.frames();
  out.cycles = dut.edges();
  // Edges at t = k T, k = 0..n-1: the run spans n periods (the last edge's cycle included).
  out.simulated_time_s = dut.span_end().to_seconds();
  out.sc_errors = static_cast<long long>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR)) - err0;
  out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rangesim::systemc
