#pragma once
// Sensor-independent result of an analytic evaluation over a signal x background grid (thesis
// chapters 3-4), which the `rangesim evaluate` and `rangesim table` commands print, plot and
// compare with Table 5.1. Each sensor's golden model fills one
// (golden/<sensor>/model.cpp).
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace rangesim::golden {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A log-spaced grid axis in the sensor's own unit: volts at the end of integration
// (ls-conventional), photocurrent in A (ls-demodulation, tof-lockin) or count rate in Hz
// (tof-spad).
struct EvalAxis {
  std::string quantity;        // "signal" or "background"
  std::string unit;            // "V", "A" or "Hz"
  std::vector<double> values;  // ascending
};

struct EvalPoint {
  double signal = 0;            // axis units
  double background = 0;        // axis units
  std::string detect;           // "detectable" or the reason range cannot be derived (snake_case id)
  double sbr_total_dB = kNaN;   // SBR' by thesis eq. 3.11 style (signal + background) / background
  double sbr_ratio_dB = kNaN;   // SBR' by eq. 3.23 / 4.11 style, signal / background
  double accuracy_m = kNaN;     // rms range error at the sensor's reference distance (detectable points)
  std::vector<double> metrics;  // one per EvalResult::metric_names; NaN where not defined
  // What `evaluate --trials` compares beside accuracy_m, NaN where the model gives none
  // (docs/evaluate-montecarlo.md): the probability that a trial reports a range, the probability
  // of an outlier (light-section: an activation outside the spot's pixels) and the rms error of
  // the detecting trials without one.
  double p_detect = kNaN;
  double p_outlier = kNaN;
  double accuracy_clean_m = kNaN;
};

// Detectable interval along one axis, at a fixed value of the other.
struct EvalRange {
  double lo = kNaN, hi = kNaN;      // edges in axis units
  double range_dB = 0;              // 20 log10(hi / lo); 0 when nothing is detectable
  bool lo_limited_by_grid = false;  // the edge is the grid's end, not a physical limit
  bool hi_limited_by_grid = false;
  double at = kNaN;  // value of the other axis
};

// A one-dimensional sweep (accuracy versus averaging, detections, gain, pulse width, ...),
// plotted as lines: one series per curve.
struct EvalSeries {
  std::string label;      // legend, e.g. "alpha = 10"
  std::vector<double> x;  // x values
  std::vector<double> y;  // y values (NaN: not defined at that x)
};
struct EvalSweep {
  std::string id;     // file stem, e.g. "accuracy_vs_frames"
  std::string title;  // plot title
  std::string x_label, x_unit;
  std::string y_label, y_unit;
  bool log_x = false, log_y = false;
  std::vector<EvalSeries> series;
};

struct EvalResult {
  std::string sensor;  // preset id
  EvalAxis signal, background;
  // Reason ids that can appear in EvalPoint::detect, "detectable" first, with a one-line
  // description each (legend of the detectable-area map).
  std::vector<std::pair<std::string, std::string>> reasons;
  // Extra per-point metrics, names with their unit ("accuracy_px", "noise_std_m", ...).
  std::vector<std::string> metric_names;
  std::vector<EvalPoint> points;  // row-major: points[ib * signal.values.size() + is]

  // Summary over the grid.
  int points_detectable = 0;
  EvalRange signal_range;                                   // detectable signal at the grid's lowest background
  EvalRange background_range;                               // detectable background at the grid's highest signal
  double sbr_min_dB = kNaN, sbr_max_dB = kNaN;              // eq. 3.11 style over the detectable area
  double sbr_ratio_min_dB = kNaN, sbr_ratio_max_dB = kNaN;  // eq. 3.23 / 4.11 style
  double accuracy_min_m = kNaN, accuracy_max_m = kNaN;      // over the detectable area
  double distance_m = kNaN;                                 // where accuracy_m is taken
  // Further summary figures, keys snake_case with unit ("accuracy_min_px", "range_per_px_m").
  std::vector<std::pair<std::string, double>> summary_extra;
  // One-dimensional sweeps that go with the evaluation (thesis Fig. 3.6-3.9, 4.4-4.6, ...).
  std::vector<EvalSweep> sweeps;

  const EvalPoint& at(size_t ib, size_t is) const { return points[ib * signal.values.size() + is]; }
  // Points of the grid, also when they were streamed (EvalSink) and `points` is empty.
  size_t grid_points() const { return signal.values.size() * background.values.size(); }
};

// Where a streamed evaluation puts its points (golden/common/grid_scan.h): each background row in
// order, handed over and then dropped.
class EvalSink {
 public:
  virtual ~EvalSink() = default;
  // Before the first row; the axes, reasons and metric names of `r` are set.
  virtual void begin(const EvalResult& r) = 0;
  // Background row `ib`, its points in signal order.
  virtual void row(size_t ib, const std::vector<EvalPoint>& points) = 0;
};

// For a caller that needs only the summary and the ranges (sweep, table): the points go nowhere.
class DiscardPoints : public EvalSink {
 public:
  void begin(const EvalResult&) override {}
  void row(size_t, const std::vector<EvalPoint>&) override {}
};

// The summary fields (points_detectable, sbr/accuracy min/max) accumulated point by point; the
// ranges are the sensor model's job (exact edges, not snapped to the grid).
class PointSummary {
 public:
  void add(const EvalPoint& p);
  void into(EvalResult& r) const;

 private:
  int detectable_ = 0;
  double sbr_min_ = kNaN, sbr_max_ = kNaN, ratio_min_ = kNaN, ratio_max_ = kNaN, acc_min_ = kNaN, acc_max_ = kNaN;
};

// Fills the summary fields from r.points (PointSummary over all of them).
void summarise_points(EvalResult& r);

// Log-spaced axis from lo to hi with n points (n = 1 gives {lo}).
std::vector<double> log_spaced(double lo, double hi, int n);

}  // namespace rangesim::golden
