#pragma once
// The images of `rangesim simulate`, the same for every sensor: range_map.png and, where the scene
// gives a ground truth, range_error.png.
#include <functional>
#include <vector>

#include "app/output_dir.h"
#include "systemc/common/simulation.h"

namespace rangesim::app {

// One job per image, the costlier first, its file staged now: range_map.png (valid ranges on
// viridis, invalid pixels blank, one pixel a square) and, where a range and its truth both exist
// somewhere, range_error.png (range - truth on a diverging map symmetric about 0, to the 99th
// percentile of |range - truth|), staged in that order and run first. Each draws in-process
// (app/simulate/map_image.h) with buffers of its own, so the jobs may run on threads of their own
// while `map` lives; a write error throws std::runtime_error naming the file.
std::vector<std::function<void()>> range_map_image_jobs(OutputDir& out, const systemc::RangeMap& map);

}  // namespace rangesim::app
