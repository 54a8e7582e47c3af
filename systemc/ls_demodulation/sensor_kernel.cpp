#include "systemc/ls_demodulation/sensor_kernel.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "systemc/common/random_stream.h"

namespace rangesim::systemc {

const char* to_string(DemodPhase p) {
  switch (p) {
    case DemodPhase::Integration: return "integration";
    case DemodPhase::Decision: return "decision";
    case DemodPhase::RowReadout: return "row_readout";
    case DemodPhase::Done: return "done";
  }
  return "?";
}

int DemodFrameResult::rows_detected() const {
  int n = 0;
  for (const auto& r : rows) n += r.valid() ? 1 : 0;
  return n;
}

namespace {

// The row's chain-settle cycles (core/ls_demodulation/config.h); below 1 the row cannot be read.
int settle_cycles(const LsDemodulationConfig& cfg) {
  const int s = readout_search_cycles(cfg.readout);
  if (s < 1)
    throw std::invalid_argument(
        "readout.row_cycles = " + std::to_string(cfg.readout.row_cycles) +
        ": must be at least 2 + 2 x readout.address_bits = " + std::to_string(2 + 2 * cfg.readout.address_bits) +
        " (start, search settle, left and right address)");
  return s;
}

}  // namespace

AddressSearchKernel demod_address_search(const LsDemodulationConfig& cfg) {
  AddressSearchConfig a;
  a.columns = cfg.pixel.columns;
  a.address_bits = cfg.readout.address_bits;
  a.addresses_per_sampling = 2;
  return AddressSearchKernel(a, settle_cycles(cfg));
}

DemodSensorKernel::DemodSensorKernel(const LsDemodulationConfig& cfg, const DemodKernelOptions& opt)
    : cfg_(cfg),
      opt_(opt),
      sched_(demod_window_schedule(cfg)),
      rows_(cfg.pixel.rows),
      columns_(cfg.pixel.columns),
      search_cycles_(settle_cycles(cfg)),
      search_(demod_address_search(cfg)) {
  if (rows_ < 1 || columns_ < 1) throw std::invalid_argument("pixel.rows / pixel.columns must be >= 1");
  if (cfg.grid.detections < 1) throw std::invalid_argument("evaluation.detections must be >= 1");
  if (cfg.comparator.adc_bits != 1)
    throw std::invalid_argument("comparator.adc_bits: only the 1-bit comparator is modelled");
  pixels_.assign(static_cast<std::size_t>(rows_) * columns_, DemodPixelKernel(cfg_, sched_));
  rngs_.resize(pixels_.size());
  search_.reset();
}

long long DemodSensorKernel::frame_cycles() const {
  return static_cast<long long>(cfg_.grid.detections) *
         (sched_.window_cycles() + 1 + static_cast<long long>(rows_) * cfg_.readout.row_cycles);
}

void DemodSensorKernel::start_frame(std::uint64_t frame, const DemodStimulus& stim) {
  const std::size_t n = pixels_.size();
  if (stim.beam_A.size() != n || stim.background_A.size() != n)
    throw std::invalid_argument("DemodSensorKernel: stimulus size differs from rows x columns");
  stim_ = stim;
  res_ = DemodFrameResult{};
  res_.frame = frame;
  res_.phase_cycles.assign(3, 0);
  res_.rows.assign(static_cast<std::size_t>(rows_), DemodRowResult{});
  res_.activations.assign(static_cast<std::size_t>(rows_), ActivationRow(columns_));
  decision_ = 0;
  row_strobe_ = false;
  begin_decision();
}

void DemodSensorKernel::begin_decision() {
  const std::uint64_t key_frame = res_.frame * static_cast<std::uint64_t>(cfg_.grid.detections) + decision_;
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < columns_; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * columns_ + c;
      rngs_[i] = pixel_stream(
          pixel_stream_key(opt_.seed, key_frame, static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(c)));
      pixels_[i].reset(stim_.beam_A[i], stim_.background_A[i], rngs_[i], opt_.noise,
                       opt_.event_skipping && opt_.aggregate);
    }
  phase_ = DemodPhase::Integration;
  phase_cycle_ = 0;
}

void DemodSensorKernel::decide() {
  const std::uint64_t key_frame = res_.frame * static_cast<std::uint64_t>(cfg_.grid.detections) + decision_;
  for (int r = 0; r < rows_; ++r) {
    // Frame-common read noise of the row: its own stream (column key 0xffffffff).
    pcg32 rr = pixel_stream(pixel_stream_key(opt_.seed, key_frame, static_cast<std::uint32_t>(r), 0xffffffffU));
    const double n = standard_normal(rr);
    const double o = opt_.noise.read ? n * cfg_.noise.read_noise_V : 0.0;
    ActivationRow act(columns_);
    for (int c = 0; c < columns_; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * columns_ + c;
      const double d = pixels_[i].diff_V();
      const double offset = stim_.comparator_offset_V.empty() ? 0.0 : stim_.comparator_offset_V[i];
      if (d + o + offset >= cfg_.comparator.threshold_V) act.set(c);
      if (opt_.keep_analogue) res_.diff_V.push_back(d);
    }
    if (opt_.keep_analogue) res_.read_offset_V.push_back(o);
    res_.activations[static_cast<std::size_t>(r)] = act;
  }
}

