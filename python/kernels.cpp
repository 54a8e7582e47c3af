// rangesim.kernels: the clock kernels of the readout blocks (systemc/<sensor>/*_kernel.h), made
// from a preset (Sensor.kernel(block)) and driven cycle by cycle or transaction by transaction,
// as a Python testbench's reference model. The kernels are the ones the SystemC modules, the
// co-simulation scoreboards and the sweeps run; the bindings only check the arguments the C++
// API leaves to assertions, so a bad call raises rangesim.Error instead of corrupting state.
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "python/bindings.h"
#include "python/kernel_blocks.h"
#include "core/sensor_registry.h"
#include "systemc/common/address_search_kernel.h"

namespace rangesim {
#define RANGESIM_DECLARE(s) const SensorInfo& s##_sensor_info();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE
}  // namespace rangesim

namespace rangesim::python {

void require_range(const std::string& key, long long v, long long lo, long long hi) {
  if (v < lo || v > hi) bad_argument(key, fmt::format("{} = {}: allowed {} .. {}", key, v, lo, hi));
}

namespace {

using systemc::ActivationRow;
using systemc::AddressSearchKernel;
using systemc::AddressSearchPins;
using systemc::AddressSearchResult;

// An activation row from a Python value: an ActivationRow, or a sequence / array of truth values.
ActivationRow to_row(const py::handle& act) {
  if (py::isinstance<ActivationRow>(act)) return act.cast<ActivationRow>();
  // Null (the Python error cleared) when `act` is not convertible to truth values.
  const auto bits = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(act);
  if (!bits || bits.ndim() != 1)
    bad_argument("act", "act: allowed an ActivationRow or a 1-D sequence of truth values, one per column");
  ActivationRow row(static_cast<int>(bits.size()));
  const auto b = bits.unchecked<1>();
  for (py::ssize_t c = 0; c < bits.size(); ++c)
    if (b(c)) row.set(static_cast<int>(c));
  return row;
}

// The row as the kernel needs it: `columns` wide (the C++ kernel asserts the width).
ActivationRow row_for(const AddressSearchKernel& k, const py::handle& act) {
  ActivationRow row = to_row(act);
  if (row.columns() != k.config().columns)
    bad_argument("act",
                 fmt::format("act: {} columns; allowed: the search's {} columns", row.columns(), k.config().columns));
  return row;
}

void bind_activation_row(py::module_& k) {
  py::class_<ActivationRow>(k, "ActivationRow",
                            "Activation bits of one row (column c is bit c), as the address search latches them.")
      .def(py::init<int>(), py::arg("columns"))
      .def(py::init([](const py::object& bits) { return to_row(bits); }), py::arg("bits"))
      .def_property_readonly("columns", &ActivationRow::columns)
      .def(
          "set",
          [](ActivationRow& r, int c, bool v) {
            require_range("column", c, 0, r.columns() - 1);
            r.set(c, v);
          },
          py::arg("column"), py::arg("value") = true)
      .def(
          "test",
          [](const ActivationRow& r, int c) {
            require_range("column", c, 0, r.columns() - 1);
            return r.test(c);
          },
          py::arg("column"))
      .def("clear", &ActivationRow::clear)
      .def("any", &ActivationRow::any)
      .def("first", &ActivationRow::first, "Lowest activated column, -1 if none.")
      .def("last", &ActivationRow::last, "Highest activated column, -1 if none.")
      .def("bits",
           [](const ActivationRow& r) {
             py::array_t<bool> a(r.columns());
             auto m = a.mutable_unchecked<1>();
             for (int c = 0; c < r.columns(); ++c) m(c) = r.test(c);
             return a;
           })
      .def("__str__", &ActivationRow::to_string)
      .def("__repr__", [](const ActivationRow& r) { return "ActivationRow('" + r.to_string() + "')"; })
      .def(py::self == py::self);
}

void bind_address_search(py::module_& k) {
  py::class_<AddressSearchPins>(k, "AddressSearchPins", "Output ports of the address search during one cycle.")
      .def_readonly("busy", &AddressSearchPins::busy)
      .def_readonly("found", &AddressSearchPins::found)
      .def_readonly("addr_valid", &AddressSearchPins::addr_valid)
      .def_readonly("addr_bit", &AddressSearchPins::addr_bit)
      .def_readonly("done", &AddressSearchPins::done)
      .def(py::self == py::self)
      .def("__repr__", [](const AddressSearchPins& p) {
        return fmt::format("AddressSearchPins(busy={:d}, found={:d}, addr_valid={:d}, addr_bit={:d}, done={:d})",
                           p.busy, p.found, p.addr_valid, p.addr_bit, p.done);
      });
  py::class_<AddressSearchResult>(k, "AddressSearchResult", "One search operation: its transaction.")
      .def_readonly("found", &AddressSearchResult::found)
      .def_readonly("left", &AddressSearchResult::left)
      .def_readonly("right", &AddressSearchResult::right)
      .def_readonly("done_cycle", &AddressSearchResult::done_cycle)
      .def("__repr__", [](const AddressSearchResult& r) {
        return fmt::format("AddressSearchResult(found={}, left={}, right={}, done_cycle={})",
                           r.found ? "True" : "False", r.left, r.right, r.done_cycle);
      });
  py::class_<AddressSearchKernel>(k, "AddressSearch",
                                  "Row address search: latches a row's activation bits on start, settles for "
                                  "search_cycles, then streams the left and right addresses MSB first on addr_bit "
                                  "(systemc/common/address_search_kernel.h; rtl/common/address_search.sv).")
      .def(py::init([](int columns, int address_bits, int search_cycles) {
             return AddressSearchKernel(AddressSearchConfig{columns, address_bits, 2}, search_cycles);
           }),
           py::arg("columns"), py::arg("address_bits"), py::arg("search_cycles"))
      .def(
          "tick",
          [](AddressSearchKernel& s, bool rst, bool start, const py::object& act) {
            // The row is read only when this edge latches it; then it must be given and fit.
            if (!rst && start && s.idle()) {
              if (act.is_none()) bad_argument("act", "act: start on an idle search latches a row; give it");
              if (py::isinstance<ActivationRow>(act)) {  // no copy: the common case of a testbench loop
                const auto& row = act.cast<const ActivationRow&>();
                if (row.columns() == s.config().columns) {
                  s.tick(rst, start, row);
                  return s.pins();
                }
              }
              s.tick(rst, start, row_for(s, act));
            } else {
              static const ActivationRow unused;
              s.tick(rst, start, unused);
            }
            return s.pins();
          },
          py::arg("rst") = false, py::arg("start") = false, py::arg("act") = py::none(),
          "One rising clock edge with the inputs of the ending cycle; returns the pins of the new cycle.")
      .def("reset", &AddressSearchKernel::reset)
      .def_property_readonly("pins", &AddressSearchKernel::pins)
      .def_property_readonly("idle", &AddressSearchKernel::idle)
      .def_property_readonly("edges", &AddressSearchKernel::edges)
      .def(
          "run",
          [](AddressSearchKernel& s, const py::object& act) {
            if (!s.idle()) bad_argument("run", "run: the search is busy; allowed on an idle search (reset() first)");
            return s.run(row_for(s, act));
          },
          py::arg("act"), "A whole operation tick by tick, the addresses decoded from the addr_bit stream.")
      .def(
          "evaluate", [](const AddressSearchKernel& s, const py::object& act) { return s.evaluate(row_for(s, act)); },
          py::arg("act"), "The same transaction in closed form (no ticks).")
      .def("operation_cycles", &AddressSearchKernel::operation_cycles, py::arg("found"))
      .def_property_readonly("columns", [](const AddressSearchKernel& s) { return s.config().columns; })
      .def_property_readonly("address_bits", [](const AddressSearchKernel& s) { return s.config().address_bits; })
      .def_property_readonly("search_cycles", &AddressSearchKernel::search_cycles);
}

}  // namespace

void bind_kernels(py::module_& m, SensorClass& sensor) {
  py::module_ k = m.def_submodule("kernels", "The clock kernels of the readout blocks, step by step (docs/python.md).");
  bind_activation_row(k);
  bind_address_search(k);
#define RANGESIM_BIND(s) s##_bind_kernels(k);
  RANGESIM_FOR_EACH_SENSOR(RANGESIM_BIND)
#undef RANGESIM_BIND

  k.def(
      "blocks",
      [] {
        py::list l;
        for (const auto& b : kernel_blocks())
          l.append(py::dict(py::arg("block") = b.block, py::arg("sensor") = b.sensor, py::arg("what") = b.what));
        return l;
      },
      "The blocks Sensor.kernel() makes: block, sensor (preset id) and what it is.");
  sensor.def(
      "kernels",
      [](const Sensor& s) {
        std::vector<std::string> names;
        for (const auto& b : kernel_blocks())
          if (b.sensor == s.params.sensor_id()) names.push_back(b.block);
        return names;
      },
      "The blocks whose kernels this sensor's preset makes (Sensor.kernel(block)).");
  sensor.def(
      "kernel", [](const Sensor& s, const std::string& block) { return make_kernel(s.params, block); },
      py::arg("block"),
      "The clock kernel of one readout block, sized by this preset (rangesim.kernels; e.g. \"address_search\").");
}

const std::vector<KernelBlock>& kernel_blocks() {
  // Each sensor's blocks in registry order (core/sensor_list.h), the sensor filled in from the
  // registration so that a block's own file never repeats its id.
  static const std::vector<KernelBlock> list = [] {
    std::vector<KernelBlock> l;
#define RANGESIM_APPEND(s)                    \
  for (KernelBlock b : s##_kernel_blocks()) { \
    b.sensor = s##_sensor_info().id;          \
    l.push_back(std::move(b));                \
  }
    RANGESIM_FOR_EACH_SENSOR(RANGESIM_APPEND)
#undef RANGESIM_APPEND
    return l;
  }();
  return list;
}

py::object make_kernel(const ParamSet& params, const std::string& block) {
  std::string mine, elsewhere;
  for (const auto& b : kernel_blocks()) {
    if (b.sensor == params.sensor_id()) {
      if (b.block == block) return b.make(params);
      mine += (mine.empty() ? "" : ", ") + b.block;
    } else if (b.block == block) {
      elsewhere = b.sensor;
    }
  }
  bad_argument("block", fmt::format("block = \"{}\": {}; allowed for {}: {}", block,
                                    elsewhere.empty() ? "no such block" : "a block of " + elsewhere, params.sensor_id(),
                                    mine.empty() ? "(none)" : mine));
}

}  // namespace rangesim::python
