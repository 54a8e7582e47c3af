#include "systemc/ls_conventional/activation_sampler.h"

#include <algorithm>
#include <cmath>
#include <mutex>

#include "golden/common/activation_cdf.h"
#include "golden/common/pixel.h"
#include "systemc/common/gamma_sampler.h"
#include "systemc/common/poisson_sampler.h"

namespace rangesim::systemc {

namespace {
constexpr std::size_t kMemoEntries = 16;    // distinct thresholds kept (a scene has one per background)
constexpr std::size_t kSharedEntries = 64;  // the same, process-wide
double Phi(double z) { return 0.5 * std::erfc(-z * M_SQRT1_2); }

// The process-wide store of bounds and tables (ExactActivation::entry). Building them is most of
// a kernel's set-up (about 1 ms for the preset's threshold, against 7 for a whole map).
struct SharedEntry {
  ActivationModel model;
  double threshold_V = 0;
  ActivationBounds b;
  std::shared_ptr<const ActivationTable> table;
  std::shared_ptr<const golden::ActivationTable> exact;
};

bool same_model(const ActivationModel& a, const ActivationModel& b) {
  return a.shot == b.shot && a.ktc_V == b.ktc_V && a.read_V == b.read_V && a.electrons_per_V == b.electrons_per_V &&
         a.gain == b.gain && a.saturation_V == b.saturation_V && a.samplings == b.samplings;
}

std::mutex& shared_mutex() {
  static std::mutex m;
  return m;
}

std::vector<SharedEntry>& shared_entries() {
  static std::vector<SharedEntry> v;
  return v;
}

SharedEntry* find_shared(const ActivationModel& m, double threshold_V) {  // shared_mutex() held
  for (SharedEntry& e : shared_entries())
    if (e.threshold_V == threshold_V && same_model(e.model, m)) return &e;
  return nullptr;
}

void publish(const ActivationModel& m, const ThresholdEntry& e) {
  std::lock_guard<std::mutex> lock(shared_mutex());
  if (SharedEntry* s = find_shared(m, e.threshold_V)) {
    if (!s->table) s->table = e.table;
    return;
  }
  std::vector<SharedEntry>& v = shared_entries();
  if (v.size() >= kSharedEntries) v.erase(v.begin());
  v.push_back({m, e.threshold_V, e.b, e.table, e.exact});
}
}  // namespace

ExactActivation::ExactActivation(const ActivationModel& model) : m_(model) {
  sigma_V_ = std::hypot(m_.ktc_V, m_.read_V);
}

void ExactActivation::probability(double lambda, const ThresholdEntry& e, double& p, double& q) const {
  const double t_e = e.threshold_V / m_.gain * m_.electrons_per_V, s_e = sigma_V_ * m_.electrons_per_V;
  if (m_.shot) {
    const double mean_e = std::max(lambda, 0.0);
    const golden::ActivationProbability a =
        e.exact ? (*e.exact)(mean_e) : golden::activation_probability(mean_e, t_e, s_e);
    p = a.p, q = a.q;
    return;
  }
  // No shot noise: the swing is lambda / c exactly; only the Gaussian static noise is random.
  if (s_e <= 0) {
    p = lambda >= t_e ? 1 : 0, q = 1 - p;
    return;
  }
  p = Phi((lambda - t_e) / s_e), q = Phi((t_e - lambda) / s_e);
}

ThresholdEntry& ExactActivation::entry(double threshold_V) {
  for (ThresholdEntry& e : memo_)
    if (e.threshold_V == threshold_V) return e;
  if (memo_.size() >= kMemoEntries) memo_.erase(memo_.begin());
  ThresholdEntry e;
  e.threshold_V = threshold_V;
  bool known = false;
  {
    std::lock_guard<std::mutex> lock(shared_mutex());
    if (const SharedEntry* s = find_shared(m_, threshold_V)) {
      e.b = s->b;
      e.table = s->table;
      e.exact = s->exact;
      known = true;
    }
  }
  if (!known) {
    if (m_.shot && sigma_V_ > 0)
      e.exact = std::make_shared<const golden::ActivationTable>(threshold_V / m_.gain * m_.electrons_per_V,
                                                                sigma_V_ * m_.electrons_per_V);
    e.b = compute_bounds(e);
    publish(m_, e);
  }
  memo_.push_back(std::move(e));
  return memo_.back();
}

ActivationBounds ExactActivation::compute_bounds(const ThresholdEntry& e) const {
  // Bisection on lambda, started from the Gaussian picture (transition width s = sqrt(t + sigma^2))
  // and widened until the bracket holds; each end kept on its certain side, so rounding only
  // narrows the certain ranges.
  const double threshold_V = e.threshold_V;
  const double t = threshold_V / m_.gain * m_.electrons_per_V, s_e = sigma_V_ * m_.electrons_per_V;
  auto p_of = [&](double l) {
    double p, q;
    probability(l, e, p, q);
    return p;
  };
  auto q_of = [&](double l) {
    double p, q;
    probability(l, e, p, q);
    return q;
  };
  ActivationBounds b;
  const double width = std::sqrt(std::max(t, 0.0) + s_e * s_e) + 1;
  if (p_of(0) <= kComputedTail) {
    double lo = std::max(0.0, t - 12 * width);
    if (p_of(lo) > kComputedTail) lo = 0;
    double hi = std::max(t, lo);
    while (hi - lo > 0.01 * width) {
      const double mid = 0.5 * (lo + hi);
      (p_of(mid) <= kComputedTail ? lo : hi) = mid;
    }
    b.never_upto_e = lo;
  }
  // Certain firing needs the saturation to be harmless: A (V_sat + r) >= theta almost surely.
  const double sat_room_V = m_.saturation_V - threshold_V / m_.gain;
  const bool sat_harmless = m_.read_V > 0 ? Phi(-sat_room_V / m_.read_V) <= 1e-19 : sat_room_V >= 0;
  b.saturation_harmless = sat_harmless;
  if (sat_harmless) {
    double lo = std::max(t, 0.0), hi = lo + 12 * width;
    for (int i = 0; i < 60 && q_of(hi) > kComputedTail; ++i) hi = lo + 2 * (hi - lo);
    if (q_of(hi) <= kComputedTail) {
      while (hi - lo > 0.01 * width) {
        const double mid = 0.5 * (lo + hi);
        (q_of(mid) <= kComputedTail ? hi : lo) = mid;
      }
      b.always_from_e = hi;
    }
  }
  b.invertible = m_.shot && s_e > 0 && sat_harmless && b.always_from_e < 1e300 &&
                 ActivationTable::intervals_for(s_e, std::max(b.never_upto_e, 0.0), b.always_from_e) <=
                     ActivationTable::kMaxIntervals;
  return b;
}

double ExactActivation::lambda_e(const PixelDrive& d, int k) const {
  if (m_.shot) return k * d.mean_step_e;
  const double t_over_T = static_cast<double>(k) / m_.samplings;
  return golden::pixel_swing_V(d.signal_V, d.profile, d.background_V, d.dark_V, t_over_T) * m_.electrons_per_V;
}

int ExactActivation::certain_first_firing(const PixelDrive& d, const ActivationBounds& b) const {
  // lambda_k grows with k: the outcome is certain when no lambda_k falls between the bounds.
  const int N = m_.samplings;
  if (lambda_e(d, N) <= b.never_upto_e) return 0;
  for (int k = 1; k <= N; ++k) {
    const double l = lambda_e(d, k);
    if (l >= b.always_from_e) return k;
    if (l > b.never_upto_e) return -1;
  }
  return -1;  // not reached: lambda_N > never_upto_e
}

bool ExactActivation::fires(double n_e, double offset_V, double read_V, double threshold_V) const {
  // The per-sampling path's comparator expression, operation for operation.
  return m_.gain * (std::min(n_e / m_.electrons_per_V + offset_V, m_.saturation_V) + read_V) >= threshold_V;
}

int ExactActivation::draw_first_firing(const PixelDrive& d, double threshold_V, pcg32& rng) const {
  double z1 = 0, z2 = 0;
  standard_normal_pair(rng, z1, z2);  // the per-sampling path's first draws: the same o and r
  const double o = z1 * m_.ktc_V, r = z2 * m_.read_V;
  const int N = m_.samplings;
  if (!m_.shot) {
    for (int k = 1; k <= N; ++k) {
      const double v =
          golden::pixel_swing_V(d.signal_V, d.profile, d.background_V, d.dark_V, static_cast<double>(k) / N);
      if (m_.gain * (std::min(v + o, m_.saturation_V) + r) >= threshold_V) return k;
    }
    return 0;
  }
  // Saturated below theta: no count fires (min(., V_sat) caps the swing).
  if (!(m_.gain * (m_.saturation_V + r) >= threshold_V)) return 0;
  // n*: the smallest count the comparator accepts; the estimate is corrected by the expression
  // itself, so rounding cannot move it.
  double n = std::max(0.0, std::ceil((threshold_V / m_.gain - o - r) * m_.electrons_per_V));
  if (!(n < 9e15)) return 0;  // beyond any count a double holds: never reached
  while (n > 0 && fires(n - 1, o, r, threshold_V)) n -= 1;
  while (!fires(n, o, r, threshold_V)) n += 1;
  if (n == 0) return 1;  // fires with no electron at the first sampling
  if (!(d.mean_step_e > 0)) return 0;
  const double T = gamma_variate(rng, n);  // mean count at which the n*-th electron arrives
  const double k = std::max(1.0, std::ceil(T / d.mean_step_e));
  return k <= N ? static_cast<int>(k) : 0;
}

bool ExactActivation::below(double u, double lambda, ThresholdEntry& e) {
  if (e.table) {
    const double v = e.table->value(lambda), d = e.table->bound();
    if (u < v - d) return true;
    if (u >= v + d) return false;
  }
  double p, q;
  probability(lambda, e, p, q);
  ++exact_evaluations_;
  if (!e.table && ++e.exact_evaluations >= kTableAfter) {
    {
      std::lock_guard<std::mutex> lock(shared_mutex());  // another kernel may have made it meanwhile
      if (const SharedEntry* s = find_shared(m_, e.threshold_V)) e.table = s->table;
    }
    if (!e.table) {
      const double t_e = e.threshold_V / m_.gain * m_.electrons_per_V, s_e = sigma_V_ * m_.electrons_per_V;
      e.table = std::make_shared<const ActivationTable>(t_e, s_e, std::max(e.b.never_upto_e, 0.0), e.b.always_from_e);
      publish(m_, e);
    }
  }
  return u < p;
}

void ExactActivation::prepare_inversion(const PixelDrive& d, const ThresholdEntry& e, double* cut) const {
  for (int k = 1; k <= m_.samplings; ++k) {
    const double l = lambda_e(d, k);
    double* c = cut + 2 * (k - 1);
    if (l <= e.b.never_upto_e) {
      c[0] = c[1] = 0;  // f = 0: never u < 0
    } else if (l >= e.b.always_from_e) {
      c[0] = c[1] = 2;  // f = 1: always u < 2
    } else if (e.table) {
      const double v = e.table->value(l), bound = e.table->bound();
      c[0] = v - bound, c[1] = v + bound;
    } else {
      c[0] = -1, c[1] = 2;  // no table yet: every u goes to below()
    }
  }
}

int ExactActivation::invert_first_firing(const PixelDrive& d, ThresholdEntry& e, double u) {
  // K = the first k with u < f(lambda_k); f rises with k.
  for (int k = 1; k <= m_.samplings; ++k) {
    const double l = lambda_e(d, k);
    if (l <= e.b.never_upto_e) continue;
    if (l >= e.b.always_from_e || below(u, l, e)) return k;
  }
  return 0;
}

}  // namespace rangesim::systemc
