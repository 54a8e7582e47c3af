#include "systemc/tof_spad/sensor.h"

#include "systemc/common/waveform.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rangesim::systemc::spad {

namespace {
std::uint32_t word_of(long long v) { return static_cast<std::uint32_t>(std::min<long long>(v, 0xffffffffLL)); }

// Words of one frame in readout order: per row, per group, codes x pixels of the group.
void append_words(const FrameResult& f, int cpt, std::vector<std::uint32_t>& out) {
  for (std::size_t i = 0; i < f.pixels.size(); i += static_cast<std::size_t>(cpt))
    for (int k = 0; k < cpt; ++k)
      for (long long v : f.pixels[i + static_cast<std::size_t>(k)].events) out.push_back(word_of(v));
}
}  // namespace

TofSpadSensor::TofSpadSensor(sc_core::sc_module_name name, const TofSpadKernel& kernel, const PixelSelection& sel,
                             RateSource rates, long long frames, const std::vector<TracePixel>& traced)
    : sc_core::sc_module(name), kernel_(kernel), sel_(sel), rates_(std::move(rates)), frames_to_run_(frames) {
  if (frames < 1) SC_REPORT_ERROR(this->name(), "frames must be >= 1");
  const int cpt = kernel.config().tdc.columns_per_tdc;
  for (const TracePixel& p : traced) {
    pixel_probes_.push_back(std::make_unique<PixelProbe>());
    pixel_probes_.back()->at = p;
    if (probe_of(p.column / cpt) >= 0) continue;
    group_probes_.push_back(std::make_unique<GroupProbe>());
    group_probes_.back()->group = p.column / cpt;
  }
  period_ = sc_core::sc_time(kernel.config().tdc.lsb_s, sc_core::SC_SEC);
  if (period_ == sc_core::SC_ZERO_TIME) SC_REPORT_ERROR(this->name(), "TDC LSB below the time resolution");
  SC_THREAD(sequencer);
}

void TofSpadSensor::sequencer() {
  const int cpt = kernel_.config().tdc.columns_per_tdc;
  for (long long fr = 0; fr < frames_to_run_; ++fr) {
    FrameResult f;
    f.frame = fr;
    f.phase_cycles.assign(2, 0);
    const sc_core::sc_time frame_start = sc_core::sc_time_stamp();
    for (int row = 0; row < kernel_.rows(); ++row) {
      row_o.write(row);
      phase_o.write(1);
      const bool simulated = std::find(sel_.rows.begin(), sel_.rows.end(), row) != sel_.rows.end();
      long long starts = kernel_.laser_cycles();
      std::vector<GroupHistogram> groups;
      std::vector<TracedHit> hits;
      const bool traced_row =
          std::any_of(pixel_probes_.begin(), pixel_probes_.end(), [row](const auto& p) { return p->at.row == row; });
      if (simulated) {
        for (int gi = sel_.first_group; gi < sel_.first_group + sel_.groups; ++gi) {
          const int probe = traced_row ? probe_of(gi) : -1;
          const TofSpadKernel::HitObserver record = [&hits, probe, gi, cpt](int who, const TdcHit& h) {
            hits.push_back({static_cast<std::size_t>(probe), gi * cpt + who, h});
          };
          groups.push_back(
              kernel_.simulate_group(static_cast<std::uint64_t>(fr), row, gi, rates_, probe >= 0 ? &record : nullptr));
          if (probe >= 0 && (groups.back().aggregated || groups.back().background_class)) ++drawn_at_once_;
          starts = groups.back().starts;
          kernel_.count_group(f, row, gi, groups.back(), rates_);
        }
      }
      std::stable_sort(hits.begin(), hits.end(),
                       [](const TracedHit& a, const TracedHit& b) { return a.hit.abs_bin < b.hit.abs_bin; });
      sc_core::sc_time t0 = sc_core::sc_time_stamp();
      integrate(row, starts, std::move(hits));
      f.phase_cycles[0] += std::llround((sc_core::sc_time_stamp() - t0) / period_);
      phase_o.write(2);
      t0 = sc_core::sc_time_stamp();
      const sc_core::sc_time word_time = period_ * static_cast<double>(kernel_.cycles_per_word());
      // Readout: lanes in parallel; the module streams the simulated groups' words on one port.
      std::vector<std::uint32_t> row_words;
      for (std::size_t gi = 0; gi < groups.size(); ++gi)
        for (int k = 0; k < cpt; ++k)
          for (long long v : groups[gi].events[static_cast<std::size_t>(k)]) row_words.push_back(word_of(v));
      const long long words = kernel_.readout_words_per_row();
      for (long long w = 0; w < words; ++w) {
        // Word w of every lane leaves now; lane gi's word is row_words[gi * words + w].
        for (std::size_t gi = 0; gi < groups.size(); ++gi) {
          const std::uint32_t v = row_words[gi * static_cast<std::size_t>(words) + static_cast<std::size_t>(w)];
          word_o.write(v);
        }
        word_valid_o.write(!groups.empty());
        wait(word_time);
      }
      word_valid_o.write(false);
      f.phase_cycles[1] += std::llround((sc_core::sc_time_stamp() - t0) / period_);
      for (std::size_t gi = 0; gi < groups.size(); ++gi)
        for (int k = 0; k < cpt; ++k)
          f.pixels.push_back(
              kernel_.make_pixel(row, (sel_.first_group + static_cast<int>(gi)) * cpt + k, groups[gi], k));
      for (std::uint32_t v : row_words) words_.push_back(v);
    }
    phase_o.write(0);
    f.cycles = std::llround((sc_core::sc_time_stamp() - frame_start) / period_);
    if (f.cycles != f.phase_cycles[0] + f.phase_cycles[1]) SC_REPORT_ERROR(name(), "frame cycles != sum of phases");
    frames_.push_back(std::move(f));
  }
  done_ = true;
}

