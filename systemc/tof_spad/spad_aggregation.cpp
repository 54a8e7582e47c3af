#include "systemc/tof_spad/spad_aggregation.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <random>

#include "systemc/common/random_stream.h"
#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::systemc::spad {

namespace {
constexpr std::uint64_t kAggregateSalt = 0x4147475245474154ULL;   // "AGGREGAT"
constexpr std::uint64_t kBackgroundSalt = 0x424b47524f554e44ULL;  // "BKGROUND"
// Echoes of cycles more than this many periods away reach a cycle with mass erfc(> 2 P / sigma):
// zero in double precision for any pulse shorter than a period.
constexpr int kSpill = 2;
// Up to this many detections in a bin are split one by one (uniform draws) instead of by binomials.
constexpr long long kFewDraws = 32;

double gauss_mass(double a, double b, double centre, double sigma) {
  if (!(sigma > 0)) return (centre >= a && centre < b) ? 1.0 : 0.0;
  const double s = sigma * std::sqrt(2.0);
  return 0.5 * (std::erfc((a - centre) / s) - std::erfc((b - centre) / s));
}

// P(X >= 2) / P(X >= 1) for X ~ Poisson(lam): a detecting cycle had more arrivals in its bin.
double more_than_one_given_one(double lam) {
  const double p1 = -std::expm1(-lam);
  if (!(p1 > 0)) return 0;
  const double tail = lam < 1e-2 ? 0.5 * lam * lam * (1 + lam / 3 + lam * lam / 12 + lam * lam * lam / 60)
                                 : std::expm1(lam) - lam;  // e^lam P(X >= 2)
  return std::min(1.0, std::exp(-lam) * tail / p1);
}

// Binomial(n, p): by inversion (one uniform, the pmf recurrence from k = 0) when n min(p, 1-p) < 30,
// else libstdc++'s rejection sampler. Both exact up to rounding; inversion avoids the rejection
// set-up (lgamma, logs) that dominated the aggregated group's time.
long long binomial(pcg32& rng, long long n, double p) {
  if (n <= 0 || !(p > 0)) return 0;
  if (p >= 1) return n;
  if (p > 0.5) return n - binomial(rng, n, 1 - p);
  if (static_cast<double>(n) * p < 30) {
    const double u = uniform_open01(rng), r = p / (1 - p);
    double pk = std::exp(static_cast<double>(n) * std::log1p(-p)), cum = pk;
    long long k = 0;
    while (cum < u && k < n) pk *= r * static_cast<double>(n - k) / static_cast<double>(k + 1), cum += pk, ++k;
    return k;
  }
  return std::binomial_distribution<long long>(n, p)(rng);
}
long long poisson(pcg32& rng, double mean) {
  if (!(mean > 0)) return 0;
  return std::poisson_distribution<long long>(mean)(rng);
}
// X ~ Poisson(lam) given X >= 2, by inversion from k = 2.
long long poisson_at_least_two(pcg32& rng, double lam) {
  const double e = std::exp(-lam), norm = 1 - e - lam * e;
  double p = e * lam * lam / 2, cum = p;
  const double u = uniform_open01(rng) * (norm > 0 ? norm : p);
  long long k = 2;
  while (cum < u && k < 100000) p *= lam / static_cast<double>(++k), cum += p;
  return k;
}
// N laser cycles of one class (group arrivals lam[i] per bin and cycle, independent cycles) added
// to g: detections per bin multinomial over bins + "no detection" (one cycle: one categorical
// draw by inversion; many: sequential binomials), each bin's detections to the columns in equal
// shares (or overflow), and the other arrivals of the detecting cycles: more in the same bin
// (zero-truncated Poisson - 1) into g.avalanches, the later bins' mean into after_mean.
void draw_cycles(pcg32& rng, const std::vector<double>& lam, long long cycles, int nc, GroupHistogram& g,
                 double& after_mean) {
  const int np = static_cast<int>(lam.size()), cpt = static_cast<int>(g.events.size());
  double lam_total = 0;
  for (double l : lam) lam_total += l;
  std::vector<long long> x_of(static_cast<size_t>(np), 0);
  if (cycles == 1) {
    const double u = uniform_open01(rng);
    double before = 0, cum = 0;
    for (int i = 0; i < np; ++i) {
      const double li = lam[static_cast<size_t>(i)];
      cum += std::exp(-before) * -std::expm1(-li);
      before += li;
      if (u < cum) {
        x_of[static_cast<size_t>(i)] = 1;
        break;
      }
    }
  } else {
    long long n_rem = cycles;
    double p_rem = 1, before = 0;
    for (int i = 0; i < np && n_rem > 0; ++i) {
      const double li = lam[static_cast<size_t>(i)];
      const double pi = std::exp(-before) * -std::expm1(-li);
      before += li;
      const long long x = p_rem > 0 ? binomial(rng, n_rem, pi / p_rem) : 0;
      n_rem -= x, p_rem -= pi;
      x_of[static_cast<size_t>(i)] = x;
    }
  }
  double after_total = lam_total;
  for (int i = 0; i < np; ++i) {
    const double li = lam[static_cast<size_t>(i)];
    after_total -= li;
    const long long x = x_of[static_cast<size_t>(i)];
    if (x == 0) continue;
    if (i < nc && x <= kFewDraws) {
      // Few detections: each to a uniformly drawn column (cheaper than cpt - 1 binomials).
      for (long long m = 0; m < x; ++m)
        ++g.events[std::min(static_cast<size_t>(uniform_open01(rng) * cpt), static_cast<size_t>(cpt) - 1)]
                  [static_cast<size_t>(i)];
    } else if (i < nc) {
      long long left = x;
      for (int c = 0; c < cpt; ++c) {
        const long long y = c + 1 == cpt ? left : binomial(rng, left, 1.0 / (cpt - c));
        g.events[static_cast<size_t>(c)][static_cast<size_t>(i)] += y, left -= y;
      }
    } else {
      g.overflows += x;
    }
    const double q = more_than_one_given_one(li);
    long long more = 0;
    if (x <= kFewDraws)
      for (long long m = 0; m < x; ++m) more += uniform_open01(rng) < q;
    else
      more = binomial(rng, x, q);
    long long extra = 0;
    for (long long m = 0; m < more; ++m) extra += poisson_at_least_two(rng, li) - 1;
    g.avalanches += x + extra;
    after_mean += static_cast<double>(x) * std::max(0.0, after_total);
  }
}

// The totals that follow from the histogram: photons, busy losses, armed counts.
void finish_counts(pcg32& rng, double after_mean, long long L, int nc, GroupHistogram& g) {
  g.avalanches += poisson(rng, after_mean);
  g.photons += g.avalanches;
  long long recorded = g.overflows;
  for (const auto& e : g.events)
    for (long long v : e) recorded += v;
  g.lost_busy = g.avalanches - recorded;
  // Armed at code i's start: every cycle whose detection (if any) came in a later or the same code.
  long long before_hits = 0;
  std::vector<long long> ev(static_cast<size_t>(nc), 0);
  for (const auto& e : g.events)
    for (int i = 0; i < nc; ++i) ev[static_cast<size_t>(i)] += e[static_cast<size_t>(i)];
  for (int i = 0; i < nc; ++i)
    g.armed[static_cast<size_t>(i)] = L - before_hits, before_hits += ev[static_cast<size_t>(i)];
}
}  // namespace

