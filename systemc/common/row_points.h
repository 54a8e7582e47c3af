#pragma once
// The points table of the light-section sensors (points.csv / points.npy): one record per (frame,
// row) that is visible or detected, truth beside the detected centre and range. ls-conventional's
// frames are beam positions, so it adds that column.
#include <utility>
#include <vector>

#include "systemc/common/table.h"

namespace rangesim::systemc {

inline Table row_points_table(bool beam_position) {
  using K = Table::Kind;
  std::vector<Table::Column> c = {{"frame", K::Index},   {"beam_position", K::Index},
                                  {"row", K::Index},     {"truth_visible", K::Flag},
                                  {"truth_centre_px"},   {"truth_range_m"},
                                  {"detected", K::Flag}, {"centre_px"},
                                  {"range_m"},           {"error_px"},
                                  {"error_m"},           {"valid", K::Flag},
                                  {"detecting_fraction"}};
  if (!beam_position) c.erase(c.begin() + 1);
  return Table(std::move(c));
}

}  // namespace rangesim::systemc
