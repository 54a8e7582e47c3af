#pragma once
// One look for every plot the command writes (gnuplot script fragments): perceptually uniform
// colour maps (viridis for magnitudes, a blue-white-red diverging map for signed errors), a
// colour-blind-safe line palette whose styles stay apart where curves coincide, engineering
// notation on logarithmic axes (1k, 10µ) and colour-bar ticks at 1-2-5 steps.
#include <string>
#include <vector>

#include "app/matrix_rows.h"

namespace rangesim::app {

// `set encoding utf8`, `set micro` (µ in prefixes) and the shared defaults (outward tics, dotted grid); after `set
// terminal`.
std::string plot_preamble();
// `set palette defined (...)` of viridis (magnitudes) or of a diverging map around 0 (signed
// values: give it a symmetric cbrange).
std::string viridis_palette();
std::string diverging_palette();
// `set format <axis> '...'` for a logarithmic axis in `unit`: SI prefixes (100m, 1, 10k) for a unit
// that takes them, plain %g (0.001, 1e-05) for dimensionless ones, px, dB and the like.
std::string log_format(const std::string& axis, const std::string& unit);
// `set cbtics (...)` at 1, 2 and 5 per decade between lo and hi (both > 0), labelled %g; "" when
// the range holds no such value.
std::string log_cbtics(double lo, double hi);
// The style of the i-th curve of a line plot: colour, dash, point type and a line width that
// shrinks with i, so a curve drawn over an identical earlier one leaves that one visible.
std::string series_style(std::size_t i);
// Only the colour of the i-th series, "#rrggbb" (points and their model curve share it).
std::string series_colour(std::size_t i);
// Minimum and maximum of the finite values (NaN, NaN when none).
std::pair<double, double> finite_range(MatrixRows rows);

}  // namespace rangesim::app