std::string spad_aggregation_blocker(const TofSpadConfig& cfg, const SpadNoise& noise, int np, int nc,
                                     int block_event_bins, int block_overflow_bins) {
  // The conditions that tie one laser cycle to the next (shared with background-only groups) ...
  if (std::string b = spad_background_blocker(cfg, noise, np, nc, block_event_bins, block_overflow_bins); !b.empty())
    return b;
  // ... and those that only an echo raises.
  const double sigma = noise.pulse_width ? cfg.laser.sigma_per_fwhm * cfg.laser.pulse_fwhm_s : 0.0;
  if (cfg.tdc.columns_per_tdc > 1 && !(sigma > 0))
    return "delta pulse on a shared TDC: simultaneous echoes go to the lowest column, not in equal shares";
  return {};
}

bool spad_group_aggregatable(const std::vector<PixelRates>& px) {
  for (const auto& p : px)
    if (!p.echoes.empty() || p.signal_Hz != px.front().signal_Hz || p.background_Hz != px.front().background_Hz ||
        p.round_trip_s != px.front().round_trip_s || p.dark_extra_Hz != px.front().dark_extra_Hz)
      return false;
  return true;
}

GroupHistogram aggregate_spad_group(const TofSpadConfig& cfg, const SpadNoise& noise, const golden::spad::TdcBins& bins,
                                    const std::vector<PixelRates>& pixels, long long laser_cycles, std::uint64_t seed,
                                    std::uint64_t frame, int row, int first_column) {
  const int cpt = static_cast<int>(pixels.size()), np = bins.phase_bins, nc = bins.codes;
  const long long L = laser_cycles;
  const double period_s = 1.0 / cfg.laser.repetition_rate_Hz;
  const PixelRates& r = pixels.front();
  const double sigma = noise.pulse_width ? cfg.laser.sigma_per_fwhm * cfg.laser.pulse_fwhm_s : 0.0;
  const double uniform_Hz =
      (noise.background ? r.background_Hz : 0.0) + (noise.dark ? cfg.spad.dark_count_rate_Hz + r.dark_extra_Hz : 0.0);
  const double mu = r.signal_Hz / cfg.laser.repetition_rate_Hz;  // signal photons per pixel and cycle
  // Bin edges as the TDC sorts phases (TofSpadKernel::phase_bin): bin 0 from the START, the last to the period.
  std::vector<double> edge(static_cast<size_t>(np) + 1);
  for (int i = 0; i <= np; ++i)
    edge[static_cast<size_t>(i)] = std::clamp(bins.edges_s[static_cast<size_t>(i)], 0.0, period_s);
  edge[0] = 0, edge[static_cast<size_t>(np)] = period_s;

  pcg32 rng = pixel_stream(pixel_stream_key(seed ^ kAggregateSalt, frame, static_cast<std::uint32_t>(row),
                                            static_cast<std::uint32_t>(first_column)));
  GroupHistogram g;
  g.events.assign(static_cast<size_t>(cpt), std::vector<long long>(static_cast<size_t>(nc), 0));
  g.armed.assign(static_cast<size_t>(nc), 0);
  g.starts = L;
  std::vector<double> lam(static_cast<size_t>(np));  // group arrivals per bin and cycle
  // Cycle classes: cycle c receives the echoes of cycles c + d, d in [max(-kSpill, -c), min(kSpill, L-1-c)];
  // the first and last kSpill cycles one by one, the interior ones together.
  struct Class {
    long long cycles;
    int dlo, dhi;
    bool first;
  };
  std::vector<Class> classes;
  for (long long c = 0; c < L; ++c) {
    if (c == kSpill && L - kSpill > c) {
      const long long n = L - 2 * kSpill;
      if (n > 0) classes.push_back({n, -kSpill, kSpill, false});
      c = std::max(c, L - kSpill) - 1;
      continue;
    }
    classes.push_back({1, static_cast<int>(std::max<long long>(-kSpill, -c)),
                       static_cast<int>(std::min<long long>(kSpill, L - 1 - c)), c == 0});
  }
  double after_mean = 0;  // arrivals after the detecting bin, summed over detecting cycles
  // Echo mass per bin and source offset d, computed once (bins more than 40 sigma away get 0).
  std::vector<std::vector<double>> echo(2 * kSpill + 1, std::vector<double>(static_cast<size_t>(np), 0.0));
  for (int d = -kSpill; d <= kSpill; ++d) {
    const double centre = d * period_s + r.round_trip_s;
    for (int i = 0; i < np; ++i) {
      const double a = edge[static_cast<size_t>(i)], b = edge[static_cast<size_t>(i) + 1];
      if (sigma > 0 && (b < centre - 40 * sigma || a > centre + 40 * sigma)) continue;
      echo[static_cast<size_t>(d + kSpill)][static_cast<size_t>(i)] = gauss_mass(a, b, centre, sigma);
    }
  }
  for (const Class& k : classes) {
    for (int i = 0; i < np; ++i) {
      const double a = edge[static_cast<size_t>(i)], b = edge[static_cast<size_t>(i) + 1];
      double s = 0;
      for (int d = k.dlo; d <= k.dhi; ++d) s += echo[static_cast<size_t>(d + kSpill)][static_cast<size_t>(i)];
      lam[static_cast<size_t>(i)] = cpt * (uniform_Hz * (b - a) + mu * s);
    }
    draw_cycles(rng, lam, k.cycles, nc, g, after_mean);
    if (k.first) {
      // Echo photons of cycle 0 (and the next) before the first START: arrivals, never avalanches.
      double s = 0;
      for (int d = 0; d <= k.dhi; ++d) s += gauss_mass(-1e300, 0.0, d * period_s + r.round_trip_s, sigma);
      g.photons += poisson(rng, cpt * mu * s);
    }
  }
  finish_counts(rng, after_mean, L, nc, g);
  g.aggregated = true;
  return g;
}

