// Aggregation figure of tof-lockin (app/bench/bench_aggregation.h).
#include <fmt/format.h>

#include "app/bench/bench_aggregation.h"
#include "app/bench/bench_stats.h"
#include "app/bench/bench_util.h"
#include "core/preset.h"
#include "core/tof_lockin/config.h"
#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::app::bench {

namespace {
namespace lk = rangesim::systemc::lockin;
using nlohmann::json;

struct LockinRun {
  double cpu_s = 0;            // CPU time of the timed run (the fastest where repeated)
  double first_cpu_s = 0;      // the kernel's first run (aggregated: frame means, laws, buffers set up)
  std::vector<double> tap[2];  // ADC inputs of the LED frames, all pixels, of the first run
};

// One row of `columns` identical pixels (a wall at 3 m, 0.5 nA signal, 50 pA background:
// scenes/tof-lockin-plane.toml), built outside the timing. The aggregated kernel is run once, then
// restarted in place (new streams, the frame means and laws kept) and timed `repeats` times.
LockinRun run_lockin(const TofLockinConfig& cfg, bool aggregated, int columns, long long frames, int repeats) {
  lk::LockinSimOptions o;
  o.event_skipping = aggregated;
  o.aggregate = aggregated;
  o.seed = aggregated ? 11 : 12;  // independent samples for the two-sample test
  lk::LockinPixelStimulus st{0.5e-9, 50e-12, 2 * 3.0 / 299792458.0};
  std::vector<lk::LockinPixelStimulus> stim(static_cast<std::size_t>(columns), st);
  LockinRun r;
  lk::TofLockinSensorKernel k(cfg, o, 1, columns, stim, frames);
  double c0 = cpu_now();
  k.run();
  r.first_cpu_s = r.cpu_s = cpu_now() - c0;
  for (const auto& rec : k.frame_records())
    if (rec.led_on)
      for (int c = 0; c < columns; ++c)
        for (int t = 0; t < 2; ++t) r.tap[t].push_back(k.adc_input_V(rec.frame, 0, c, t));
  for (int i = 0; i < repeats; ++i) {
    k.restart(o.seed + 100 + static_cast<std::uint64_t>(i));
    c0 = cpu_now();
    k.run();
    r.cpu_s = i == 0 ? cpu_now() - c0 : std::min(r.cpu_s, cpu_now() - c0);
  }
  return r;
}

}  // namespace

FigureSpec aggregation_figure_lockin() {
  return {"aggregated_vs_per_clock_lockin", ">= 1000",
          "tof-lockin per-clock frame time / aggregated frame time, statistically identical"};
}

json bench_aggregation_lockin(bool quick) {
  const TofLockinConfig cfg = tof_lockin_from_params(load_preset_file(resolve_preset("tof-lockin")));
  const int columns = 256;
  const long long frames = quick ? 6 : 40;  // LED + ambient frames alternate
  progress(fmt::format("tof-lockin: {} frames x {} pixels clock by clock", frames, columns));
  const LockinRun per_clock = run_lockin(cfg, false, columns, frames, 0);
  progress(fmt::format("tof-lockin: the same frames aggregated"));
  // The aggregated frames take microseconds: repeated on the restarted kernel, the fastest kept.
  const LockinRun agg = run_lockin(cfg, true, columns, frames, 20);
  const double v = per_clock.cpu_s / agg.cpu_s;
  json j{{"value", v}, {"target", ">= 1000"}, {"target_met", v >= 1000}};
  j["frames"] = frames;
  j["pixels"] = columns;
  j["accumulations_per_frame"] = cfg.gates.accumulations_per_frame;
  j["per_clock_cpu_s"] = per_clock.cpu_s;
  j["aggregated_cpu_s"] = agg.cpu_s;
  j["aggregated_first_run_cpu_s"] = agg.first_cpu_s;
  j["aggregated_ns_per_pixel_frame"] = agg.cpu_s * 1e9 / (static_cast<double>(columns) * static_cast<double>(frames));
  j["merged_draws"] = cfg.simulation.merged_draws;
  j["timing"] =
      "kernels built outside the timing; per clock one run; aggregated: the fastest of 20 runs of the kernel "
      "restarted in place after a first run (its frame means, merged-draw laws and buffers set up there, reported "
      "as aggregated_first_run_cpu_s)";
  bool same = true;
  for (int t = 0; t < 2; ++t) {
    const TwoSampleComparison c = compare_samples(agg.tap[t], per_clock.tap[t]);
    j[fmt::format("tap{}", t + 1)] = comparison_json(c);
    same = same && c.indistinguishable();
  }
  j["samples_per_tap"] = per_clock.tap[0].size();
  j["test"] =
      "per tap, ADC input of the LED frames: |mean diff| < 5 SE, |variance diff| < 5 SE, two-sample KS p >= 0.001";
  j["statistically_identical"] = same;
  return j;
}

}  // namespace rangesim::app::bench
