#pragma once
// tof-lockin's scene adapter: from the one scene (scene/scene.h) to what the lock-in model
// consumes, a per-pixel depth taken from the target geometry or the depth map resampled to the
// sensor's pixel grid, and the light. Kept beside the sensor so scene/ stays one reader.
#include "core/tof_lockin/config.h"
#include "scene/scene.h"
#include "systemc/tof_lockin/lockin_scene.h"

namespace rangesim::scene {

// tof-lockin: `s` loaded with sensor "tof-lockin"; the depth map (if any) is resampled to the
// whole array of `cfg`. Throws UserError naming the file and key for a depth outside (0, 1000] m.
systemc::lockin::LockinScene to_lockin_scene(const Scene& s, const TofLockinConfig& cfg);

}  // namespace rangesim::scene
