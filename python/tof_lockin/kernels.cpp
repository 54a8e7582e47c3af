// rangesim.kernels for tof-lockin: the gate generator and the column ADC, and the blocks its
// preset makes.
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "core/tof_lockin/config.h"
#include "python/kernel_blocks.h"
#include "systemc/tof_lockin/column_adc_kernel.h"
#include "systemc/tof_lockin/lockin_gate_generator_kernel.h"

namespace rangesim::python {

namespace {

using systemc::lockin::ColumnAdcKernel;
using systemc::lockin::LockinGateGeneratorKernel;

void bind_lockin(py::module_& k) {
  py::class_<LockinGateGeneratorKernel>(
      k, "LockinGateGenerator",
      "Gate timing: per accumulation period PHASE1 (TX1, light), PHASE2 (TX2), PHASE3 (TXD) "
      "(systemc/tof_lockin/lockin_gate_generator_kernel.h).")
      .def("start", &LockinGateGeneratorKernel::start, "First cycle of PHASE1 of accumulation 0.")
      .def_property_readonly("done", &LockinGateGeneratorKernel::done)
      .def_property_readonly("phase",
                             [](const LockinGateGeneratorKernel& g) { return systemc::lockin::phase_name(g.phase()); })
      .def_property_readonly("tx1", &LockinGateGeneratorKernel::tx1)
      .def_property_readonly("tx2", &LockinGateGeneratorKernel::tx2)
      .def_property_readonly("txd", &LockinGateGeneratorKernel::txd)
      .def_property_readonly("light", &LockinGateGeneratorKernel::light)
      .def_property_readonly("cycle_in_period", &LockinGateGeneratorKernel::cycle_in_period)
      .def_property_readonly("accumulation", &LockinGateGeneratorKernel::accumulation)
      .def("cycles_to_edge", &LockinGateGeneratorKernel::cycles_to_edge)
      .def(
          "advance",
          [](LockinGateGeneratorKernel& g, long long n) {
            if (g.done()) bad_argument("advance", "advance: the frame's accumulations are done; start() first");
            require_range("n", n, 1, g.cycles_to_edge());
            return g.advance(n);
          },
          py::arg("n") = 1,
          "Advances n cycles (1 .. cycles_to_edge()); returns whether a window closed at the end of them.")
      .def("finish_all", &LockinGateGeneratorKernel::finish_all)
      .def_property_readonly("t0_cycles", &LockinGateGeneratorKernel::t0_cycles)
      .def_property_readonly("period_cycles", &LockinGateGeneratorKernel::period_cycles)
      .def_property_readonly("accumulations", &LockinGateGeneratorKernel::accumulations)
      .def(
          "window_open",
          [](const LockinGateGeneratorKernel& g, int w) {
            require_range("window", w, 0, 2);
            return g.window_open(w);
          },
          py::arg("window"))
      .def(
          "window_close",
          [](const LockinGateGeneratorKernel& g, int w) {
            require_range("window", w, 0, 2);
            return g.window_close(w);
          },
          py::arg("window"));
  py::class_<ColumnAdcKernel>(k, "ColumnAdc",
                              "Column ADC: code = floor(v / LSB) clipped to 0 .. 2^bits - 1 "
                              "(systemc/tof_lockin/column_adc_kernel.h).")
      .def("code", &ColumnAdcKernel::code, py::arg("v"), "One conversion (volts -> code).")
      .def(
          "codes",
          [](const ColumnAdcKernel& a, py::array_t<double, py::array::forcecast> v) {
            py::array_t<long long> out(v.request().shape);
            const double* in = v.data();
            long long* o = out.mutable_data();
            for (py::ssize_t i = 0; i < v.size(); ++i) o[i] = a.code(in[i]);
            return out;
          },
          py::arg("v"), "Conversions of an array of voltages, one call.")
      .def("value_V", &ColumnAdcKernel::value_V, py::arg("code"))
      .def_property_readonly("lsb_V", &ColumnAdcKernel::lsb_V)
      .def_property_readonly("top_code", &ColumnAdcKernel::top_code)
      .def_property_readonly("conversion_cycles", &ColumnAdcKernel::conversion_cycles);
}

py::object make_gate_generator(const ParamSet& p) {
  return py::cast(LockinGateGeneratorKernel(tof_lockin_from_params(p)));
}
py::object make_column_adc(const ParamSet& p) { return py::cast(ColumnAdcKernel(tof_lockin_from_params(p))); }

}  // namespace

void tof_lockin_bind_kernels(py::module_& k) { bind_lockin(k); }

std::vector<KernelBlock> tof_lockin_kernel_blocks() {
  return {
      {"lockin_gate_generator", "gate timing PHASE1/2/3 (LockinGateGenerator)", &make_gate_generator},
      {"column_adc", "column ADC (ColumnAdc)", &make_column_adc},
  };
}

}  // namespace rangesim::python
