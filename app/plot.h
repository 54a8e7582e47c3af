#pragma once
// Heat maps of an evaluation (thesis Fig. 3.3 and 3.4) rendered by gnuplot as PNG and SVG.
#include <string>

#include "app/output_dir.h"
#include "golden/ls_conventional_eval.h"

namespace rangesim::app {

// Stages detectable_area.{png,svg} and accuracy_px.{png,svg} in `out`. Returns "" on success,
// otherwise a warning (gnuplot missing or failed); the evaluation's data files are unaffected.
std::string render_heatmaps(OutputDir& out, const golden::Evaluation& ev, const std::string& title);

}  // namespace rangesim::app
