#pragma once
// The images of `rangesim simulate`, the same for every sensor: range_map.png and, where the scene
// gives a ground truth, range_error.png.
#include <string>

#include "app/output_dir.h"
#include "systemc/common/simulation.h"

namespace rangesim::app {

// Stages range_map.png (valid ranges on viridis, invalid pixels blank, one pixel a square) and
// range_error.png (range - truth on a diverging map symmetric about 0, where both exist), drawn
// in-process (app/simulate/map_image.h). Returns "" or a warning (none at present; a write error
// throws).
std::string render_range_map(OutputDir& out, const systemc::RangeMap& map);

}  // namespace rangesim::app
