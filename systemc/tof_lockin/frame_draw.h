#pragma once
// The merged draws of an aggregated tof-lockin frame (config simulation.merged_draws; docs/
// tof-lockin-clock.md, "Noise"): draw what the ADC codes need, exactly.
//   - The frame's photo and dark charge on an FD is Poisson (the aggregation) and so is the offset
//     charge C V_offset / q (offset_charge.shot_noise): their sum is one Poisson count of the
//     summed mean (independent Poisson counts add).
//   - kTC noise sits on the FD before the V_sat clip and read noise after it; where the FD swing
//     cannot reach V_sat (probability < 2^-60, a Bernstein bound on the count and a 9.1 sigma
//     bound on kTC) the clip is the identity and the two are one normal of the summed variance at
//     the ADC input. Otherwise they are drawn apart, as on the unmerged path.
//   - The count comes from an alias table of its mean where the kernel shares few means among
//     many draws (alias_table.h), else from PTRS with its constants set once
//     (systemc/common/poisson_sampler.h); the normals from the ziggurat (normal_ziggurat.h); all
//     words from one counter-based stream per pixel (counter_stream.h), keyed (seed, row,
//     column), each frame's words from word frame << 32 on.
// Every step is exact in distribution, so the codes have the law of the unmerged draws; the
// proofs are statistical (LockinMergedDraws.* in tests/skipping/test_lockin_merged.cpp).
#include <cstdint>
#include <map>
#include <memory>

#include "core/tof_lockin/config.h"
#include "systemc/common/poisson_sampler.h"
#include "systemc/tof_lockin/counter_stream.h"
#include "systemc/tof_lockin/kernel_types.h"
#include "systemc/tof_lockin/alias_table.h"

namespace rangesim::systemc::lockin {

// The law of one tap's frame: its count and its normal noise.
struct TapFrameLaw {
  double count_mean_e = 0;              // frame charge + offset charge, electrons
  const PoissonAlias* table = nullptr;  // the count by table, or
  PoissonSampler ptrs;                  // by PTRS
  double offset_e = 0;                  // mean offset charge inside the count (V_offset carries it)
  bool may_saturate = true;             // the swing can reach V_sat: kTC and read noise drawn apart
  double sigma_V = 0;                   // else: one normal at the ADC input, sqrt(A_sf^2 kTC^2 + read^2)
  double ktc_fd_V = 0, read_V = 0;      // apart: kTC at the FD, read noise at the ADC input

  // One count of the law (above 1e15 electrons Normal(mean, mean), as the unmerged path).
  double count(CounterStream& s) const { return table ? static_cast<double>((*table)(s)) : count_without_table(s); }
  double count_without_table(CounterStream& s) const;
};

// Whether the FD swing of tap `tap` can reach V_sat when its count has mean `count_mean_e` of
// which `offset_e` is the offset charge: false when P(swing >= V_sat) < 2^-60.
bool swing_may_saturate(const TofLockinConfig& cfg, int tap, double count_mean_e, double offset_e);

// The laws of a kernel's taps, with the alias tables they share.
class FrameLaws {
 public:
  // A table of ~19 sqrt(mean) entries costs about as much to build as PTRS draws a third of that
  // many counts: WhenTheyPay builds one where its mean is drawn at least table entries / 2 times.
  // All tables together hold at most this many entries (a few tens of MB).
  static constexpr std::size_t kMaxTableEntries = std::size_t{1} << 22;
  // frame_mean_e: 2 per pixel (FD1, FD2, without the offset charge); offset_e: each FD's mean
  // offset charge (0 without its shot noise); frames: how many frames draw these laws (each tap
  // once per frame).
  void build(const TofLockinConfig& cfg, const std::vector<double>& frame_mean_e, const double offset_e[2],
             PoissonTables tables, long long frames);
  // The two taps' laws of pixel p.
  const TapFrameLaw* pixel(std::size_t p) const { return &laws_[2 * pair_[p]]; }
  bool uses_tables() const { return !tables_.empty(); }

 private:
  std::vector<TapFrameLaw> laws_;    // distinct (FD1, FD2) pairs, two laws each (uniform scenes: one)
  std::vector<std::uint32_t> pair_;  // each pixel's pair
  std::map<double, std::unique_ptr<PoissonAlias>> tables_;
};

}  // namespace rangesim::systemc::lockin
