#pragma once
// What the tof-lockin skipping tests compare between two runs of the sensor kernel: each tap's
// ADC input over the LED frames and the ranges of every map, for one row of `columns` pixels.
#include <vector>

#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::systemc::lockin::test {

struct Samples {
  std::vector<double> tap[2], range;
};

inline Samples led_samples(const TofLockinSensorKernel& k, int columns) {
  Samples s;
  for (const auto& rec : k.frame_records())
    if (rec.led_on)
      for (int c = 0; c < columns; ++c)
        for (int t = 0; t < 2; ++t) s.tap[t].push_back(k.adc_input_V(rec.frame, 0, c, t));
  for (long long m = 0; m < k.range_maps(); ++m)
    for (int c = 0; c < columns; ++c) s.range.push_back(k.range_m(m, 0, c));
  return s;
}

}  // namespace rangesim::systemc::lockin::test