int TofSpadSensor::probe_of(int group) const {
  for (std::size_t i = 0; i < group_probes_.size(); ++i)
    if (group_probes_[i]->group == group) return static_cast<int>(i);
  return -1;
}

void TofSpadSensor::integrate(int row, long long starts, std::vector<TracedHit> hits) {
  // Event skipping: without traced hits the integration is one wait of its whole length.
  const sc_core::sc_time t0 = sc_core::sc_time_stamp();
  const sc_core::sc_time end = t0 + period_ * static_cast<double>(starts * kernel_.phase_bins());
  write_counts_.assign(
      group_probes_.size(),
      std::vector<long long>(static_cast<std::size_t>(kernel_.config().tdc.columns_per_tdc * kernel_.codes())));
  sc_core::sc_time pulse_end = t0;  // when the pulses of the last hit fall (one LSB later)
  for (const TracedHit& h : hits) {
    const sc_core::sc_time at = t0 + period_ * static_cast<double>(h.hit.abs_bin);
    if (at >= pulse_end && pulse_end > t0) {
      wait(pulse_end - sc_core::sc_time_stamp());
      clear_pulses();
    }
    if (at > sc_core::sc_time_stamp()) wait(at - sc_core::sc_time_stamp());
    show_hit(row, h);
    pulse_end = at + period_;
  }
  if (pulse_end > t0 && pulse_end <= end) {
    wait(pulse_end - sc_core::sc_time_stamp());
    clear_pulses();
  }
  if (end > sc_core::sc_time_stamp()) wait(end - sc_core::sc_time_stamp());
  clear_pulses();
}

void TofSpadSensor::show_hit(int row, const TracedHit& h) {
  GroupProbe& g = *group_probes_[h.probe];
  const int cpt = kernel_.config().tdc.columns_per_tdc;
  laser_cycle.write(h.hit.abs_bin / kernel_.phase_bins());
  g.hit.write(true), g.hit_column.write(h.column), g.code.write(h.hit.code);
  g.result.write(h.hit.kind == TdcHit::Kind::Event ? 1 : h.hit.kind == TdcHit::Kind::Overflow ? 2 : 3);
  for (const auto& p : pixel_probes_)
    if (p->at.row == row && p->at.column == h.column) p->avalanche.write(true);
  if (h.hit.kind != TdcHit::Kind::Event) return;
  long long& count = write_counts_[h.probe][static_cast<std::size_t>((h.column % cpt) * kernel_.codes() + h.hit.code)];
  write.write(true), write_column.write(h.column), write_code.write(h.hit.code), write_count.write(++count);
}

