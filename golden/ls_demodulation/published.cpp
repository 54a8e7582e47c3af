#include "golden/ls_demodulation/published.h"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "golden/ls_demodulation/evaluation.h"
#include "golden/ls_demodulation/selectivity.h"

namespace rangesim::golden {

namespace {

constexpr const char* kId = "ls-demodulation";

// Signal values of the line plots: the grid axis thinned to about 25 points.
std::vector<double> sweep_signals(const LsDemodulationConfig& cfg) {
  return log_spaced(cfg.grid.signal_min_A, cfg.grid.signal_max_A, 25);
}

// Accuracy (m) against signal at the sweep background; NaN where not detectable.
EvalSeries accuracy_curve(const LsDemodulationConfig& cfg, const std::string& label, int K, int Np, double bg) {
  EvalSeries s{label, {}, {}};
  for (double sig : sweep_signals(cfg)) {
    const DemodPoint p = evaluate_demod_point(cfg, sig, bg, K, Np);
    s.x.push_back(sig);
    s.y.push_back(p.detect == DemodDetect::Detectable ? p.accuracy.accuracy_m : kNaN);
  }
  return s;
}

EvalSweep accuracy_sweep(const char* id, const char* title) {
  return EvalSweep{id, title, "signal photocurrent", "A", "rms range error", "m", true, true, {}};
}

}  // namespace

// The operating point of the "effective area" accuracy figures: a strong signal (0.15 V on the
// thesis axis) under the sweep background.
double demod_nominal_signal_A(const LsDemodulationConfig& cfg) { return 0.1 * cfg.grid.signal_max_A; }

std::vector<EvalSweep> demod_sweeps(const LsDemodulationConfig& cfg) {
  std::vector<EvalSweep> out;
  const double bg = cfg.grid.sweep_background_A;
  const int K = cfg.grid.detections, Np = cfg.grid.frames_averaged;

  // Mirror gain: at the grid's lowest background (threshold-limited, where alpha lowers the weakest
  // signal 10x) and at the sweep background (shot-noise-limited: alpha scales signal and noise alike,
  // and at alpha = 10 the background's noise crosses V_cmp).
  EvalSweep gain = accuracy_sweep("accuracy_vs_mirror_gain",
                                  "ls-demodulation: accuracy against signal, mirror gain alpha (thesis Fig. 3.6)");
  for (double b : {cfg.grid.background_min_A, bg})
    for (double a : {1.0, 10.0}) {
      LsDemodulationConfig c = cfg;
      c.suppression.mirror_gain = a;
      gain.series.push_back(accuracy_curve(c, fmt::format("alpha = {:g}, I_bg = {:.3g} A", a, b), K, Np, b));
    }
  out.push_back(std::move(gain));

  EvalSweep frames = accuracy_sweep("accuracy_vs_frames",
                                    "ls-demodulation: accuracy against signal, frames averaged N_p (thesis Fig. 3.8)");
  for (int n : {1, 10, 25}) frames.series.push_back(accuracy_curve(cfg, fmt::format("N_p = {}", n), K, n, bg));
  out.push_back(std::move(frames));

  // Detections: the shot/kTC part averages, the frame-common read noise and the bias do not.
  EvalSweep det{"accuracy_vs_detections",
                "ls-demodulation: accuracy against correlation decisions per frame (thesis Fig. 3.9)",
                "decisions per frame",
                "",
                "rms range error",
                "m",
                true,
                true,
                {}};
  const double smin = min_detectable_signal_A(cfg, bg, cfg.grid.signal_min_A, cfg.grid.signal_max_A);
  for (double f : {1.5, 4.0}) {
    for (bool read : {true, false}) {
      LsDemodulationConfig c = cfg;
      if (!read) c.noise.read_noise_V = 0;
      EvalSeries s{fmt::format("I_sig = {:.3g} A{}", f * smin, read ? "" : ", no read noise"), {}, {}};
      for (int k : {1, 2, 4, 8, 16, 32, 64, 128}) {
        const DemodPoint p = evaluate_demod_point(c, f * smin, bg, k, Np);
        s.x.push_back(k);
        s.y.push_back(p.detect == DemodDetect::Detectable ? p.accuracy.accuracy_m : kNaN);
      }
      if (std::isfinite(smin)) det.series.push_back(std::move(s));
    }
  }
  out.push_back(std::move(det));

  EvalSweep sel{"selectivity_vs_harmonic",
                "ls-demodulation: response to background modulated at k f0, relative to k = 1",
                "harmonic k",
                "",
                "relative response",
                "dB",
                false,
                false,
                {}};
  LsDemodulationConfig duty = cfg;
  duty.correlator.reference_duty_cycle = duty_for_even_harmonic_dB(-13.0);
  EvalSeries lin{"sinusoid, linearised (preset)", {}, {}}, sq{"square 50%, exact chain (preset)", {}, {}},
      dl{fmt::format("sinusoid, MPY+ duty {:.3f}", duty.correlator.reference_duty_cycle), {}, {}};
  for (int k = 1; k <= 10; ++k) {
    // -inf (ideal rejection) is drawn as a gap.
    auto fin = [](double v) { return std::isfinite(v) ? v : kNaN; };
    lin.x.push_back(k), sq.x.push_back(k), dl.x.push_back(k);
    lin.y.push_back(fin(harmonic_selectivity_dB(cfg, bg, k)));
    sq.y.push_back(fin(harmonic_selectivity_square_dB(cfg, bg, 0.1 * bg, k)));
    dl.y.push_back(fin(harmonic_selectivity_dB(duty, bg, k)));
  }
  sel.series = {lin, sq, dl};
  out.push_back(std::move(sel));

  EvalSweep step{"step_settling",
                 "ls-demodulation: background step, residual of the subtraction and correlator error",
                 "time after the step",
                 "s",
                 "relative residual / |error| / V_cmp",
                 "",
                 true,
                 true,
                 {}};
  EvalSeries res{"I_mod residual / (alpha dI)", {}, {}},
      cor{"|correlator error| / V_cmp, step x10 from the sweep background", {}, {}};
  for (double t : log_spaced(1e-5, 20 * cfg.suppression.lpf_time_constant_s, 30)) {
    res.x.push_back(t), cor.x.push_back(t);
    res.y.push_back(step_residual_fraction(cfg, t));
    cor.y.push_back(std::fabs(step_correlator_error_V(cfg, bg, 10 * bg, t)) / cfg.comparator.threshold_V);
  }
  step.series = {res, cor};
  out.push_back(std::move(step));
  return out;
}

std::vector<PublishedFigure> demod_published_figures(const LsDemodulationConfig& cfg) {
  std::vector<PublishedFigure> f;
  const auto& g = cfg.grid;
  const std::vector<double> sig_axis = log_spaced(g.signal_min_A, g.signal_max_A, g.signal_points);
  const std::vector<double> bg_axis = log_spaced(g.background_min_A, g.background_max_A, g.background_points);
  const double per_px = demod_range_per_px_m(cfg);

  // -18 dB SBR in 48 dB background: weakest detectable signal 48 dB above the grid's lowest background.
  const double b48 = g.background_min_A * std::pow(10.0, 48.0 / 20);
  const double s48 = min_detectable_signal_A(cfg, b48, 1e-3 * g.signal_min_A, g.signal_max_A);
  f.push_back(
      {kId, "sbr_min_48dB_background", "-18 dB SBR in 48 dB background (chip paper, thesis 3.2.1)", -18.0, "dB",
       20 * std::log10(s48 / b48), 0.1,
       fmt::format("not reproduced: weakest detectable signal {:.3g} A at background {:.3g} A (48 dB above the "
                   "grid's 0.001 V-equivalent lowest background), ratio-style SBR'. Our threshold is calibrated "
                   "to the thesis's 0.01 V (43.5 dB signal span); -18 dB there would need a threshold 3x higher "
                   "(33.5 dB signal span). The two published spans cannot both hold with one V_cmp",
                   s48, b48)});

  f.push_back(
      {kId, "even_harmonic_suppression", "-13 dB suppression of even harmonics of f0 (chip paper, thesis 3.2.1)", -13.0,
       "dB", std::fmax(-300.0, harmonic_selectivity_dB(cfg, g.sweep_background_A, 2)), 0.05,
       fmt::format("not reproduced: with a 50% MPY+ duty the correlation weight has no even Fourier "
                   "coefficients (C1 != C2 and mirror mismatch only add a DC term), so the model rejects "
                   "k = 2 ideally (shown as -300 dB). -13 dB is |cos(pi D)| for an MPY+ duty D = {:.4f}; the chip's "
                   "finite rejection points to such an asymmetry (or MPY timing skew), not modelled by default "
                   "because it would also leak the background's DC residue into V_out+ - V_out-",
                   duty_for_even_harmonic_dB(-13.0))});
  {
    LsDemodulationConfig d = cfg;
    d.correlator.reference_duty_cycle = duty_for_even_harmonic_dB(-13.0);
    f.push_back({kId, "even_harmonic_suppression_duty",
                 "-13 dB even-harmonic suppression with the explaining MPY+ duty", -13.0, "dB",
                 harmonic_selectivity_dB(d, g.sweep_background_A, 2), 1e-3,
                 fmt::format("MPY+ duty {:.4f} (derived from |cos(pi D)| = 10^(-13/20)); linearised chain at {:.3g} A "
                             "background",
                             d.correlator.reference_duty_cycle, g.sweep_background_A)});
  }

  const double frame_rate = 1 / demod_frame_time_s(cfg, 1);
  const bool det16 = demod_detectable(cfg, b48 * std::pow(10.0, -16.0 / 20), b48);
  f.push_back({kId, "frame_rate_2000fps", "2000 fps at -16 dB SBR (chip paper, thesis 3.2.1)", 2000.0, "1/s",
               frame_rate, 0.01,
               fmt::format("one 50 us decision + {} rows x {} cycles at {:g} Hz (row_cycles calibrated); -16 dB SBR at "
                           "{:.3g} A background is {}",
                           cfg.pixel.rows, cfg.readout.row_cycles, cfg.readout.clock_Hz, b48,
                           det16 ? "detectable" : "NOT detectable")});

  // Accuracy at the nominal operating point, 1000 mm.
  const double sn = demod_nominal_signal_A(cfg);
  const DemodPoint pn = evaluate_demod_point(cfg, sn, g.sweep_background_A, 1, 1);
  const double acc = pn.accuracy.accuracy_px * per_px, worst = pn.accuracy.worst_error_px * per_px;
  const std::string at = fmt::format("signal {:.3g} A, background {:.3g} A, one frame, {:.3g} m, {:.3g} mm/px", sn,
                                     g.sweep_background_A, cfg.optics.distance_m, per_px * 1e3);
  f.push_back({kId, "std_effective_area", "0.6 mm std in the effective area at 1000-1100 mm (thesis 3.2.1)", 0.6e-3,
               "m", acc, 0.05, "rms error over spot positions at " + at + "; baseline calibrated to this figure"});
  f.push_back({kId, "max_error_effective_area", "1.5 mm maximum error at 1000 mm (chip paper, thesis 3.2.1)", 1.5e-3,
               "m", worst, 0.25,
               "max over spot positions of |bias| + 3 std at " + at +
                   (std::fabs(worst - 1.5e-3) <= 0.25 * 1.5e-3
                        ? ""
                        : "; differs: our 1-bit edge readout's error "
                          "spread (bias steps of 0.5 px plus noise) has a larger max/std ratio than the chip's 2.5")});
  f.push_back({kId, "std_full_area", "0.89 mm std over the full area (thesis 3.2.1)", 0.89e-3, "m", acc, 0.05,
               "not reproduced: the full area adds lens distortion, calibration and target effects at the image "
               "edges that the model does not hold; ours is the effective-area value"});
  f.push_back({kId, "max_error_full_area", "3.2 mm maximum error over the full area (thesis 3.2.1)", 3.2e-3, "m", worst,
               0.05, "not reproduced: as std_full_area; ours is the effective-area value"});

  // Averaging: exponent of accuracy ~ N_p^-x between 1 and 25 frames at a noise-dominated point.
  {
    const double bg = g.sweep_background_A;
    const double s = 1.5 * min_detectable_signal_A(cfg, bg, g.signal_min_A, g.signal_max_A);
    const double a1 = evaluate_demod_point(cfg, s, bg, 1, 1).accuracy.accuracy_px;
    const double a25 = evaluate_demod_point(cfg, s, bg, 1, 25).accuracy.accuracy_px;
    f.push_back({kId, "averaging_exponent", "accuracy improves as 1/sqrt(N_p) with frame averaging (thesis Fig. 3.8)",
                 0.5, "1", std::log(a1 / a25) / std::log(25.0), 0.2,
                 fmt::format("exponent x of N_p^-x from 1 to 25 frames at {:.3g} A signal, {:.3g} A background "
                             "(1.5 x the weakest detectable). The noise part falls exactly as N_p^-1/2; the bias of "
                             "the 1-bit edge readout does not average, so x < 0.5 wherever it matters",
                             s, bg)});
  }

  const EvalRange sr = demod_signal_range(cfg, bg_axis.front(), sig_axis);
  const EvalRange br = demod_background_range(cfg, sig_axis.back(), bg_axis);
  f.push_back({kId, "signal_span", "detectable signal span 43.5 dB (thesis 3.2.3, Table 5.1 [27])", 43.5, "dB",
               sr.range_dB, 0.02,
               fmt::format("{:.3g}-{:.3g} A at {:.3g} A background; the lower edge is V_cmp (g_m calibrated to the "
                           "thesis's 0.01 V = 7.4 pA), the upper the grid's 1.5 V-equivalent end{}",
                           sr.lo, sr.hi, sr.at, sr.hi_limited_by_grid ? " (grid-limited)" : "")});
  f.push_back({kId, "background_span", "detectable background span 103.5 dB (thesis 3.2.3, Table 5.1 [27])", 103.5,
               "dB", br.range_dB, 0.02,
               fmt::format("not reproduced: {:.3g}-{:.3g} A at {:.3g} A signal. Above ~{:.2g} A the background's "
                           "shot noise through the correlator makes background-only pixels cross V_cmp (row false "
                           "activation > {:g}); the thesis's noise-free evaluation has no such limit",
                           br.lo, br.hi, br.at, br.hi, cfg.comparator.false_activation_max)});

  // Table 5.1 SBR' extremes over the grid (both definitions computed in the evaluation).
  double rat_lo = INFINITY, rat_hi = -INFINITY;
  for (double b : bg_axis) {
    const double smin = min_detectable_signal_A(cfg, b, g.signal_min_A, g.signal_max_A);
    if (!std::isfinite(smin)) continue;
    rat_lo = std::fmin(rat_lo, 20 * std::log10(smin / b));
    if (demod_detectable(cfg, g.signal_max_A, b)) rat_hi = std::fmax(rat_hi, 20 * std::log10(g.signal_max_A / b));
  }
  f.push_back({kId, "table51_sbr_max", "SBR' max 83 dB (Table 5.1 [27])", 83.0, "dB", rat_hi, 0.02,
               "ratio-style 20 log(I_sig / I_bg): highest signal over the lowest background of the grid (0.001 V "
               "equivalent); the thesis's 83 dB implies a 20 dB lower background floor, and its spans "
               "(43.5 + 103.5 = 147 dB) do not add up to its SBR' span (83 + 62 = 145 dB)"});
  f.push_back({kId, "table51_sbr_min", "SBR' min -62 dB (Table 5.1 [27])", -62.0, "dB", rat_lo, 0.05,
               "ratio-style: weakest detectable signal over the strongest background where it is detectable; limited "
               "by the background's shot noise (background_activation) rather than by V_sat"});
  f.push_back({kId, "table51_accuracy_min", "range accuracy min 0.6 mm (Table 5.1 [27])", 0.6e-3, "m", acc, 0.05,
               "the thesis copies the chip's effective-area std; ours at the nominal point (see std_effective_area)"});
  f.push_back({kId, "table51_accuracy_max", "range accuracy max 1.5 mm (Table 5.1 [27])", 1.5e-3, "m", worst, 0.25,
               "the thesis copies the chip's maximum error; ours as max_error_effective_area"});
  // What each agreement is worth (table --published): tuned, arithmetic or predicted.
  using B = FigureBasis;
  set_basis(f, "sbr_min_48dB_background", B::Predicted);
  set_basis(f, "even_harmonic_suppression", B::Predicted);
  set_basis(f, "even_harmonic_suppression_duty", B::Calibrated, "correlator.reference_duty_cycle", {},
            "set to the duty that gives -13 dB in this figure's variant only");
  set_basis(f, "frame_rate_2000fps", B::Calibrated, "readout.row_cycles");
  set_basis(f, "std_effective_area", B::Calibrated, "optics.baseline_m");
  set_basis(f, "max_error_effective_area", B::Predicted, "", {}, "max/std ratio at the calibrated geometry");
  set_basis(f, "std_full_area", B::Predicted);
  set_basis(f, "max_error_full_area", B::Predicted);
  set_basis(f, "averaging_exponent", B::Predicted);
  set_basis(f, "signal_span", B::Calibrated, "correlator.transconductance_S");
  set_basis(f, "background_span", B::Predicted);
  set_basis(f, "table51_sbr_max", B::Arithmetic, "", {}, "the grid's top signal over its lowest background");
  set_basis(f, "table51_sbr_min", B::Predicted);
  set_basis(f, "table51_accuracy_min", B::Calibrated, "optics.baseline_m", {}, "the same value as std_effective_area");
  set_basis(f, "table51_accuracy_max", B::Predicted, "", {}, "the same value as max_error_effective_area");
  return f;
}

}  // namespace rangesim::golden
