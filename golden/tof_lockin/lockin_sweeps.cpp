#include "golden/tof_lockin/lockin_sweeps.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "core/physics.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/pulse_timing.h"

namespace rangesim::golden {

namespace {

double or_nan(const LockinPoint& p) { return p.detect == LockinDetect::Detectable ? p.accuracy_m : kNaN; }

EvalSweep delay_sweep(const TofLockinConfig& cfg) {
  EvalSweep sw{"accuracy_vs_delay",
               "tof-lockin: range accuracy against delay (thesis 4.1.1: 2.9 / 3.45 / 2.9 cm at 1 / 50 / 100 ns, 0.7 V)",
               "delay T_D",
               "ns",
               "accuracy (rms)",
               "m",
               false,
               false,
               {}};
  const double T0 = cfg.source.pulse_width_s;
  for (double v : {0.7, 1.4}) {
    EvalSeries s{fmt::format("{:g} V signal, no background, 1 frame", v), {}, {}};
    for (int i = 0; i <= 100; ++i) {
      const double delay = T0 * i / 100.0;
      const double L = phys::kSpeedOfLight_m_per_s * delay / 2.0;
      s.x.push_back(delay * 1e9);
      s.y.push_back(accuracy_at_voltage_m(cfg, v, L, 1));
    }
    sw.series.push_back(std::move(s));
  }
  return sw;
}

EvalSweep frames_sweep(const TofLockinConfig& cfg) {
  EvalSweep sw{"accuracy_vs_frames",
               "tof-lockin: range accuracy against frames averaged (thesis 4.1.1, Fig. 4.6)",
               "frames averaged N_p",
               "",
               "accuracy (rms)",
               "m",
               true,
               true,
               {}};
  for (double v : {0.25, 1.3}) {
    EvalSeries s{fmt::format("{:g} V signal at {:g} m", v, cfg.eval.distance_m), {}, {}};
    for (long long n : {1, 2, 5, 10, 25, 50, 100}) {
      s.x.push_back(static_cast<double>(n));
      s.y.push_back(accuracy_at_voltage_m(cfg, v, cfg.eval.distance_m, n));
    }
    sw.series.push_back(std::move(s));
  }
  return sw;
}

EvalSweep pulse_width_sweep(const TofLockinConfig& cfg) {
  EvalSweep sw{"accuracy_vs_pulse_width",
               "tof-lockin: range accuracy against pulse width (thesis 4.1.1: 0.4 / 1.4 / 2.6 cm)",
               "pulse width T0",
               "ns",
               "accuracy (rms)",
               "m",
               false,
               false,
               {}};
  EvalSeries s{fmt::format("0.2 V signal, 10 frames at {:g} m", cfg.eval.distance_m), {}, {}};
  for (int ns = 10; ns <= 100; ns += 5) {
    s.x.push_back(ns);
    s.y.push_back(accuracy_at_voltage_m(cfg, 0.2, cfg.eval.distance_m, 10, ns * 1e-9));
  }
  sw.series.push_back(std::move(s));
  return sw;
}

EvalSweep signal_sweep(const TofLockinConfig& cfg, const std::vector<double>& sig, const std::vector<double>& bg) {
  EvalSweep sw{"accuracy_vs_signal",
               "tof-lockin: range accuracy against signal at several backgrounds (thesis Fig. 4.5)",
               "signal photocurrent",
               "A",
               "accuracy (rms)",
               "m",
               true,
               true,
               {}};
  // The grid's lowest background and each decade of the grid above it.
  std::vector<double> levels{bg.front()};
  for (double b = std::pow(10.0, std::ceil(std::log10(bg.front())) + 1); b <= bg.back() * 1.000001; b *= 100.0)
    levels.push_back(b);
  for (double b : levels) {
    EvalSeries s{fmt::format("background {:g} A, {} frame(s)", b, cfg.eval.frames_averaged), {}, {}};
    for (double i : sig) {
      s.x.push_back(i);
      s.y.push_back(or_nan(evaluate_point(cfg, i, b, cfg.eval.distance_m, cfg.eval.frames_averaged)));
    }
    sw.series.push_back(std::move(s));
  }
  return sw;
}

EvalSweep distance_sweep(const TofLockinConfig& cfg, const std::vector<double>& sig, const std::vector<double>& bg) {
  EvalSweep sw{"accuracy_vs_distance",
               "tof-lockin: range accuracy against distance (Table 4.1: 0.8-12 m)",
               "distance",
               "m",
               "accuracy (rms)",
               "m",
               false,
               true,
               {}};
  const int n = std::max(cfg.eval.distance_points, 1);
  for (double i : {sig.back(), std::sqrt(sig.front() * sig.back())}) {
    EvalSeries s{fmt::format("signal {:.3g} A, background {:g} A", i, bg.front()), {}, {}};
    for (int k = 0; k < n; ++k) {
      const double L =
          n == 1 ? cfg.eval.distance_min_m
                 : cfg.eval.distance_min_m + (cfg.eval.distance_max_m - cfg.eval.distance_min_m) * k / (n - 1);
      s.x.push_back(L);
      s.y.push_back(or_nan(evaluate_point(cfg, i, bg.front(), L, cfg.eval.frames_averaged)));
    }
    sw.series.push_back(std::move(s));
  }
  return sw;
}

}  // namespace

double accuracy_at_voltage_m(const TofLockinConfig& cfg0, double signal_V, double distance_m, long long frames,
                             double pulse_width_s) {
  TofLockinConfig cfg = cfg0;
  if (pulse_width_s > 0) cfg.source.pulse_width_s = pulse_width_s;
  const double i = signal_current_for_voltage_A(cfg, signal_V, distance_m);
  return or_nan(evaluate_point(cfg, i, 0.0, distance_m, frames));
}

std::vector<EvalSweep> lockin_sweeps(const TofLockinConfig& cfg, const std::vector<double>& sig,
                                     const std::vector<double>& bg) {
  return {delay_sweep(cfg), frames_sweep(cfg), pulse_width_sweep(cfg), signal_sweep(cfg, sig, bg),
          distance_sweep(cfg, sig, bg)};
}

}  // namespace rangesim::golden
