#pragma once
// Statistics of the Monte Carlo trials at one operating point, each with its 95% confidence
// interval. Trial errors are reduced in trial order by a two-pass sum, so the figures depend only
// on the trials' values, never on threads or scheduling.
//
// Intervals (z = 1.96, normal approximations, valid for the trial counts a sweep uses: >= 30
// detected trials is the documented minimum for a stated interval, below that they are wider than
// they look):
//   p_detect  Wilson score interval of detected / trials;
//   bias      mean error +- z s / sqrt(n);
//   std       sqrt of var +- z sqrt((m4 - var^2) / n) (the variance's standard error from the
//             fourth central moment, no normality assumed), lower end clamped at 0;
//   rms       sqrt of mean(e^2) +- z sd(e^2) / sqrt(n): the accuracy (rms error), the same
//             quantity as the golden `accuracy` (sqrt(bias^2 + variance));
//   p_outlier Wilson score interval of outliers / trials (McTrial::outlier);
//   rms_clean rms as above over the detected trials without an outlier (the golden
//             `accuracy_clean`): comparable with golden at any trial count, where the rms of all
//             trials is not until the trials see the rare outliers (docs/evaluate-montecarlo.md).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace rangesim::app::mc {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kZ95 = 1.959963984540054;  // two-sided 95% normal quantile

struct McInterval {
  double value = kNaN, lo = kNaN, hi = kNaN;
  double half_width() const { return 0.5 * (hi - lo); }
  bool contains(double x) const { return x >= lo && x <= hi; }
};

struct McPointStats {
  long long trials = 0;    // trials run
  long long detected = 0;  // trials in which the sensor reported a range / position
  McInterval p_detect;     // detected / trials
  McInterval bias;         // mean of (estimate - truth) over detected trials, model unit
  McInterval std;          // standard deviation of the error, model unit
  McInterval rms;          // rms error (accuracy), model unit
  long long outliers = 0;  // trials with an outlier
  McInterval p_outlier;    // outliers / trials
  McInterval rms_clean;    // rms error of the detected trials without an outlier, model unit

  // Exact text form for the sweep journal (hex floats, one line).
  std::string to_record() const;
  // Inverse of to_record(); throws std::runtime_error on a malformed record.
  static McPointStats from_record(const std::string& record);
};

// Statistics of `trials` trials whose detected ones had errors `errors` (in trial order);
// `outlier` (empty: none) flags the detected trials with an outlier, one per error.
McPointStats summarise_trials(long long trials, const std::vector<double>& errors,
                              const std::vector<char>& outlier = {});

// Wilson score interval of k successes in n trials.
McInterval wilson_interval(long long k, long long n);

}  // namespace rangesim::app::mc
