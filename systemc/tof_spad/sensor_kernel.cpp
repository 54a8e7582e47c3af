#include "systemc/tof_spad/sensor_kernel.h"

#include "golden/tof_spad/validity.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/physics.h"
#include "golden/tof_spad/pile_up.h"
#include "golden/tof_spad/point_model.h"
#include "systemc/tof_spad/spad_aggregation.h"
#include "systemc/tof_spad/tdc_kernel.h"

namespace rangesim::systemc::spad {

TofSpadKernel::TofSpadKernel(const TofSpadConfig& cfg, int rows, int columns, const TofSpadKernelOptions& opt)
    : cfg_(cfg), rows_(rows), columns_(columns), opt_(opt) {
  if (rows < 1 || columns < 1 || cfg.tdc.columns_per_tdc < 1 || columns % cfg.tdc.columns_per_tdc != 0)
    throw std::invalid_argument("tof-spad kernel: columns must be a multiple of tdc.columns_per_tdc");
  const golden::spad::SpadModel model(cfg);  // same bins, share and blocking as the golden model
  bins_ = model.bins();
  est_ = model.estimator();
  share_ = model.share();
  const golden::spad::PileUpInput in =
      model.pile_up_input(std::vector<double>(static_cast<size_t>(bins_.phase_bins), 0.0));
  block_event_bins_ = in.block_event_bins;
  block_overflow_bins_ = in.block_overflow_bins;
  laser_cycles_ = laser_cycles_per_row(cfg);
  cycles_per_word_ = cycles_per_histogram_word(cfg);
  aggregation_blocker_ = spad_aggregation_blocker(cfg_, opt_.noise, bins_.phase_bins, bins_.codes, block_event_bins_,
                                                  block_overflow_bins_);
  background_blocker_ =
      spad_background_blocker(cfg_, opt_.noise, bins_.phase_bins, bins_.codes, block_event_bins_, block_overflow_bins_);
}

std::optional<GroupHistogram> TofSpadKernel::simulate_group_background(std::uint64_t frame, int row, int group,
                                                                       const RateSource& rates) const {
  const int cpt = cfg_.tdc.columns_per_tdc;
  std::vector<PixelRates> px;
  for (int k = 0; k < cpt; ++k) px.push_back(rates(row, group * cpt + k));
  if (!spad_group_background_only(px)) return std::nullopt;
  const bool no_arrivals = !(opt_.noise.background && px.front().background_Hz > 0) &&
                           !(opt_.noise.dark && cfg_.spad.dark_count_rate_Hz + px.front().dark_extra_Hz > 0);
  if (!background_blocker_.empty() && !no_arrivals) return std::nullopt;
  return background_spad_group(cfg_, opt_.noise, bins_, px, laser_cycles_, opt_.seed, frame, row, group * cpt);
}

GroupHistogram TofSpadKernel::simulate_group_aggregated(std::uint64_t frame, int row, int group,
                                                        const RateSource& rates) const {
  const int cpt = cfg_.tdc.columns_per_tdc;
  std::vector<PixelRates> px;
  for (int k = 0; k < cpt; ++k) px.push_back(rates(row, group * cpt + k));
  GroupHistogram g =
      aggregate_spad_group(cfg_, opt_.noise, bins_, px, laser_cycles_, opt_.seed, frame, row, group * cpt);
  return g;
}

int TofSpadKernel::phase_bin(double phase_s) const {
  // Coarse counter: the clock cycle of the hit; fine interpolation: position between the actual
  // (INL/DNL) edges around it. Equivalent to a search on the golden edges.
  const auto& e = bins_.edges_s;
  const int np = bins_.phase_bins;
  int i = std::clamp(static_cast<int>(phase_s / bins_.lsb_s), 0, np - 1);
  while (i > 0 && phase_s < e[static_cast<size_t>(i)]) --i;
  while (i < np - 1 && phase_s >= e[static_cast<size_t>(i) + 1]) ++i;
  return i;
}

GroupHistogram TofSpadKernel::simulate_group(std::uint64_t frame, int row, int group, const RateSource& rates,
                                             const HitObserver* observer) const {
  if (!opt_.event_skipping) return simulate_group_ticked(frame, row, group, rates);
  if (opt_.sparse)
    if (auto g = simulate_group_background(frame, row, group, rates)) return *g;
  if (opt_.aggregate && aggregation_blocker_.empty()) {
    std::vector<PixelRates> pr;
    for (int k = 0; k < cfg_.tdc.columns_per_tdc; ++k) pr.push_back(rates(row, group * cfg_.tdc.columns_per_tdc + k));
    if (spad_group_aggregatable(pr)) return simulate_group_aggregated(frame, row, group, rates);
  }
  const int cpt = cfg_.tdc.columns_per_tdc, np = bins_.phase_bins, nc = bins_.codes;
  std::vector<SpadPixelKernel> px;
  px.reserve(static_cast<size_t>(cpt));
  for (int k = 0; k < cpt; ++k) {
    const int col = group * cpt + k;
    px.emplace_back(cfg_, rates(row, col), opt_.noise, laser_cycles_, opt_.seed, frame, static_cast<std::uint32_t>(row),
                    static_cast<std::uint32_t>(col));
  }
  // The shared TDC, hit by hit (systemc/tof_spad/tdc_kernel.h).
  TdcGroupKernel tdc(np, nc, block_event_bins_, block_overflow_bins_, laser_cycles_, cpt);
  for (;;) {
    int who = -1;
    SpadTime t = SpadTime::never_time();
    for (int k = 0; k < cpt; ++k)  // arbitration: the earliest avalanche of the group
      if (px[static_cast<size_t>(k)].peek() < t) t = px[static_cast<size_t>(k)].peek(), who = k;
    if (who < 0) break;
    px[static_cast<size_t>(who)].pop();
    if (t.cycle < 0) {
      tdc.lose();
      continue;
    }  // jittered before the first START
    if (t.cycle >= laser_cycles_) break;
    const TdcHit hit = tdc.hit(who, t.cycle, phase_bin(t.offset_s));  // cycle and offset: exact at any integration time
    if (observer) (*observer)(who, hit);
  }
  GroupHistogram g = tdc.finish();
  for (const auto& p : px) g.avalanches += p.avalanches(), g.photons += p.photons();
  return g;
}

GroupHistogram TofSpadKernel::simulate_group_ticked(std::uint64_t frame, int row, int group,
                                                    const RateSource& rates) const {
  const int cpt = cfg_.tdc.columns_per_tdc, np = bins_.phase_bins, nc = bins_.codes;
  std::vector<SpadPixelKernel> px;
  px.reserve(static_cast<size_t>(cpt));
  for (int k = 0; k < cpt; ++k) {
    const int col = group * cpt + k;
    px.emplace_back(cfg_, rates(row, col), opt_.noise, laser_cycles_, opt_.seed, frame, static_cast<std::uint32_t>(row),
                    static_cast<std::uint32_t>(col));
  }
  GroupHistogram g;
  g.events.assign(static_cast<size_t>(cpt), std::vector<long long>(static_cast<size_t>(nc), 0));
  g.armed.assign(static_cast<size_t>(nc), 0);
  // Arbitration: the pixel with the earliest pending avalanche (-1: none left).
  auto earliest = [&](SpadTime& t) {
    int who = -1;
    t = SpadTime::never_time();
    for (int k = 0; k < cpt; ++k)
      if (px[static_cast<size_t>(k)].peek() < t) t = px[static_cast<size_t>(k)].peek(), who = k;
    return who;
  };
  // Absolute code (cycle * Np + phase bin) of an avalanche time.
  auto abs_bin_of = [&](const SpadTime& t) { return t.cycle * np + phase_bin(t.offset_s); };
  SpadTime t;
  // Avalanches jittered before the first START find the TDC not yet running.
  for (int who = earliest(t); who >= 0 && t.cycle < 0; who = earliest(t))
    px[static_cast<size_t>(who)].pop(), ++g.lost_busy;
  const long long end_bin = laser_cycles_ * np;
  long long armed_from = 0;  // TDC armed in cycles >= armed_from (busy / stopped before)
  for (long long c = 0; c < end_bin; ++c) {
    const int phase = static_cast<int>(c % np);
    const bool armed = c >= armed_from;  // state during this cycle, before its hits
    for (int who = earliest(t); who >= 0; who = earliest(t)) {
      if (t.cycle >= laser_cycles_) break;  // after the integration
      const long long abs_bin = abs_bin_of(t);
      if (abs_bin > c) break;  // a later cycle
      px[static_cast<size_t>(who)].pop();
      if (abs_bin < armed_from) {
        ++g.lost_busy;
        continue;
      }
      long long rearm;
      if (phase < nc) {
        ++g.events[static_cast<size_t>(who)][static_cast<size_t>(phase)];
        rearm = abs_bin + block_event_bins_;
      } else {
        ++g.overflows;
        rearm = abs_bin + block_overflow_bins_;
      }
      armed_from = std::max(rearm, (c / np + 1) * np);  // a stopped TDC waits for the next START
    }
    if (armed && phase < nc) ++g.armed[static_cast<size_t>(phase)];
  }
  // The event-driven loop consumes the first avalanche past the integration before it stops.
  if (const int who = earliest(t); who >= 0) px[static_cast<size_t>(who)].pop();
  g.starts = laser_cycles_;
  for (const auto& p : px) g.avalanches += p.avalanches(), g.photons += p.photons();
  return g;
}

golden::spad::HistogramCounts TofSpadKernel::counts(const std::vector<long long>& events,
                                                    const std::vector<long long>& armed) const {
  golden::spad::HistogramCounts h;
  h.events.assign(events.begin(), events.end());
  h.armed.assign(armed.begin(), armed.end());
  h.share = share_;
  return h;
}

std::optional<double> TofSpadKernel::estimate(const std::vector<long long>& events,
                                              const std::vector<long long>& armed) const {
  return golden::spad::estimate_time_s(counts(events, armed), bins_, est_);
}

PixelResult TofSpadKernel::make_pixel(int row, int column, const GroupHistogram& g, int index) const {
  PixelResult p;
  p.row = row, p.column = column;
  p.events = g.events[static_cast<size_t>(index)];
  p.armed = g.armed;
  const golden::spad::HistogramCounts h = counts(p.events, p.armed);
  int peak = 0;
  p.time_s = golden::spad::estimate_time_s(h, bins_, est_, &peak);
  p.range_m = p.time_s ? 0.5 * phys::kSpeedOfLight_m_per_s * *p.time_s : NAN;
  if (p.time_s) p.significance = golden::spad::peak_significance(h, est_, peak).sigma;
  return p;
}

void TofSpadKernel::count_group(FrameResult& f, int row, int group, const GroupHistogram& g,
                                const RateSource& rates) const {
  f.avalanches += g.avalanches, f.photons += g.photons;
  if (g.background_class) {
    ++f.groups_background;
    return;
  }
  ++(g.aggregated ? f.groups_aggregated : f.groups_per_cycle);
  if (opt_.sparse && !g.aggregated) {
    std::vector<PixelRates> px;
    for (int k = 0; k < cfg_.tdc.columns_per_tdc; ++k) px.push_back(rates(row, group * cfg_.tdc.columns_per_tdc + k));
    if (spad_group_background_only(px)) ++f.groups_background_per_cycle;
  }
}

FrameResult TofSpadKernel::run_frame(std::uint64_t frame, const PixelSelection& sel, const RateSource& rates) const {
  FrameResult f;
  f.frame = static_cast<long long>(frame);
  f.phase_cycles.assign(2, 0);
  const int cpt = cfg_.tdc.columns_per_tdc;
  for (int row = 0; row < rows_; ++row) {
    const bool simulated = std::find(sel.rows.begin(), sel.rows.end(), row) != sel.rows.end();
    long long starts = laser_cycles_;
    if (simulated) {
      for (int gi = sel.first_group; gi < sel.first_group + sel.groups; ++gi) {
        const GroupHistogram g = simulate_group(frame, row, gi, rates);
        starts = g.starts;
        count_group(f, row, gi, g, rates);
        for (int k = 0; k < cpt; ++k) f.pixels.push_back(make_pixel(row, gi * cpt + k, g, k));
      }
    }
    f.phase_cycles[0] += starts * bins_.phase_bins;  // the coarse counter runs Np cycles per START
    for (long long w = 0; w < readout_words_per_row(); ++w) f.phase_cycles[1] += cycles_per_word_;
  }
  f.cycles = f.phase_cycles[0] + f.phase_cycles[1];
  return f;
}

}  // namespace rangesim::systemc::spad