std::string spad_background_blocker(const TofSpadConfig& cfg, const SpadNoise& noise, int np, int nc,
                                    int block_event_bins, int block_overflow_bins) {
  // The aggregation conditions, less the one about simultaneous echoes (there is no echo).
  if (noise.afterpulse && cfg.spad.afterpulse_probability > 0)
    return fmt::format("afterpulses (spad.afterpulse_probability = {:g}) tie an avalanche to the next ones",
                       cfg.spad.afterpulse_probability);
  if (cfg.spad.dead_time_s > 0)
    return fmt::format("SPAD dead time {:g} s: an avalanche late in a cycle blinds the next one", cfg.spad.dead_time_s);
  if (noise.jitter && cfg.spad.jitter_sigma_s > 0)
    return fmt::format("jitter {:g} s: avalanches cross cycle edges, so cycles are not independent",
                       cfg.spad.jitter_sigma_s);
  if (nc > 0 && nc - 1 + block_event_bins > np)
    return fmt::format("TDC blocked {} bins after an event: a late event carries into the next cycle",
                       block_event_bins);
  if (nc < np && np - 1 + block_overflow_bins > np)
    return fmt::format("TDC blocked {} bins after an overflow: carries into the next cycle", block_overflow_bins);
  return {};
}

bool spad_group_background_only(const std::vector<PixelRates>& px) {
  for (const auto& p : px) {
    if (p.signal_Hz != 0 || p.background_Hz != px.front().background_Hz || p.dark_extra_Hz != px.front().dark_extra_Hz)
      return false;
    for (const SpadEcho& e : p.echoes)
      if (e.signal_Hz != 0) return false;
  }
  return true;
}

