#include "systemc/ls_conventional/sensor.h"

#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>

namespace rangesim::systemc {

LsConventionalSensor::LsConventionalSensor(sc_core::sc_module_name name, const LsConventionalConfig& config,
                                           const PixelArrayOptions& options, StimulusSource source)
    : sc_core::sc_module(name),
      config_(config),
      sequencer_("sequencer", config.timing, config.multisampling.samplings),
      pixels_("pixel_array", config, options, std::move(source)),
      rows_("rows", config.pixel.rows, config.search, config.timing.search_cycles) {
  const std::size_t rows = static_cast<std::size_t>(config.pixel.rows);
  act_.init(rows);

  sequencer_.clk_i(clk_i);
  sequencer_.rst_i(rst_i);
  sequencer_.pix_reset_o(pix_reset_);
  sequencer_.latch_o(latch_);
  sequencer_.search_start_o(search_start_);
  sequencer_.frame_done_o(frame_done_);
  sequencer_.phase_o(phase_);
  sequencer_.sampling_o(sampling_);
  sequencer_.frame_o(frame_);

  pixels_.pix_reset_i(pix_reset_);
  pixels_.sampling_i(sampling_);
  pixels_.frame_i(frame_);
  pixels_.act_o.bind(act_);

  rows_.clk_i(clk_i);
  rows_.rst_i(rst_i);
  rows_.start_i(search_start_);
  rows_.clear_i(pix_reset_);
  rows_.act_i.bind(act_);
  rows_.pins_o(row_pins_);

  SC_METHOD(on_clock);
  sensitive << clk_i.pos();
  dont_initialize();
}

void LsConventionalSensor::on_clock() {
  if (rst_i.read()) {
    release_time_ = sc_core::sc_time_stamp();
    cycle_ = 0;
    phase_cycles_ = {};
    return;
  }
  for (PixelProbe& p : pixel_probes_) *p.active = act_[static_cast<std::size_t>(p.at.row)].read().test(p.at.column);
  // Signals hold their values of the ending cycle.
  const ReadoutPhase phase = static_cast<ReadoutPhase>(phase_.read());
  ++phase_cycles_[static_cast<std::size_t>(phase)];
  const RowArrayPins& rp = row_pins_.read();
  const std::size_t rows = rp.search.size();
  if (search_start_.read()) {
    for (std::size_t r = 0; r < rows; ++r)
      if (rp.search[r].busy)
        SC_REPORT_ERROR("rangesim/ls_conventional_sensor",
                        ("frame " + std::to_string(frame_.read()) + " row " + std::to_string(r) +
                         ": search start while the row's search is busy")
                            .c_str());
  }
  if (frame_done_.read()) {
    FrameResult fr;
    fr.frame = frame_.read();
    fr.rows.resize(rows);
    for (std::size_t r = 0; r < rows; ++r) {
      if (rp.search[r].busy)
        SC_REPORT_ERROR("rangesim/ls_conventional_sensor",
                        ("frame " + std::to_string(fr.frame) + " row " + std::to_string(r) +
                         ": address search still busy at the end of the frame access")
                            .c_str());
      fr.rows[r] = rp.centre[r];
    }
    fr.end_cycle = cycle_ + 1;
    fr.phase_cycles = phase_cycles_;
    for (long long c : phase_cycles_) fr.cycles += c;
    phase_cycles_ = {};
    results_.push_back(std::move(fr));
    if (on_frame_) on_frame_(static_cast<long long>(results_.size()));
    if (stop_after_ > 0 && static_cast<long long>(results_.size()) >= stop_after_) sc_core::sc_stop();
  }
  ++cycle_;
}

void LsConventionalSensor::trace(Waveform& w, const std::vector<int>& rows, const std::vector<TracePixel>& pixels) {
  Waveform::ValueNames phases;
  for (int p = 0; p < kReadoutPhases; ++p) phases.push_back({p, readout_phase_name(static_cast<ReadoutPhase>(p))});
  const std::string top = "ls_conventional", seq = top + ".sequencer";
  w.add(clk_i, top, "clk");
  w.add(rst_i, top, "rst");
  w.add(phase_, seq, "phase", phases);
  w.add(sampling_, seq, "sampling");
  w.add(frame_, seq, "frame");
  w.add(pix_reset_, seq, "pix_reset");
  w.add(latch_, seq, "latch");
  w.add(search_start_, seq, "search_start");
  w.add(frame_done_, seq, "frame_done");
  for (int r : rows) {
    if (r < 0 || r >= static_cast<int>(act_.size())) continue;
    // The row array's pins as written at each edge (fixed storage, traced by reference).
    const AddressSearchPins& s = rows_.pins().search[static_cast<std::size_t>(r)];
    const CentreProcessorPins& c = rows_.pins().centre[static_cast<std::size_t>(r)];
    const std::string row = top + ".row" + std::to_string(r);
    w.add(s.busy, row + ".address_search", "busy");
    w.add(s.found, row + ".address_search", "found");
    w.add(s.addr_valid, row + ".address_search", "addr_valid");
    w.add(s.addr_bit, row + ".address_search", "addr_bit");
    w.add(s.done, row + ".address_search", "done");
    w.add(c.valid, row + ".centre_processor", "valid");
    w.add(c.centre_q, row + ".centre_processor", "centre_q");
    w.add(c.sum, row + ".centre_processor", "sum");
    w.add(c.count, row + ".centre_processor", "count");
  }
  if (!w.enabled()) return;
  for (const TracePixel& p : pixels) {
    pixel_probes_.push_back({p, std::make_unique<bool>(false)});
    w.add(*pixel_probes_.back().active, top + ".pixel_" + std::to_string(p.row) + "_" + std::to_string(p.column),
          "active");
  }
}

// ---- run helpers ----

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
long long default_budget(const LsConventionalConfig& c, long long frames) {
  const MultisamplingSequencerKernel seq(c.timing, c.multisampling.samplings);
  return 2 * seq.frame_cycles() * frames + 16;
}
}  // namespace

