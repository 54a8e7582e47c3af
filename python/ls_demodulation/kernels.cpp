// rangesim.kernels for ls-demodulation: its row search is the address search every sensor may share
// (bound in python/kernels.cpp), sized and timed as the sensor kernel runs it.
#include "core/ls_demodulation/config.h"
#include "python/kernel_blocks.h"
#include "systemc/ls_demodulation/sensor_kernel.h"

namespace rangesim::python {

namespace {

py::object make_address_search(const ParamSet& p) {
  return py::cast(systemc::demod_address_search(ls_demodulation_from_params(p)));
}

}  // namespace

void ls_demodulation_bind_kernels(py::module_&) {}

std::vector<KernelBlock> ls_demodulation_kernel_blocks() {
  return {
      {"address_search", "row address search, time-multiplexed over the rows (AddressSearch)", &make_address_search}};
}

}  // namespace rangesim::python