GroupHistogram background_spad_group(const TofSpadConfig& cfg, const SpadNoise& noise,
                                     const golden::spad::TdcBins& bins, const std::vector<PixelRates>& pixels,
                                     long long laser_cycles, std::uint64_t seed, std::uint64_t frame, int row,
                                     int first_column) {
  const int cpt = static_cast<int>(pixels.size()), np = bins.phase_bins, nc = bins.codes;
  const double period_s = 1.0 / cfg.laser.repetition_rate_Hz;
  const double uniform_Hz = (noise.background ? pixels.front().background_Hz : 0.0) +
                            (noise.dark ? cfg.spad.dark_count_rate_Hz + pixels.front().dark_extra_Hz : 0.0);
  GroupHistogram g;
  g.events.assign(static_cast<size_t>(cpt), std::vector<long long>(static_cast<size_t>(nc), 0));
  g.armed.assign(static_cast<size_t>(nc), 0);
  g.starts = laser_cycles;
  g.background_class = true;
  // Group arrivals per bin and cycle, the same in every cycle (no echo, no edge cycles): bins as
  // the TDC sorts phases (bin 0 from the START, the last to the period).
  std::vector<double> lam(static_cast<size_t>(np));
  for (int i = 0; i < np; ++i) {
    const double a = i == 0 ? 0.0 : std::clamp(bins.edges_s[static_cast<size_t>(i)], 0.0, period_s);
    const double b = i + 1 == np ? period_s : std::clamp(bins.edges_s[static_cast<size_t>(i) + 1], 0.0, period_s);
    lam[static_cast<size_t>(i)] = cpt * uniform_Hz * (b - a);
  }
  pcg32 rng = pixel_stream(pixel_stream_key(seed ^ kBackgroundSalt, frame, static_cast<std::uint32_t>(row),
                                            static_cast<std::uint32_t>(first_column)));
  double after_mean = 0;
  draw_cycles(rng, lam, laser_cycles, nc, g, after_mean);
  finish_counts(rng, after_mean, laser_cycles, nc, g);
  return g;
}

}  // namespace rangesim::systemc::spad
