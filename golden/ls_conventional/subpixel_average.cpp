#include "golden/ls_conventional/subpixel_average.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "golden/common/position_noise.h"

namespace rangesim::golden {

namespace {

// The averaged quantities, each per unit of u (see subpixel_average.h).
enum Part { kP, kE, kPc, kEc, kOut, kVar, kParts };
using Parts = std::array<double, kParts>;

// What noise changes at spot position u: p - 1{nf}, p (b^2 + v) - 1{nf} e_nf^2 (all and clean),
// the outlier probability and p v. control = false: p and p (b^2 + v) themselves.
Parts integrand(const RowModel& row, double u, ActivationCache& cache, bool control = true) {
  const double x0 = row.centre_pixel - 0.5 + u;
  const SplitMoments m = position_moments_split(row, x0, &cache);
  const CentreEstimate nf = control ? noise_free_estimate(row, x0) : CentreEstimate{};
  const double nf_p = nf.detected ? 1.0 : 0.0;
  const double nf_e2 = nf.detected ? (nf.centre_px - x0) * (nf.centre_px - x0) : 0.0;
  auto square_error = [&](const PositionMoments& pm) {
    if (!(pm.p_detect > 0)) return 0.0;
    const double b = pm.mean_px - x0;
    return pm.p_detect * (b * b + pm.var_px2);
  };
  const double keep = 1 - m.p_outlier;  // P(no outlier)
  Parts f{};
  f[kP] = m.all.p_detect - nf_p;
  f[kE] = square_error(m.all) - nf_e2;
  f[kPc] = keep * m.clean.p_detect - nf_p;
  f[kEc] = keep * square_error(m.clean) - nf_e2;
  f[kOut] = m.p_outlier;
  f[kVar] = m.all.p_detect > 0 ? m.all.p_detect * m.all.var_px2 : 0.0;
  return f;
}

// Gauss-Kronrod 7-15 (abscissae and weights of QUADPACK's qk15).
constexpr std::array<double, 8> kXgk = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                                        0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                                        0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                                        0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr std::array<double, 8> kWgk = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                        0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                        0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                        0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> kWg = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                                       0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Segment {
  double a = 0, b = 0;
  Parts value{}, error{};  // K15 integral and |K15 - G7|
};

Segment gauss_kronrod(const RowModel& row, double a, double b, ActivationCache& cache, int& positions) {
  Segment s{a, b, {}, {}};
  const double h = 0.5 * (b - a), mid = 0.5 * (a + b);
  Parts k{}, g{};
  for (int i = 0; i < 8; ++i) {
    const int n = i == 7 ? 1 : 2;
    for (int side = 0; side < n; ++side) {
      const Parts f = integrand(row, mid + (side ? -1 : 1) * h * kXgk[i], cache);
      ++positions;
      for (int c = 0; c < kParts; ++c) {
        k[c] += kWgk[i] * f[c];
        if (i % 2 == 1) g[c] += kWg[i / 2] * f[c];
      }
    }
  }
  for (int c = 0; c < kParts; ++c) s.value[c] = h * k[c], s.error[c] = std::fabs(h * (k[c] - g[c]));
  return s;
}

// The noise-free parts over the integrated span (exact, multisampling.h) and the totals built on them.
struct Totals {
  double d_all = 0, n_all = 0, d_clean = 0, n_clean = 0, out = 0, length = 1;
};

Totals totals(const Parts& integral, double nf_detected, double nf_square, double length) {
  Totals t;
  t.length = length;
  t.d_all = nf_detected + integral[kP];
  t.n_all = nf_square + integral[kE];
  t.d_clean = nf_detected + integral[kPc];
  t.n_clean = nf_square + integral[kEc];
  t.out = integral[kOut];
  return t;
}

// The criterion: relative error of the accuracies (half the relative errors of their mean squares
// and of the detection weights), of P(detect), and of P(outlier) (or 1e-9 absolute).
double relative_error(const Parts& e, const Totals& t) {
  auto rel = [](double err, double v) { return v > 0 ? err / v : (err > 0 ? HUGE_VAL : 0.0); };
  const double acc = 0.5 * (rel(e[kE], t.n_all) + rel(e[kP], t.d_all));
  const double clean = 0.5 * (rel(e[kEc], t.n_clean) + rel(e[kPc], t.d_clean));
  const double out = e[kOut] / (t.out + 1e-9 * t.length);
  return std::max({acc, clean, rel(e[kP], t.d_all), out});
}

SubpixelAverage finish(const Parts& integral, double error, const Totals& t) {
  SubpixelAverage r;
  auto root = [](double n, double d) { return d > 0 ? std::sqrt(std::max(0.0, n / d)) : 0.0; };
  r.p_detect = std::clamp(t.d_all / t.length, 0.0, 1.0);
  r.accuracy_px = root(t.n_all, t.d_all);
  r.accuracy_clean_px = root(t.n_clean, t.d_clean);
  r.p_outlier = std::clamp(t.out / t.length, 0.0, 1.0);
  r.noise_std_px = root(integral[kVar], t.d_all);
  r.error_estimate = error;
  return r;
}

}  // namespace

SubpixelAverage subpixel_average(const RowModel& row, const QuantisationError& q, double tolerance, int fixed_positions,
                                 int max_positions) {
  ActivationCache cache;
  const bool mirror = 2 * row.centre_pixel + 1 == row.columns;
  const double length = mirror ? 0.5 : 1.0;
  // Exact noise-free integrals over [0, length] (by symmetry half the pixel's when mirrored).
  const double nf_detected = q.detected_fraction * length;
  const double nf_square = q.rms_px * q.rms_px * q.detected_fraction * length;
  int positions = 0;

  if (!(tolerance > 0)) {  // the fixed midpoint rule
    // Without the control variate: with a few positions, the exact noise-free integral minus the
    // noise-free value at the positions can leave P(detect) < 0; the plain average stays a mean
    // of probabilities and errors inside the row.
    const int P = std::max(1, static_cast<int>(std::lround(fixed_positions * length)));
    Parts sum{};
    for (int i = 0; i < P; ++i) {
      const Parts f = integrand(row, length * (i + 0.5) / P, cache, false);
      for (int c = 0; c < kParts; ++c) sum[c] += f[c] * length / P;
    }
    SubpixelAverage r = finish(sum, NAN, totals(sum, 0, 0, length));
    r.positions = P;
    r.converged = false;
    r.noise_only_detections = q.detected_fraction == 0;
    return r;
  }

  // Segments between the noise-free breakpoints, in u.
  const double lo = row.centre_pixel - 0.5;
  std::vector<double> cuts;
  for (double x : estimate_breakpoints(row, lo, lo + length)) cuts.push_back(std::clamp(x - lo, 0.0, length));
  std::sort(cuts.begin(), cuts.end());
  std::vector<Segment> segs;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    if (cuts[i + 1] - cuts[i] > 1e-12) segs.push_back(gauss_kronrod(row, cuts[i], cuts[i + 1], cache, positions));
  if (segs.empty()) segs.push_back(gauss_kronrod(row, 0.0, length, cache, positions));

  for (;;) {
    Parts value{}, error{};
    for (const Segment& s : segs)
      for (int c = 0; c < kParts; ++c) value[c] += s.value[c], error[c] += s.error[c];
    const Totals t = totals(value, nf_detected, nf_square, length);
    const double err = relative_error(error, t);
    const bool done = err <= tolerance, out_of_budget = positions + 30 > max_positions;
    if (done || out_of_budget) {
      SubpixelAverage r = finish(value, err, t);
      r.positions = positions;
      r.converged = done;
      r.noise_only_detections = q.detected_fraction == 0;
      return r;
    }
    // Halve the segment that contributes most to the error.
    std::size_t worst = 0;
    double worst_err = -1;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      const double e = relative_error(segs[i].error, t);
      if (e > worst_err) worst_err = e, worst = i;
    }
    const Segment s = segs[worst];
    const double m = 0.5 * (s.a + s.b);
    segs[worst] = gauss_kronrod(row, s.a, m, cache, positions);
    segs.push_back(gauss_kronrod(row, m, s.b, cache, positions));
  }
}

}  // namespace rangesim::golden
