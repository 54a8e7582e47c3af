#include "golden/common/position_noise.h"

#include <algorithm>
#include <cmath>

#include "golden/common/fixed_pattern_activation.h"
#include "golden/common/pixel.h"
#include "golden/common/spot.h"

namespace rangesim::golden {
namespace {

constexpr double kWindowMin = 1e-15;  // pixels less likely than this to activate are left out

using Vec = std::vector<double>;
using Mat = std::vector<std::vector<double>>;

// P(F in [lo, hi]) for 1 <= lo, hi <= N+1, from the accurate CDF and survival arrays.
inline double interval(const Vec& C, const Vec& S, int lo, int hi, int N) {
  if (lo > hi) return 0;
  if (hi == N + 1) return S[lo - 1];
  if (lo == 1) return C[hi];
  return C[lo - 1] < 0.5 ? C[hi] - C[lo - 1] : S[lo - 1] - S[hi];
}

// E[l_k ; min F >= lb] (L1), and E[l_k l_k' ; min F >= lb] (LL, symmetric, LL[k][k] = E[l_k^2]),
// k = 1..N stored at k-1, for pixels in the given order (reverse the order to get the r's).
void left_sums(const Vec& x, const Mat& C, const Mat& S, int lb, int N, Vec& L1, Mat& LL) {
  const int W = static_cast<int>(x.size());
  auto I = [&](int j, int lo, int hi) { return interval(C[j], S[j], lo, hi, N); };
  Vec SE(W), PA(W + 1), D(W), B(W), Cm(W);
  // SE[j] = prod_{i>j} P(F_i >= lb)
  SE[W - 1] = 1;
  for (int j = W - 2; j >= 0; --j) SE[j] = SE[j + 1] * I(j + 1, lb, N + 1);
  L1.assign(N, 0);
  LL.assign(N, Vec(N, 0));
  for (int k = 1; k <= N; ++k) {
    PA[0] = 1;
    for (int j = 0; j < W; ++j) PA[j + 1] = PA[j] * I(j, std::max(lb, k + 1), N + 1);
    double s1 = 0, s2 = 0;
    for (int j = 0; j < W; ++j) {
      const double w = PA[j] * I(j, lb, k) * SE[j];  // P(l_k = j, min F >= lb)
      s1 += x[j] * w;
      s2 += x[j] * x[j] * w;
    }
    L1[k - 1] = s1;
    LL[k - 1][k - 1] = s2;
  }
  for (int k = 1; k <= N; ++k)
    for (int kp = k + 1; kp <= N; ++kp) {
      // l_k' = j' <= l_k = j. j' = j: pixels left of j inactive at k', j active by k.
      // j' < j: left of j' inactive at k', j' activates in (k, k'], between inactive at k.
      PA[0] = 1;
      for (int j = 0; j < W; ++j) {
        PA[j + 1] = PA[j] * I(j, std::max(lb, kp + 1), N + 1);
        B[j] = I(j, std::max(lb, k + 1), kp);
        Cm[j] = I(j, std::max(lb, k + 1), N + 1);
        D[j] = I(j, lb, k);
      }
      double T = 0, sum = 0;
      for (int j = 0; j < W; ++j) {
        sum += x[j] * D[j] * SE[j] * (x[j] * PA[j] + T);
        T = T * Cm[j] + x[j] * PA[j] * B[j];
      }
      LL[k - 1][kp - 1] = LL[kp - 1][k - 1] = sum;
    }
}

// E[l_k r_k' ; min F >= lb] for all k, k' (pixels ascending). Always l_k <= r_k'.
void left_right_sums(const Vec& x, const Mat& C, const Mat& S, int lb, int N, Mat& LR) {
  const int W = static_cast<int>(x.size());
  auto I = [&](int j, int lo, int hi) { return interval(C[j], S[j], lo, hi, N); };
  Vec PL(W + 1), SR(W), M(W);
  for (int j = 0; j < W; ++j) M[j] = I(j, lb, N + 1);
  LR.assign(N, Vec(N, 0));
  for (int k = 1; k <= N; ++k) {
    PL[0] = 1;
    for (int j = 0; j < W; ++j) PL[j + 1] = PL[j] * I(j, std::max(lb, k + 1), N + 1);
    for (int kp = 1; kp <= N; ++kp) {
      SR[W - 1] = 1;
      for (int j = W - 2; j >= 0; --j) SR[j] = SR[j + 1] * I(j + 1, std::max(lb, kp + 1), N + 1);
      const int kmin = std::min(k, kp);
      double T = 0, sum = 0;
      for (int j = 0; j < W; ++j) {
        // j' = j here: same pixel is the left edge at k and the right edge at k'.
        sum += x[j] * SR[j] * (x[j] * PL[j] * I(j, lb, kmin) + T * I(j, lb, kp));
        T = T * M[j] + x[j] * PL[j] * I(j, lb, k);
      }
      LR[k - 1][kp - 1] = sum;
    }
  }
}

}  // namespace

ActivationProbability ActivationCache::get(double mean_e, double threshold_e, double sigma_e) {
  const auto key = std::make_pair(mean_e, threshold_e);
  auto it = memo_.find(key);
  if (it != memo_.end()) return it->second;
  const auto table_key = std::make_pair(threshold_e, std::max(sigma_e, 0.0));
  auto t = tables_.find(table_key);
  if (t == tables_.end()) {
    ActivationTable built(threshold_e, sigma_e);
    if (table_entries_ + built.entries() > kMaxTableEntries) tables_.clear(), table_entries_ = 0;
    table_entries_ += built.entries();
    t = tables_.emplace(table_key, std::move(built)).first;
  }
  const ActivationTable* table = &t->second;
  const ActivationProbability p = (*table)(mean_e);
  if (memo_.size() > 4096) memo_.clear();
  memo_.emplace(key, p);
  return p;
}

PositionMoments edge_centre_moments(const Vec& x, const Mat& cdf, const Mat& surv, int N) {
  PositionMoments r;
  const int W = static_cast<int>(x.size());
  r.window_pixels = W;
  if (W == 0) return r;
  double log_none = 0;
  for (int j = 0; j < W; ++j) log_none += std::log(surv[j][N]);
  r.p_detect = -std::expm1(log_none);
  if (!(r.p_detect > 0)) return r;

  Vec xr(x.rbegin(), x.rend());
  Mat Cr(cdf.rbegin(), cdf.rend()), Sr(surv.rbegin(), surv.rend());
  // Per lower bound lb on all F: the sums of E[c_k] and E[c_k c_k'] over k, k' >= kmin on
  // {min F >= lb}; each lb's matrices are computed once and serve kmin = lb and kmin = lb - 1.
  std::vector<Vec> L1(N + 2), R1(N + 2);
  std::vector<Mat> LL(N + 2), RR(N + 2), LR(N + 2);
  for (int lb = 1; lb <= N; ++lb) {
    left_sums(x, cdf, surv, lb, N, L1[lb], LL[lb]);
    left_sums(xr, Cr, Sr, lb, N, R1[lb], RR[lb]);
    left_right_sums(x, cdf, surv, lb, N, LR[lb]);
  }
  auto sums = [&](int lb, int kmin, double& s1, double& s2) {
    s1 = s2 = 0;
    if (lb > N) return;  // nothing activates by t_N
    for (int k = kmin; k <= N; ++k) {
      s1 += 0.5 * (L1[lb][k - 1] + R1[lb][k - 1]);
      for (int kp = kmin; kp <= N; ++kp)
        s2 += 0.25 * (LL[lb][k - 1][kp - 1] + LR[lb][k - 1][kp - 1] + LR[lb][kp - 1][k - 1] + RR[lb][k - 1][kp - 1]);
    }
  };
  double e1 = 0, e2 = 0;
  for (int a = 1; a <= N; ++a) {
    double s1a, s2a, s1b, s2b;
    sums(a, a, s1a, s2a);      // min F >= a
    sums(a + 1, a, s1b, s2b);  // min F >= a + 1; difference: min F = a, D = {a..N}
    const double n = N - a + 1;
    e1 += (s1a - s1b) / n;
    e2 += (s2a - s2b) / (n * n);
  }
  r.mean_px = e1 / r.p_detect;
  r.var_px2 = std::max(0.0, e2 / r.p_detect - r.mean_px * r.mean_px);
  return r;
}

double level_threshold_electrons(const RowModel& row, int m) {
  return code_threshold_V(row.quantiser, m) / row.cfg.pixel.source_follower_gain * electrons_per_volt(row.cfg.pixel);
}

double static_noise_electrons(const RowModel& row) {
  return static_noise_V(row.cfg) * electrons_per_volt(row.cfg.pixel);
}

namespace {

// P(pixel i activated by sampling k) at the row's threshold and static noise, averaged over the
// chip's PRNU and DSNU draws when they are on (fixed_pattern_activation.h).
ActivationProbability pixel_activation(const RowModel& row, ActivationCache& cache, int i, double x0, int k, double thr,
                                       double sig) {
  if (!fixed_pattern_spreads_mean(row.cfg)) return cache.get(row_pixel_mean_electrons(row, i, x0, k), thr, sig);
  const double t = static_cast<double>(k) / row.samplings;
  const double photo_V = row.signal_V * spot_profile(row.cfg.spot, i - x0) + row.background_V;
  return fixed_pattern_activation(row.cfg, cache, photo_V * electrons_per_volt(row.cfg.pixel) * t, t, thr, sig);
}

// Pixels [first, last] whose activation probability (code >= 1 by t_N) exceeds kWindowMin.
bool activation_window(const RowModel& row, double x0, ActivationCache& cache, int& first, int& last) {
  const int N = row.samplings;
  const double thr = level_threshold_electrons(row, 1), sig = static_noise_electrons(row);
  const double bg_only = (row.background_V + row.dark_V) * electrons_per_volt(row.cfg.pixel);
  const ActivationProbability bg =
      fixed_pattern_spreads_mean(row.cfg)
          ? fixed_pattern_activation(row.cfg, cache, row.background_V * electrons_per_volt(row.cfg.pixel), 1.0, thr,
                                     sig)
          : cache.get(bg_only, thr, sig);
  if (bg.p > kWindowMin) {  // background alone may activate: whole row
    first = 0;
    last = row.columns - 1;
    return true;
  }
  // The profile falls off monotonically from x0, so the window is contiguous around it.
  auto active = [&](int i) { return pixel_activation(row, cache, i, x0, N, thr, sig).p > kWindowMin; };
  const int c = std::clamp(static_cast<int>(std::lround(x0)), 0, row.columns - 1);
  first = c;
  while (first > 0 && active(first - 1)) --first;
  last = c;
  while (last < row.columns - 1 && active(last + 1)) ++last;
  if (!active(c)) {  // the nearest pixel may still be below and its neighbour above (x0 on a pixel edge)
    const bool l = c > 0 && active(c - 1), r = c + 1 < row.columns && active(c + 1);
    if (!l && !r) return false;
  }
  return true;
}

// 1 bit: the moments of every activation and, when `split`, of the spot's pixels alone with the
// outlier probability.
SplitMoments exact_moments(const RowModel& row, double x0_px, ActivationCache& cache, int first, int last, bool split) {
  const int N = row.samplings, W = last - first + 1;
  const double thr = level_threshold_electrons(row, 1), sig = static_noise_electrons(row);
  Vec x(W);
  Mat C(W, Vec(N + 2)), S(W, Vec(N + 2));
  for (int j = 0; j < W; ++j) {
    const int i = first + j;
    x[j] = i - row.centre_pixel;  // relative positions keep E[x^2] - E[x]^2 free of cancellation
    C[j][0] = 0;
    S[j][0] = 1;
    C[j][N + 1] = 1;
    S[j][N + 1] = 0;
    for (int k = 1; k <= N; ++k) {
      const ActivationProbability p = pixel_activation(row, cache, i, x0_px, k, thr, sig);
      C[j][k] = p.p;
      S[j][k] = p.q;
    }
  }
  SplitMoments r;
  r.all = edge_centre_moments(x, C, S, N);
  r.all.mean_px += row.centre_pixel;
  r.clean = r.all;
  if (!split) return r;
  const ColumnSpan spot = spot_window(row.cfg.spot, x0_px, row.columns);
  const int a = std::max(first, spot.first) - first, b = std::min(last, spot.last) - first;  // spot in the window
  double log_none = 0;  // log P(no pixel of the window outside the spot's pixels activates by t_N)
  for (int j = 0; j < W; ++j)
    if (j < a || j > b) log_none += std::log(S[j][N]);
  r.p_outlier = -std::expm1(log_none);
  if (a == 0 && b == W - 1) return r;
  if (a > b) {  // no spot pixel may activate: without an outlier nothing is detected
    r.clean = {};
    return r;
  }
  // The pixels are independent: given that none outside activates, the spot's pixels are as if alone.
  const Vec xs(x.begin() + a, x.begin() + b + 1);
  const Mat Cs(C.begin() + a, C.begin() + b + 1), Ss(S.begin() + a, S.begin() + b + 1);
  r.clean = edge_centre_moments(xs, Cs, Ss, N);
  r.clean.mean_px += row.centre_pixel;
  return r;
}

// The outlier probability alone (adc_bits > 1: the code >= 1 activations).
double outlier_probability(const RowModel& row, double x0_px, ActivationCache& cache, int first, int last) {
  const double thr = level_threshold_electrons(row, 1), sig = static_noise_electrons(row);
  const ColumnSpan spot = spot_window(row.cfg.spot, x0_px, row.columns);
  double log_none = 0;
  for (int i = first; i <= last; ++i)
    if (!spot.contains(i)) log_none += std::log(pixel_activation(row, cache, i, x0_px, row.samplings, thr, sig).q);
  return -std::expm1(log_none);
}

PositionMoments delta_moments(const RowModel& row, double x0, ActivationCache& cache, int first, int last);

}  // namespace

PositionMoments position_moments(const RowModel& row, double x0_px, ActivationCache* cache_in) {
  ActivationCache local;
  ActivationCache& cache = cache_in ? *cache_in : local;
  int first, last;
  if (!activation_window(row, x0_px, cache, first, last)) return {};
  if (row.quantiser.bits > 1) return delta_moments(row, x0_px, cache, first, last);
  return exact_moments(row, x0_px, cache, first, last, false).all;
}

SplitMoments position_moments_split(const RowModel& row, double x0_px, ActivationCache* cache_in) {
  ActivationCache local;
  ActivationCache& cache = cache_in ? *cache_in : local;
  int first, last;
  if (!activation_window(row, x0_px, cache, first, last)) return {};
  if (row.quantiser.bits > 1) {
    SplitMoments r;
    r.all = r.clean = delta_moments(row, x0_px, cache, first, last);
    r.p_outlier = outlier_probability(row, x0_px, cache, first, last);
    return r;
  }
  return exact_moments(row, x0_px, cache, first, last, true);
}

namespace {

// The number of code levels a pixel of mean mu_e reaches with probability exactly 1 (a prefix:
// P(c >= m) falls with m). A binary search, so a wide ADC (up to 16383 levels) costs the levels
// near the mean only, not one activation probability per level below it.
int certain_levels(const RowModel& row, double mu_e, double sig, ActivationCache& cache) {
  auto certain = [&](int m) { return cache.get(mu_e, level_threshold_electrons(row, m), sig).p == 1.0; };
  int lo = 0, hi = row.quantiser.max_code;  // levels <= lo certain, > hi not (invariant once tested)
  if (hi <= 16 || !certain(1)) return 0;    // few levels: the plain loop is as cheap
  lo = 1;
  if (certain(hi)) return hi;
  while (hi - lo > 1) {
    const int mid = lo + (hi - lo) / 2;
    (certain(mid) ? lo : hi) = mid;
  }
  return lo;
}

PositionMoments delta_moments(const RowModel& row, double x0, ActivationCache& cache, int first, int last) {
  const int N = row.samplings, W = last - first + 1, M = row.quantiser.max_code;
  const double sig = static_noise_electrons(row), e_per_V = electrons_per_volt(row.cfg.pixel);
  const double sigR_V = static_noise_V(row.cfg);
  Mat Ec(W, Vec(N)), Vc(W, Vec(N)), mu(W, Vec(N));
  Vec pnone(N, 0.0);  // log P(no pixel has code >= 1 at sampling k)
  for (int j = 0; j < W; ++j)
    for (int k = 1; k <= N; ++k) {
      mu[j][k - 1] = row_pixel_mean_electrons(row, first + j, x0, k);
      const int sure = certain_levels(row, mu[j][k - 1], sig, cache);
      // The certain levels (P = 1 exactly) add 1 each to E[c] and sum_{m <= sure} (2m - 1) = sure^2
      // to E[c^2]: exact in doubles, so the same bits as adding them one by one.
      double e = sure, e2 = static_cast<double>(sure) * sure;
      pnone[k - 1] += std::log(cache.get(mu[j][k - 1], level_threshold_electrons(row, 1), sig).q);
      for (int m = sure + 1; m <= M; ++m) {
        const ActivationProbability p = cache.get(mu[j][k - 1], level_threshold_electrons(row, m), sig);
        if (p.p == 0) break;  // higher levels are harder still
        e += p.p;
        e2 += (2.0 * m - 1) * p.p;  // E[c^2] = sum_m (2m - 1) P(c >= m)
      }
      Ec[j][k - 1] = e;
      Vc[j][k - 1] = std::max(0.0, e2 - e * e);
    }
  PositionMoments r;
  r.exact = false;
  r.window_pixels = W;
  r.p_detect = -std::expm1(pnone[N - 1]);  // codes are nested in time: detect at t_N <=> ever
  std::vector<int> D;
  for (int k = 1; k <= N; ++k)
    if (-std::expm1(pnone[k - 1]) >= 0.5) D.push_back(k);
  if (D.empty() && r.p_detect > 0) D.push_back(N);
  if (D.empty()) return r;
  const double nD = static_cast<double>(D.size());
  Mat grad(W, Vec(N, 0.0));
  double mean = 0;
  for (int k : D) {
    double sw = 0, swx = 0;
    for (int j = 0; j < W; ++j) {
      sw += Ec[j][k - 1];
      swx += Ec[j][k - 1] * (first + j);
    }
    if (!(sw > 0)) continue;
    const double ck = swx / sw;
    mean += ck / nD;
    for (int j = 0; j < W; ++j) grad[j][k - 1] = ((first + j) - ck) / (sw * nD);
  }
  double var = 0;
  for (int j = 0; j < W; ++j)
    for (int k : D)
      for (int kp : D) {
        const double g = grad[j][k - 1] * grad[j][kp - 1];
        if (g == 0) continue;
        // Gaussian correlation of the analog noise: shared static offset + nested shot noise.
        const double vk = mu[j][k - 1] / (e_per_V * e_per_V) + sigR_V * sigR_V;
        const double vkp = mu[j][kp - 1] / (e_per_V * e_per_V) + sigR_V * sigR_V;
        const double cov = mu[j][std::min(k, kp) - 1] / (e_per_V * e_per_V) + sigR_V * sigR_V;
        const double rho = cov / std::sqrt(vk * vkp);
        var += g * rho * std::sqrt(Vc[j][k - 1] * Vc[j][kp - 1]);
      }
  r.mean_px = mean;
  r.var_px2 = var;
  return r;
}

}  // namespace
}  // namespace rangesim::golden
