// rangesim evaluate: the thesis's background-light and range-accuracy evaluation over a
// log-spaced signal x background grid, written as CSV maps, summary.json and plots.
#include <fmt/format.h>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/evaluate_params.h"
#include "app/evaluation_output.h"
#include "app/output_dir.h"
#include "app/plot.h"
#include "app/progress_line.h"
#include "core/preset.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::app {

namespace {

// Golden models report progress through a plain function pointer, hence the one line here.
ProgressLine* g_progress = nullptr;
void report_progress(int done, int total) {
  if (g_progress) g_progress->update(done, total);
}

// The schema key that starts with `prefix` (e.g. "evaluation.signal_min_"), or "".
std::string key_with_prefix(const ParamSchema& schema, const std::string& prefix) {
  for (const auto& p : schema.params)
    if (p.key.rfind(prefix, 0) == 0) return p.key;
  return "";
}

std::string key_with_suffix(const ParamSchema& schema, const std::string& suffix) {
  for (const auto& p : schema.params)
    if (p.key.size() >= suffix.size() && p.key.compare(p.key.size() - suffix.size(), suffix.size(), suffix) == 0)
      return p.key;
  return "";
}

void require_key(const std::string& key, const std::string& flag, const ParamSet& params, const std::string& what) {
  if (key.empty())
    throw UserError(fmt::format("{}: sensor {} has no {} parameter (see `rangesim show {}`)", flag, params.sensor_id(),
                                what, params.sensor_id()),
                    flag.substr(2));
}

void apply_grid(ParamSet& params, const ParamSchema& schema, const std::string& axis, const std::string& text) {
  const std::string flag = "--" + axis;
  const GridAxis g = parse_grid_axis(text, flag);
  const std::string lo = key_with_prefix(schema, "evaluation." + axis + "_min_");
  const std::string hi = key_with_prefix(schema, "evaluation." + axis + "_max_");
  require_key(lo, flag, params, "evaluation grid");
  params.set_real(lo, g.lo, flag, schema);
  params.set_real(hi, g.hi, flag, schema);
  params.set_integer("evaluation." + axis + "_points", g.n, flag, schema);
}

}  // namespace

ParamSet evaluate_params(const EvaluateOptions& opt) {
  ParamSet params = load_modelled_preset(opt.sensor, "evaluate", opt.settings);
  apply_evaluate_flags(params, opt);
  return params;
}

void apply_evaluate_flags(ParamSet& params, const EvaluateOptions& opt) {
  const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
  if (opt.samplings) {
    require_key(schema.find("multisampling.samplings") ? "multisampling.samplings" : "", "--samplings", params,
                "samplings");
    params.set_integer("multisampling.samplings", *opt.samplings, "--samplings", schema);
  }
  if (opt.adc_bits) {
    const std::string key = key_with_suffix(schema, ".adc_bits");
    require_key(key, "--adc-bits", params, "ADC bits");
    params.set_integer(key, *opt.adc_bits, "--adc-bits", schema);
  }
  if (opt.frames) {
    require_key(schema.find("evaluation.frames_averaged") ? "evaluation.frames_averaged" : "", "--frames", params,
                "frame-averaging");
    params.set_integer("evaluation.frames_averaged", *opt.frames, "--frames", schema);
  }
  if (opt.signal) apply_grid(params, schema, "signal", *opt.signal);
  if (opt.background) apply_grid(params, schema, "background", *opt.background);
}

int run_evaluate(const EvaluateOptions& opt) {
  // Validate everything before computing or touching the output directory.
  const ParamSet params = evaluate_params(opt);
  const std::string dir = opt.out.empty() ? "rangesim-out/" + params.sensor_id() : opt.out;
  OutputDir out(dir, "--out", {"evaluate", opt.force});

  ProgressLine progress("evaluate", "operating points");
  g_progress = &progress;
  const golden::EvalResult ev = golden::evaluate_sensor(params, &report_progress);
  g_progress = nullptr;

  out.write("points.csv", points_csv(ev));
  out.write("detectable_area.csv", detect_matrix_csv(ev));
  out.write("accuracy_mm.csv", accuracy_mm_matrix_csv(ev));
  for (const auto& m : ev.metric_names)
    if (m == "accuracy_px") out.write("accuracy_px.csv", metric_matrix_csv(ev, m));
  const std::string plot_warning = opt.no_plots ? "" : render_plots(out, ev);
  nlohmann::json summary = summary_json(ev, params);
  out.write("summary.json", summary.dump(2) + "\n");
  const std::vector<std::string> written = out.commit();
  summary["files"] = written;

  if (!plot_warning.empty()) fmt::print(stderr, "rangesim evaluate: warning: {}\n", plot_warning);
  if (opt.json) {
    fmt::print("{}\n", summary.dump(2));
    return 0;
  }
  fmt::print("{}\noutputs in {}/: ", summary_text(ev), dir);
  for (size_t i = 0; i < written.size(); ++i)
    fmt::print("{}{}", i ? ", " : "", written[i].substr(written[i].find_last_of('/') + 1));
  fmt::print("\n");
  return 0;
}

}  // namespace rangesim::app
