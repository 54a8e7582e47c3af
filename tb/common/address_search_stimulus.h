#pragma once
// Stimulus generator of the row address search (address_search, shared by ls-conventional and
// ls-demodulation), part of the installed verification kit (rangesim::cosim_kit): the random rows
// rangesim's own co-simulation drives (tb/common/address_search_cosim.cpp), so a user's testbench
// can drive the same kind of rows into their RTL and into rangesim's reference kernel
// (systemc/common/address_search_kernel.h). The same generator state gives the same rows.
#include <random>

#include "systemc/common/address_search_kernel.h"

namespace rangesim::tb {

// A laser sheet lights a narrow run of columns (1..5 wide, anywhere) with 0..2 false
// activations; 15 % of the rows are empty and 10 % dense noise, so the search sees every corner
// (empty, single, both ends, full).
inline systemc::ActivationRow random_address_search_row(int columns, std::mt19937_64& rng) {
  systemc::ActivationRow row(columns);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::uniform_int_distribution<int> col(0, columns - 1);
  const double kind = u(rng);
  if (kind < 0.15) return row;  // nothing detected
  if (kind < 0.25) {            // dense noise
    for (int c = 0; c < columns; ++c) row.set(c, u(rng) < 0.5);
    return row;
  }
  const int centre = col(rng);
  const int half = std::uniform_int_distribution<int>(0, 2)(rng);
  for (int c = centre - half; c <= centre + half; ++c) {
    if (c >= 0 && c < columns) row.set(c);
  }
  const int noise = std::uniform_int_distribution<int>(0, 2)(rng);
  for (int i = 0; i < noise; ++i) row.set(col(rng));
  return row;
}

}  // namespace rangesim::tb
