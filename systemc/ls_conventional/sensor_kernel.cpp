#include "systemc/ls_conventional/sensor_kernel.h"

#include <stdexcept>
#include <string>

namespace rangesim::systemc {

int FrameResult::rows_detected() const {
  int n = 0;
  for (const auto& r : rows) n += r.valid ? 1 : 0;
  return n;
}

namespace {
const LsConventionalConfig& checked(const LsConventionalConfig& c) {
  if (c.search.address_bits != c.timing.address_bits ||
      c.search.addresses_per_sampling != c.timing.addresses_per_sampling || c.search.columns != c.pixel.columns)
    throw std::invalid_argument(
        "LsConventionalSensorKernel: search (columns, address_bits, addresses_per_sampling) must equal pixel.columns "
        "and the timing's address_bits / addresses_per_sampling");
  return c;
}
}  // namespace

LsConventionalSensorKernel::LsConventionalSensorKernel(const LsConventionalConfig& config,
                                                       const SensorKernelOptions& options, StimulusSource source)
    : config_(checked(config)),
      options_(options),
      sequencer_(config.timing, config.multisampling.samplings),
      pixels_(config, options.pixel, std::move(source)) {
  const int rows = pixels_.rows();  // the band of rows this kernel simulates
  search_.reserve(static_cast<std::size_t>(rows));
  centre_.reserve(static_cast<std::size_t>(rows));
  for (int r = 0; r < rows; ++r) {
    search_.emplace_back(config.search, config.timing.search_cycles);
    centre_.emplace_back(config.search.address_bits);
  }
  search_pins_.resize(static_cast<std::size_t>(rows));
}

void LsConventionalSensorKernel::settle() {
  const MultisamplingSequencerPins p = sequencer_.pins();
  pixels_.control(p.pix_reset, p.frame, p.sampling);
}

void LsConventionalSensorKernel::reset() { reset_at_frame(0); }

void LsConventionalSensorKernel::reset_at_frame(std::uint64_t frame) {
  sequencer_.tick(true);
  sequencer_.advance_to(static_cast<long long>(frame) * sequencer_.frame_cycles());
  for (auto& s : search_) s.tick(true, false, ActivationRow{});
  for (auto& c : centre_) c.clear();
  centres_clear_ = true;
  phase_cycles_ = {};
  settle();
}

void LsConventionalSensorKernel::account(const MultisamplingSequencerPins& p, long long cycles) {
  phase_cycles_[static_cast<std::size_t>(p.phase)] += cycles;
}

template <class F>
void LsConventionalSensorKernel::for_each_extent(F f) const {
  for (std::size_t r = 0; r < centre_.size(); ++r) f(r, pixels_.extent(static_cast<int>(r)));
}

void LsConventionalSensorKernel::finish_frame(const MultisamplingSequencerPins& p) {
  FrameResult fr;
  fr.frame = p.frame;
  // The frame result's memory was asked for one frame access ahead (prepare_next_result), with room
  // for the whole array's rows: a row band's results are joined to the others' (run_sensor_kernel)
  // without a new allocation.
  const std::size_t rows = centre_.size();
  fr.rows = std::move(next_rows_);
  fr.extents = std::move(next_extents_);
  fr.rows.reserve(static_cast<std::size_t>(config_.pixel.rows));
  if (options_.frame_extents) fr.extents.reserve(static_cast<std::size_t>(config_.pixel.rows));
  const std::uint32_t* pattern = nullptr;
  const int *first = nullptr, *last = nullptr;
  std::size_t patterns = 0;
  if (centres_deferred_ && pixels_.extent_patterns(pattern, first, last, patterns)) {
    // Every sampling's search result into the centre processors at once. A row's processor was
    // cleared at the frame access's reset and takes nothing before this, so its pins are those of a
    // clear processor given its extent pattern's results: worked out once per pattern (rows share
    // them), AddressSearchKernel::evaluate's found, left and right of each sampling summed without a
    // branch on found. The rows' own processors stay clear.
    const std::size_t N = static_cast<std::size_t>(config_.multisampling.samplings);
    pattern_pins_.resize(patterns);
    pattern_extent_.resize(patterns);
    for (std::size_t p = 0; p < patterns; ++p) {
      std::uint32_t sum = 0;
      int found = 0;
      for (std::size_t k = p * N; k < (p + 1) * N; ++k) {
        const int hit = first[k] >= 0;
        sum += static_cast<std::uint32_t>(hit * (first[k] + last[k]));
        found += hit;
      }
      CentreProcessorKernel centre(config_.search.address_bits);
      centre.accumulate_total(sum, found);
      pattern_pins_[p] = centre.pins();
      pattern_extent_[p] = ActivationExtent{first[p * N + N - 1], last[p * N + N - 1]};
    }
    // Copied from the patterns straight into the result (elements read from memory: no
    // store-to-load forward to fail, as a struct built on the stack would).
    fr.rows.resize(rows);
    CentreProcessorPins* pins = fr.rows.data();
    for (std::size_t r = 0; r < rows; ++r) pins[r] = pattern_pins_[pattern[r]];
    if (options_.frame_extents) {
      fr.extents.resize(rows);
      ActivationExtent* extents = fr.extents.data();
      for (std::size_t r = 0; r < rows; ++r) extents[r] = pattern_extent_[pattern[r]];
    }
  } else {
    pins_scratch_.resize(rows);
    for (std::size_t r = 0; r < rows; ++r) pins_scratch_[r] = centre_[r].pins();
    fr.rows.assign(pins_scratch_.begin(), pins_scratch_.end());
    if (options_.frame_extents) {
      fr.extents.resize(rows);
      for_each_extent([&](std::size_t r, const ActivationExtent& e) { fr.extents[r] = e; });
    }
  }
  centres_deferred_ = false;
  prepare_next_result();
  fr.end_cycle = sequencer_.cycle() + 1;
  fr.phase_cycles = phase_cycles_;
  for (long long c : phase_cycles_) fr.cycles += c;
  results_.push_back(std::move(fr));
  phase_cycles_ = {};
}

void LsConventionalSensorKernel::prepare_next_result() {
  // The next frame result's memory, asked for and filled now: a map's results (2.2 MB of pins) are
  // not in the cache, and stores into them wait for their lines. A fill in one sequential sweep
  // fetches them faster than the copy's stores at the frame's end or prefetches did (2.7-2.9% of
  // the map).
  const std::size_t rows = static_cast<std::size_t>(config_.pixel.rows);
  next_rows_.reserve(rows);
  next_rows_.resize(centre_.size());
  if (!options_.frame_extents) return;
  next_extents_.reserve(rows);
  next_extents_.resize(centre_.size());
}

void LsConventionalSensorKernel::tick() {
  const MultisamplingSequencerPins p = sequencer_.pins();
  account(p, 1);
  const std::size_t rows = search_.size();
  for (std::size_t r = 0; r < rows; ++r) search_pins_[r] = search_[r].pins();
  if (p.search_start) {
    for (std::size_t r = 0; r < rows; ++r)
      if (!search_[r].idle())
        errors_.push_back("frame " + std::to_string(p.frame) + " sampling " + std::to_string(p.sampling) + " row " +
                          std::to_string(pixels_.first_row() + static_cast<int>(r)) +
                          ": search start while the row's search is busy");
  }
  if (p.frame_done) {
    for (std::size_t r = 0; r < rows; ++r)
      if (search_pins_[r].busy)
        errors_.push_back("frame " + std::to_string(p.frame) + " row " +
                          std::to_string(pixels_.first_row() + static_cast<int>(r)) +
                          ": address search still busy at the end of the frame access");
    finish_frame(p);
  }
  for (std::size_t r = 0; r < rows; ++r) search_[r].tick(false, p.search_start, pixels_.row(static_cast<int>(r)));
  for (std::size_t r = 0; r < rows; ++r) centre_[r].tick(p.pix_reset, search_pins_[r]);
  centres_clear_ = false;
  sequencer_.tick(false);
  ++ticks_;
  settle();
}

void LsConventionalSensorKernel::step() {
  if (!options_.event_skipping) {
    tick();
    return;
  }
  const MultisamplingSequencerPins p = sequencer_.pins();
  const long long next = sequencer_.next_event_cycle();
  account(p, next - sequencer_.cycle());
  if (p.frame_done) finish_frame(p);  // a one-cycle interval: the frame's last cycle
  if (p.pix_reset && !centres_clear_) {  // (the deferred frames leave them clear)
    for (auto& c : centre_) c.clear();
    centres_clear_ = true;
  }
  if (p.search_start) {
    if (pixels_.has_extent_patterns()) {
      centres_deferred_ = true;  // finish_frame works out every sampling's results at once
    } else {
      for_each_extent([&](std::size_t r, const ActivationExtent& e) { centre_[r].accumulate(search_[r].evaluate(e)); });
      centres_clear_ = false;
    }
  }
  sequencer_.advance_to(next);
  settle();
}

std::vector<FrameResult> LsConventionalSensorKernel::run_frames(long long frames, long long cycle_budget) {
  const std::size_t first = results_.size();
  advance_frames(frames, cycle_budget);
  return {results_.begin() + static_cast<std::ptrdiff_t>(first), results_.end()};
}

void LsConventionalSensorKernel::advance_frames(long long frames, long long cycle_budget) {
  const std::size_t target = results_.size() + static_cast<std::size_t>(frames);
  if (cycle_budget <= 0) cycle_budget = 2 * sequencer_.frame_cycles() * (frames + 1);
  const long long limit = sequencer_.cycle() + cycle_budget;
  while (results_.size() < target) {
    if (sequencer_.cycle() >= limit)
      throw std::runtime_error("LsConventionalSensorKernel: cycle budget of " + std::to_string(cycle_budget) +
                               " cycles exhausted before " + std::to_string(frames) + " frame accesses completed");
    step();
  }
}

}  // namespace rangesim::systemc
