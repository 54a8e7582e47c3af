#pragma once
// Plots of an evaluation rendered by gnuplot as PNG and SVG: heat maps of the detectable area
// and of the accuracy (thesis Fig. 3.3-3.4, 4.4-4.5), and line plots of the 1-D sweeps.
#include <string>
#include <vector>

#include "app/output_dir.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::app {

// The cells of an axis of n points a heat map shows: all of them up to 1000, else a regular subset
// of at most 1001 with the last (a picture 900 pixels wide shows no more, and gnuplot would need
// gigabytes for a 10000 x 10000 grid).
std::vector<size_t> plot_indices(size_t n);

// Stages detectable_area.{png,svg}, accuracy.{png,svg} and <sweep id>.{png,svg} in `out`.
// Returns "" on success, otherwise a warning (gnuplot missing or failed) after removing any
// partial image; the data files are complete without plots.
std::string render_plots(OutputDir& out, const golden::EvalResult& ev);

}  // namespace rangesim::app
