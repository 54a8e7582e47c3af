#pragma once
// tof-lockin's scene adapter: from the one scene (scene/scene.h) to what the lock-in model
// consumes, a per-pixel depth taken from the target geometry or the depth map resampled to the
// sensor's pixel grid, and the light. Kept beside the sensor so scene/ stays one reader.
#include "core/radiometry.h"
#include "core/tof_lockin/config.h"
#include "scene/scene.h"
#include "systemc/tof_lockin/lockin_scene.h"

namespace rangesim::scene {

// tof-lockin: `s` loaded with sensor "tof-lockin"; the depth map (if any) is resampled to the
// whole array of `cfg`. Throws UserError naming the file and key for a depth outside (0, 1000] m.
// A physical scene ([ambient], [source]) is turned into photocurrents with `radiometry`
// (core/tof_lockin/radiometry.cpp) unless the file sets the sensor's own [light]; a tilted plane or
// a step with a row edge or a column index is rasterised into a depth map. `radiometry` may be
// null for a scene that needs neither. Notes go to LockinScene::notes.
systemc::lockin::LockinScene to_lockin_scene(const Scene& s, const TofLockinConfig& cfg,
                                             const SensorRadiometry* radiometry = nullptr);

}  // namespace rangesim::scene
