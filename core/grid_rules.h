#pragma once
// The evaluation grids of a preset are log-spaced from evaluation.<axis>_min_<unit> to
// evaluation.<axis>_max_<unit>: both bounds may be in range and still give points that are not
// finite numbers (a subnormal minimum, or a ratio max / min beyond the largest double), which
// would reach the output files as inf. These rules refuse such grids wherever a grid is set.
#include <string>

#include "core/params.h"

namespace rangesim {

// Why a log-spaced grid from lo to hi has points that are not finite ("" when it has none).
std::string log_grid_problem(double lo, double hi);

// The signal and background grids of the set: UserError naming the file, both keys and the allowed range.
void check_log_grids(const ParamSet& set);

}  // namespace rangesim