void TofSpadSensor::clear_pulses() {
  write.write(false);
  for (const auto& g : group_probes_) g->hit.write(false);
  for (const auto& p : pixel_probes_) p->avalanche.write(false);
}

SystemcRun run_tof_spad_systemc(const TofSpadKernel& kernel, const PixelSelection& sel, const RateSource& rates,
                                long long frames, const std::string& vcd_base, const std::vector<TracePixel>& traced) {
  sc_core::sc_signal<int> row{"row"}, phase{"phase"};
  sc_core::sc_signal<bool> valid{"word_valid"};
  sc_core::sc_signal<std::uint32_t> word{"word"};
  TofSpadSensor dut("tof_spad", kernel, sel, rates, frames, vcd_base.empty() ? std::vector<TracePixel>{} : traced);
  dut.row_o(row), dut.phase_o(phase), dut.word_valid_o(valid), dut.word_o(word);
  SystemcRun r;
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  Waveform wave(vcd_base);  // tracing only after the zero-time start
  wave.add(row, "tof_spad.sequencer", "row");
  wave.add(phase, "tof_spad.sequencer", "phase", {{0, "idle"}, {1, "laser_cycles"}, {2, "histogram_readout"}});
  wave.add(valid, "tof_spad.histogram", "word_valid");
  wave.add(word, "tof_spad.histogram", "word");
  wave.add(dut.laser_cycle, "tof_spad.sequencer", "laser_cycle");
  wave.add(dut.write, "tof_spad.histogram", "write");
  wave.add(dut.write_column, "tof_spad.histogram", "write_column");
  wave.add(dut.write_code, "tof_spad.histogram", "write_code");
  wave.add(dut.write_count, "tof_spad.histogram", "write_count");
  for (const auto& g : dut.group_probes()) {
    const std::string scope = fmt::format("tof_spad.tdc_{}", g->group);
    wave.add(g->hit, scope, "hit");
    wave.add(g->hit_column, scope, "hit_column");
    wave.add(g->code, scope, "code");
    wave.add(g->result, scope, "result", {{0, "none"}, {1, "event"}, {2, "overflow"}, {3, "lost_busy"}});
  }
  for (const auto& p : dut.pixel_probes())
    wave.add(p->avalanche, fmt::format("tof_spad.pixel_{}_{}", p->at.row, p->at.column), "avalanche");
  // Bounded: the expected frame time plus 1%.
  const double cycles_per_frame = static_cast<double>(kernel.rows()) *
                                  (static_cast<double>(kernel.laser_cycles()) * kernel.phase_bins() +
                                   static_cast<double>(kernel.readout_words_per_row() * kernel.cycles_per_word()));
  sc_core::sc_start(dut.clock_period() * (cycles_per_frame * static_cast<double>(frames) * 1.01 + 10));
  wave.close();
  if (!dut.done()) SC_REPORT_ERROR("tof_spad", "simulation bound reached before the last frame");
  r.frames = dut.frames();
  r.words = dut.words();
  r.traced_groups_drawn_at_once = dut.traced_groups_drawn_at_once();
  r.sc_errors = static_cast<long long>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
  for (const auto& f : r.frames) r.measured_cycles += f.cycles;
  r.simulated_time_s = static_cast<double>(r.measured_cycles) / kernel.clock_Hz();
  return r;
}

SystemcRun run_tof_spad_kernel(const TofSpadKernel& kernel, const PixelSelection& sel, const RateSource& rates,
                               long long frames, const std::function<void(long long)>& progress) {
  SystemcRun r;
  for (long long fr = 0; fr < frames; ++fr) {
    r.frames.push_back(kernel.run_frame(static_cast<std::uint64_t>(fr), sel, rates));
    append_words(r.frames.back(), kernel.config().tdc.columns_per_tdc, r.words);
    r.measured_cycles += r.frames.back().cycles;
    if (progress) progress(fr + 1);
  }
  r.simulated_time_s = static_cast<double>(r.measured_cycles) / kernel.clock_Hz();
  return r;
}

}  // namespace rangesim::systemc::spad