void DemodSensorKernel::finish_row(const AddressSearchResult& r) {
  row_strobe_ = true;
  DemodRowResult& rr = res_.rows[static_cast<std::size_t>(row_)];
  if (r.found) {
    ++rr.detections;
    rr.centre_sum_px += 0.5 * (r.left + r.right);
    rr.left = r.left;
    rr.right = r.right;
    rr.min_left = rr.min_left < 0 ? r.left : std::min(rr.min_left, r.left);
    rr.max_right = std::max(rr.max_right, r.right);
  }
  last_row_ = rr;
}

void DemodSensorKernel::enter_row(int row) {
  row_ = row;
  phase_cycle_ = 0;
  if (row_ < rows_) return;
  if (++decision_ < cfg_.grid.detections) {
    begin_decision();
  } else {
    phase_ = DemodPhase::Done;
  }
}

void DemodSensorKernel::tick() {
  if (phase_ == DemodPhase::Done) throw std::logic_error("DemodSensorKernel::tick: no frame started");
  row_strobe_ = false;
  ++cycle_;
  ++res_.cycles;
  ++res_.phase_cycles[static_cast<std::size_t>(phase_)];
  switch (phase_) {
    case DemodPhase::Integration:
      if (pixels_.front().aggregated())
        throw std::logic_error(
            "DemodSensorKernel::tick: the window is aggregated; tick with aggregate or event_skipping off");
      for (auto& p : pixels_) p.step(1);
      if (++phase_cycle_ == sched_.window_cycles()) phase_ = DemodPhase::Decision, phase_cycle_ = 0;
      break;
    case DemodPhase::Decision:
      decide();
      phase_ = DemodPhase::RowReadout;
      enter_row(0);
      break;
    case DemodPhase::RowReadout: {
      const ActivationRow& act = res_.activations[static_cast<std::size_t>(row_)];
      if (phase_cycle_ == 0) {
        bits_ = 0;
        search_.tick(false, true, act);
      } else {
        const AddressSearchPins p = search_.pins();
        if (p.addr_valid) bits_ = (bits_ << 1) | (p.addr_bit ? 1U : 0U);
        if (p.done) {
          const std::uint64_t mask = (std::uint64_t{1} << cfg_.readout.address_bits) - 1;
          AddressSearchResult r;
          r.found = p.found;
          r.left = static_cast<int>((bits_ >> cfg_.readout.address_bits) & mask);
          r.right = static_cast<int>(bits_ & mask);
          finish_row(r);
        }
        search_.tick(false, false, act);
      }
      if (++phase_cycle_ == cfg_.readout.row_cycles) enter_row(row_ + 1);
      break;
    }
    case DemodPhase::Done: break;
  }
  if (phase_ == DemodPhase::Done) res_.end_cycle = cycle_;
}

long long DemodSensorKernel::advance() {
  if (!opt_.event_skipping || phase_ == DemodPhase::Decision) {
    tick();
    return 1;
  }
  if (phase_ == DemodPhase::Done) throw std::logic_error("DemodSensorKernel::advance: no frame started");
  row_strobe_ = false;
  long long n = 0;
  if (phase_ == DemodPhase::Integration) {
    n = pixels_.front().cycles_to_edge();  // the same schedule for every pixel
    for (auto& p : pixels_) p.step(n);
    if ((phase_cycle_ += n) == sched_.window_cycles()) phase_ = DemodPhase::Decision, phase_cycle_ = 0;
    res_.phase_cycles[0] += n;
  } else {  // a whole row in closed form (the search kernel stays idle)
    n = cfg_.readout.row_cycles - phase_cycle_;
    if (phase_cycle_ == 0) finish_row(search_.evaluate(res_.activations[static_cast<std::size_t>(row_)]));
    res_.phase_cycles[2] += n;
    enter_row(row_ + 1);
  }
  cycle_ += n;
  res_.cycles += n;
  if (phase_ == DemodPhase::Done) res_.end_cycle = cycle_;
  return n;
}

DemodFrameResult DemodSensorKernel::finish_frame() {
  const long long budget = frame_cycles() + 1;  // bounded: a broken schedule fails, not hangs
  for (long long k = 0; phase_ != DemodPhase::Done; ++k) {
    if (k > budget) throw std::runtime_error("DemodSensorKernel: frame exceeded its cycle budget");
    advance();
  }
  return res_;
}

DemodFrameResult DemodSensorKernel::run_frame(std::uint64_t frame, const DemodStimulus& stim) {
  start_frame(frame, stim);
  return finish_frame();
}

bool DemodSensorKernel::mpy_plus() const {
  if (phase_ != DemodPhase::Integration) return false;
  int c = static_cast<int>(phase_cycle_ % sched_.period_cycles);
  for (std::size_t i = 0; i < sched_.segment_cycles.size(); ++i) {
    if (c < sched_.segment_cycles[i]) return sched_.segment_branch[i] > 0;
    c -= sched_.segment_cycles[i];
  }
  return false;
}

DemodRunResult run_demod_kernel(const LsDemodulationConfig& cfg, const DemodKernelOptions& opt,
                                const DemodStimulusSource& source, long long frames, const DemodProgress& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  DemodSensorKernel k(cfg, opt);
  DemodRunResult out;
  DemodStimulus s;
  for (long long f = 0; f < frames; ++f) {
    source(static_cast<std::uint64_t>(f), s);
    out.frames.push_back(k.run_frame(static_cast<std::uint64_t>(f), s));
    if (progress) progress(f + 1);
  }
  out.cycles = k.cycle();
  out.simulated_time_s = static_cast<double>(out.cycles) / cfg.readout.clock_Hz;
  out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace rangesim::systemc
