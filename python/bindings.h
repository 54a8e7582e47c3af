#pragma once
// The parts of the Python module, one file each (python/module.cpp puts them together).
#include <pybind11/pybind11.h>

#include "python/py_support.h"

namespace rangesim::python {

using SensorClass = py::class_<Sensor>;

// rangesim.Error and the translation of the C++ exceptions (UserError, NotModelled).
void register_errors(py::module_& m);
// presets(), load(), table(); Sensor.show(), Sensor.frame_rate() (python/verbs.cpp).
void bind_verbs(py::module_& m, SensorClass& sensor);
// Sensor.evaluate() (python/evaluate.cpp).
void bind_evaluate(SensorClass& sensor);
// Sensor.simulate() (python/simulate.cpp).
void bind_simulate(SensorClass& sensor);
// rangesim.kernels and Sensor.kernel() (python/kernels.cpp).
void bind_kernels(py::module_& m, SensorClass& sensor);

}  // namespace rangesim::python
