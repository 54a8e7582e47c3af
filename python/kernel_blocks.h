#pragma once
// The readout blocks whose clock kernels a preset makes for Python (Sensor.kernel(block)): one
// entry per block, looked up by the loaded preset's sensor id and the block's name. Each sensor's
// blocks and kernel classes are in python/<sensor>/kernels.cpp; python/kernels.cpp binds what
// sensors share (ActivationRow, AddressSearch) and gathers the sensors' lists.
#include <string>
#include <vector>

#include "core/sensor_list.h"
#include "python/py_support.h"

namespace rangesim::python {

struct KernelBlock {
  std::string block;                      // the block's name in rtl/, systemc/ and tb/
  std::string what;                       // one line, with the Python class
  py::object (*make)(const ParamSet& p);  // the kernel from a validated preset of that sensor
  std::string sensor = {};                // preset id whose configuration sizes it (set by kernel_blocks())
};

const std::vector<KernelBlock>& kernel_blocks();
// The kernel of `block` for the preset's sensor; rangesim.Error naming the blocks it has otherwise.
py::object make_kernel(const ParamSet& params, const std::string& block);

// Each sensor's part: binds its kernel classes into rangesim.kernels (after the shared ones) and
// lists the blocks its preset makes.
#define RANGESIM_DECLARE(s)              \
  void s##_bind_kernels(py::module_& k); \
  std::vector<KernelBlock> s##_kernel_blocks();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE

// rangesim.Error naming `key` unless lo <= v <= hi.
void require_range(const std::string& key, long long v, long long lo, long long hi);

}  // namespace rangesim::python
