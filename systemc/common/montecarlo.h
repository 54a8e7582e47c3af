#pragma once
// Monte Carlo trials of one sensor's clock-level kernels (not the sc_modules) at an operating
// point of the evaluation grid: what `rangesim evaluate --trials` runs. The interface and its
// registry live here, each sensor's model in systemc/<sensor>/montecarlo.{h,cpp} (beside the
// kernels it drives); the sweep engine, statistics and output stay in app/montecarlo/. One trial is one range
// value as the sensor delivers it (ls-conventional: one frame access of a row, spot centre drawn
// uniformly across one pixel; ls-demodulation: N_p frames of K decisions averaged, spot likewise;
// tof-lockin: N_p range maps (LED + ambient frames) averaged; tof-spad: one histogram of N_p
// integrations of one TDC group), with every noise source of the kernel on.
//
// Random streams are keyed by (seed, grid point, trial) only (systemc/common/random_stream.h): a trial's
// result never depends on which thread runs it or when.
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "core/params.h"

namespace rangesim::mc {

struct McTrial {
  bool detected = false;  // the sensor reported a range / position
  double error = 0;       // estimate - truth, in McModel::unit() (detected trials)
  // The trial had an outlier (light-section: a pixel outside the spot's pixels, golden/common/spot.h,
  // activated in some decision); the statistics count such trials apart (app/montecarlo/mc_stats.h).
  // Sensors without the notion leave it false.
  bool outlier = false;
};

// Trials of one operating point; owns its kernels, used by one thread. trial() must be called with
// t = 0, 1, 2, ... in order (kernels keep frame counters); the result of trial t is a function of
// (seed, point, t) alone.
class McPointRunner {
 public:
  virtual ~McPointRunner() = default;
  virtual McTrial trial(long long t) = 0;
  // Trials t0 .. t0 + n - 1 into out[0 .. n-1], the same values as n calls of trial(). The sweep
  // calls this; a model whose trials are a few nanoseconds each overrides it with a loop the
  // compiler can inline and overlap (no virtual call, no per-trial set-up checks).
  virtual void trials(long long t0, long long n, McTrial* out) {
    for (long long i = 0; i < n; ++i) out[i] = trial(t0 + i);
  }
  // Random variates drawn so far (Poisson, normal, uniform), -1 if the kernel does not count them.
  virtual long long variates() const { return -1; }
};

class McModel {
 public:
  virtual ~McModel() = default;
  virtual const char* unit() const = 0;        // "px" (light-section) or "m" (time of flight)
  virtual double metres_per_unit() const = 0;  // triangulation at optics.distance_m, or 1
  virtual std::unique_ptr<McPointRunner> point(double signal, double background, std::uint64_t point_key) const = 0;
  // Cost of one trial at the point relative to the model's other points, for time-left estimates
  // (a sweep's first points may be far cheaper than its last); 1 where trials cost the same.
  virtual double relative_cost(double signal, double background) const {
    (void)signal, (void)background;
    return 1.0;
  }
};

// Key of a grid point's streams: (seed, point index) folded by SplitMix64.
std::uint64_t point_key(std::uint64_t seed, std::uint64_t point_index);
// Key of one trial of a point (kernels that take a seed per run).
std::uint64_t trial_key(std::uint64_t point_key, std::uint64_t trial);
// Uniform in [0, 1) of a trial (spot position), from its own stream.
double trial_uniform(std::uint64_t point_key, std::uint64_t trial);

// Where the spot sits in a light-section trial (ls-conventional, ls-demodulation): centre pixel
// c = columns / 2 (as the golden row model), x0 = c - 0.5 + u with u uniform per trial (the
// golden accuracy's average over one pixel), or u fixed (tests comparing with the golden moments
// at one position).
struct SpotPlacement {
  double fixed_u = std::numeric_limits<double>::quiet_NaN();  // NaN: uniform per trial
};

// The model of the preset's sensor (each sensor's make_<s>_mc from systemc/<s>/montecarlo.cpp,
// listed by core/sensor_list.h, or one registered at run time);
// throws std::logic_error for a sensor without one.
std::unique_ptr<McModel> make_mc_model(const ParamSet& params);
using McFactory = std::unique_ptr<McModel> (*)(const ParamSet& params);
void register_mc_model(const std::string& sensor_id, McFactory make);
// Whether the sensor has a Monte Carlo model (`evaluate --trials` runs for it).
bool has_mc_model(const std::string& sensor_id);

}  // namespace rangesim::mc
