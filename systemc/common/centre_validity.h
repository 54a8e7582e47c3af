#pragma once
// The validity rule of a light-section row (ls-conventional and ls-demodulation range maps): the
// row's centre counts when at least `min_fraction` of its `of` detection attempts (samplings,
// correlation decisions) found the spot, at least one did, and the centre lies `margin_px` inside
// the first and last column (nearer, the spot may be clipped by the array's edge, and a spot
// centred just outside still lights the edge column).
namespace rangesim::systemc {

inline bool centre_valid(int found, int of, double centre_px, int columns, double min_fraction, double margin_px) {
  const double fraction = static_cast<double>(found) / of;
  return found > 0 && fraction >= min_fraction * (1 - 1e-12) && centre_px >= margin_px &&
         centre_px <= columns - 1 - margin_px;
}

}  // namespace rangesim::systemc
