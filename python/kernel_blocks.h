#pragma once
// The readout blocks whose clock kernels a preset makes for Python (Sensor.kernel(block)): one
// entry per block, looked up by the loaded preset's sensor id and the block's name.
#include <string>
#include <vector>

#include "python/py_support.h"

namespace rangesim::python {

struct KernelBlock {
  std::string block;                      // the block's name in rtl/, systemc/ and tb/
  std::string sensor;                     // preset id whose configuration sizes it
  std::string what;                       // one line, with the Python class
  py::object (*make)(const ParamSet& p);  // the kernel from a validated preset of that sensor
};

const std::vector<KernelBlock>& kernel_blocks();
// The kernel of `block` for the preset's sensor; rangesim.Error naming the blocks it has otherwise.
py::object make_kernel(const ParamSet& params, const std::string& block);

// tof-spad's TDC group (python/kernel_tdc.cpp).
void bind_tdc(py::module_& k);
py::object make_tdc_group(const ParamSet& p);

}  // namespace rangesim::python
