#pragma once
// The images of `rangesim simulate`, the same for every sensor: range_map.png and, where the scene
// gives a ground truth, range_error.png.
#include <functional>
#include <vector>

#include "app/output_dir.h"
#include "systemc/common/simulation.h"

namespace rangesim::app {

// Each image is drawn by a job in-process (app/simulate/map_image.h), with buffers of its own, so
// jobs may run on threads of their own; its file is staged when the job is made, and a write error
// throws std::runtime_error naming it.
//
// The jobs read the map's matrices through their rows only (app/matrix_rows.h), having taken its
// labels when made: they may run while the map is moved on (systemc::SimulationHost::map_ready),
// as long as its rows live and stay as they were.
//
// range_map.png: valid ranges on viridis, invalid pixels blank, one pixel a square.
std::function<void()> range_image_job(OutputDir& out, const systemc::RangeMap& map);
// range_error.png, where a range and its truth both exist somewhere (an empty function where
// not): range - truth on a diverging map symmetric about 0, to the 99th percentile of
// |range - truth|.
std::function<void()> error_image_job(OutputDir& out, const systemc::RangeMap& map);

}  // namespace rangesim::app