namespace {
double thread_cpu_now() {
  timespec ts{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// One part of a run on the calling thread: rows [first_row, first_row + rows) of the frame
// accesses [first_frame, first_frame + frames).
struct Part {
  int first_row = 0, rows = 0;
  long long first_frame = 0, frames = 0;
};

struct PartRun {
  std::vector<FrameResult> frames;
  std::vector<std::string> errors;
  long long cycles = 0, pixels_simulated = 0, ticks = 0;
  long long first_reset_pixels = 0;  // pixels_simulated by the reset of its first frame access
  double cpu_s = 0;
  std::exception_ptr failure;
};

// `done` counts the frame accesses finished by every part; the reporting part passes it to
// run.progress.
void run_part(const LsConventionalConfig& config, SensorKernelOptions options, const Part& part,
              const StimulusSource& source, const SensorRunOptions& run, std::atomic<long long>& done, bool report,
              PartRun& out) {
  const double c0 = thread_cpu_now();
  try {
    options.pixel.first_row = part.first_row;
    options.pixel.row_count = part.rows;
    LsConventionalSensorKernel k(config, options, source);
    k.reserve_results(part.frames);
    k.reset_at_frame(static_cast<std::uint64_t>(part.first_frame));
    out.first_reset_pixels = k.pixels().pixels_simulated();
    const long long budget = run.cycle_budget > 0 ? run.cycle_budget : default_budget(config, run.frames);
    for (long long f = 0; f < part.frames; ++f) {
      const long long left = budget - k.cycle();
      if (left <= 0)
        throw std::runtime_error("simulation cycle budget of " + std::to_string(budget) + " cycles exhausted");
      k.advance_frames(1, left);
      const long long all = ++done;
      if (report && run.progress) run.progress(all);
    }
    out.cycles = k.cycle();
    out.errors = k.errors();
    out.pixels_simulated = k.pixels().pixels_simulated();
    out.ticks = k.ticks();
    out.frames = k.take_results();
  } catch (...) {
    out.failure = std::current_exception();
  }
  out.cpu_s = thread_cpu_now() - c0;
}

// The run's parts, one a thread: consecutive frame accesses, or bands of rows.
std::vector<Part> parts_of(const LsConventionalConfig& config, const SensorRunOptions& run) {
  const int rows = config.pixel.rows;
  const bool by_frames = run.split == SensorRunOptions::Split::FrameAccesses ||
                         (run.split == SensorRunOptions::Split::Auto && run.frames >= run.threads);
  const long long n = by_frames ? std::clamp<long long>(run.threads, 1, std::max(1LL, run.frames))
                                : std::clamp(run.threads, 1, std::max(1, rows));
  std::vector<Part> parts(static_cast<std::size_t>(n));
  for (long long i = 0; i < n; ++i) {
    Part& p = parts[static_cast<std::size_t>(i)];
    if (by_frames) {
      p.rows = rows;
      p.first_frame = run.frames * i / n;
      p.frames = run.frames * (i + 1) / n - p.first_frame;
    } else {
      p.first_row = static_cast<int>(rows * i / n);
      p.rows = static_cast<int>(rows * (i + 1) / n) - p.first_row;
      p.frames = run.frames;
    }
  }
  return parts;
}

// Part o's results after those of `to` (an earlier part): its frame accesses after, or its rows
// joined to each frame access's.
void join(PartRun& to, PartRun& o, const Part& part) {
  if (part.first_frame > 0) {  // later frame accesses
    to.frames.insert(to.frames.end(), std::make_move_iterator(o.frames.begin()),
                     std::make_move_iterator(o.frames.end()));
    to.cycles = o.cycles;
    to.ticks += o.ticks;
    // A kernel resets the next frame access in the cycle after its last frame_done: the part before
    // has counted this part's first reset already.
    to.pixels_simulated -= o.first_reset_pixels;
  } else {  // a band of rows: the same schedule, other rows
    if (o.frames.size() != to.frames.size() || o.cycles != to.cycles)
      throw std::logic_error("run_sensor_kernel: row bands disagree on the frame schedule");
    for (std::size_t f = 0; f < to.frames.size(); ++f) {
      FrameResult& into = to.frames[f];
      const FrameResult& from = o.frames[f];
      into.rows.insert(into.rows.end(), from.rows.begin(), from.rows.end());
      into.extents.insert(into.extents.end(), from.extents.begin(), from.extents.end());
    }
  }
  to.errors.insert(to.errors.end(), o.errors.begin(), o.errors.end());
  to.pixels_simulated += o.pixels_simulated;
}
}  // namespace

SensorRunResult run_sensor_kernel(const LsConventionalConfig& config, const SensorKernelOptions& options,
                                  StimulusSource source, const SensorRunOptions& run) {
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = thread_cpu_now();
  const std::vector<Part> parts = parts_of(config, run);
  std::vector<PartRun> out(parts.size());
  std::atomic<long long> done{0};
  {
    std::vector<std::thread> workers;
    for (std::size_t i = 1; i < parts.size(); ++i)
      workers.emplace_back([&, i] { run_part(config, options, parts[i], source, run, done, false, out[i]); });
    run_part(config, options, parts[0], source, run, done, true, out[0]);
    for (auto& w : workers) w.join();
  }
  for (const PartRun& p : out)
    if (p.failure) std::rethrow_exception(p.failure);
  for (std::size_t i = 1; i < parts.size(); ++i) join(out[0], out[i], parts[i]);
  if (run.progress && parts.size() > 1) run.progress(run.frames);
  SensorRunResult r;
  r.frames = std::move(out[0].frames);
  r.cycles = out[0].cycles;
  r.simulated_time_s = static_cast<double>(r.cycles) / config.timing.clock_Hz;
  r.ticks = out[0].ticks;
  r.errors = std::move(out[0].errors);
  r.pixels_simulated = out[0].pixels_simulated;
  for (const PartRun& p : out) r.thread_cpu_s.push_back(p.cpu_s);
  r.thread_cpu_s[0] = thread_cpu_now() - c0;  // part 0 with the set-up and the merge
  r.wall_time_s = seconds_since(t0);
  return r;
}

namespace {
struct Bench : sc_core::sc_module {
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true};
  LsConventionalSensor dut;
  int edges = 0;
  SC_HAS_PROCESS(Bench);
  Bench(sc_core::sc_module_name n, const LsConventionalConfig& c, const PixelArrayOptions& o, StimulusSource s)
      : sc_core::sc_module(n),
        clk("clk", sc_core::sc_time(1.0 / c.timing.clock_Hz, sc_core::SC_SEC)),
        dut("sensor", c, o, std::move(s)) {
    dut.clk_i(clk);
    dut.rst_i(rst);
    SC_METHOD(release_reset);
    sensitive << clk.posedge_event();
    dont_initialize();
  }
  void release_reset() {
    if (++edges == 2) rst.write(false);  // reset seen on the first two edges
  }
};
}  // namespace

SensorRunResult run_sensor_systemc(const LsConventionalConfig& config, const SensorKernelOptions& options,
                                   StimulusSource source, const SensorRunOptions& run) {
  const auto t0 = std::chrono::steady_clock::now();
  sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
  // Informational reports ("simulation stopped by user", the trace timescale) go to stdout and
  // would mix with a command's output: counted but not printed. Warnings and errors still are.
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  const long long sc_errors0 = sc_core::sc_report_handler::get_count(sc_core::SC_ERROR);
  const long long sc_warnings0 = sc_core::sc_report_handler::get_count(sc_core::SC_WARNING);
  Bench bench("bench", config, options.pixel, std::move(source));
  bench.dut.stop_after(run.frames);
  if (run.progress) bench.dut.on_frame(run.progress);
  Waveform wave(run.vcd_base);
  bench.dut.trace(wave, run.traced_rows, run.traced_pixels);
  const long long budget = run.cycle_budget > 0 ? run.cycle_budget : default_budget(config, run.frames);
  const sc_core::sc_time period = bench.clk.period();
  try {
    sc_core::sc_start(period * static_cast<double>(budget + 2));  // + the two reset edges
  } catch (...) {
    wave.close();
    throw;
  }
  wave.close();
  SensorRunResult r;
  r.frames = bench.dut.results();
  r.cycles = bench.dut.cycles();
  r.ticks = r.cycles;
  r.simulated_time_s =
      r.frames.empty() ? 0.0 : (sc_core::sc_time_stamp() - bench.dut.reset_release_time()).to_seconds();
  r.sc_errors = sc_core::sc_report_handler::get_count(sc_core::SC_ERROR) - sc_errors0;
  r.sc_warnings = sc_core::sc_report_handler::get_count(sc_core::SC_WARNING) - sc_warnings0;
  r.pixels_simulated = bench.dut.pixel_array().kernel().pixels_simulated();
  r.wall_time_s = seconds_since(t0);
  if (static_cast<long long>(r.frames.size()) < run.frames)
    throw std::runtime_error("SystemC simulation: cycle budget of " + std::to_string(budget) +
                             " cycles exhausted after " + std::to_string(r.frames.size()) + " of " +
                             std::to_string(run.frames) + " frame accesses");
  return r;
}

}  // namespace rangesim::systemc
