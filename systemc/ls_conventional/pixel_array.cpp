#include "systemc/ls_conventional/pixel_array.h"

namespace rangesim::systemc {

PixelArray::PixelArray(sc_core::sc_module_name name, const LsConventionalConfig& config,
                       const PixelArrayOptions& options, StimulusSource source)
    : sc_core::sc_module(name), kernel_(config, options, std::move(source)) {
  act_o.init(static_cast<std::size_t>(config.pixel.rows));
  for (auto& port : act_o) port.initialize(ActivationRow(config.pixel.columns));
  SC_METHOD(on_control);
  sensitive << pix_reset_i << sampling_i << frame_i;
  // Runs once at initialisation too: the array resets for frame 0 while the sensor is in reset.
}

void PixelArray::on_control() {
  if (!kernel_.control(pix_reset_i.read(), frame_i.read(), static_cast<int>(sampling_i.read()))) return;
  for (int r = 0; r < kernel_.rows(); ++r) act_o[static_cast<std::size_t>(r)].write(kernel_.row(r));
}

}  // namespace rangesim::systemc
