// rangesim.kernels: the clock kernels of the readout blocks (systemc/<sensor>/*_kernel.h), made
// from a preset (Sensor.kernel(block)) and driven cycle by cycle or transaction by transaction,
// as a Python testbench's reference model. The kernels are the ones the SystemC modules, the
// co-simulation scoreboards and the sweeps run; the bindings only check the arguments the C++
// API leaves to assertions, so a bad call raises rangesim.Error instead of corrupting state.
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "core/ls_conventional/config.h"
#include "core/tof_lockin/config.h"
#include "core/tof_spad/config.h"
#include "python/bindings.h"
#include "python/kernel_blocks.h"
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_conventional/centre_processor_kernel.h"
#include "systemc/ls_conventional/multisampling_sequencer_kernel.h"
#include "systemc/tof_lockin/column_adc_kernel.h"
#include "systemc/tof_lockin/lockin_gate_generator_kernel.h"

namespace rangesim::python {

namespace {

using systemc::ActivationRow;
using systemc::AddressSearchKernel;
using systemc::AddressSearchPins;
using systemc::AddressSearchResult;
using systemc::CentreProcessorKernel;
using systemc::CentreProcessorPins;
using systemc::MultisamplingSequencerKernel;
using systemc::MultisamplingSequencerPins;
using systemc::lockin::ColumnAdcKernel;
using systemc::lockin::LockinGateGeneratorKernel;

void require_range(const std::string& key, long long v, long long lo, long long hi) {
  if (v < lo || v > hi) bad_argument(key, fmt::format("{} = {}: allowed {} .. {}", key, v, lo, hi));
}

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
  py::class_<AddressSearchKernel>(
      k, "AddressSearch",
      "Row address search (ls-conventional): latches a row's activation bits on start, settles for "
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

void bind_centre_processor(py::module_& k) {
  py::class_<CentreProcessorPins>(k, "CentreProcessorPins", "Output of one row's centre processor.")
      .def_readonly("valid", &CentreProcessorPins::valid)
      .def_readonly("centre_q", &CentreProcessorPins::centre_q)
      .def_readonly("sum", &CentreProcessorPins::sum)
      .def_readonly("count", &CentreProcessorPins::count)
      .def_property_readonly("centre_px", &CentreProcessorPins::centre_px)
      .def_property_readonly("exact_centre_px", &CentreProcessorPins::exact_centre_px)
      .def(py::self == py::self)
      .def("__repr__", [](const CentreProcessorPins& p) {
        return fmt::format("CentreProcessorPins(valid={}, centre_q={}, sum={}, count={})", p.valid ? "True" : "False",
                           p.centre_q, p.sum, p.count);
      });
  py::class_<CentreProcessorKernel>(
      k, "CentreProcessor",
      "One row's centre processor (ls-conventional): accumulates left + right of every streamed sampling; "
      "centre = sum / (2 n) in Q(address_bits).8 (systemc/ls_conventional/centre_processor_kernel.h).")
      .def(py::init([](int address_bits) {
             require_range("address_bits", address_bits, 1, 20);
             return CentreProcessorKernel(address_bits);
           }),
           py::arg("address_bits"))
      .def(
          "tick",
          [](CentreProcessorKernel& c, bool clear, const AddressSearchPins& search) {
            c.tick(clear, search);
            return c.pins();
          },
          py::arg("clear") = false, py::arg("search") = AddressSearchPins{},
          "One rising edge with the row search's pins of the ending cycle; returns the new pins.")
      .def("accumulate", &CentreProcessorKernel::accumulate, py::arg("result"),
           "A whole sampling's stream at once (the transaction).")
      .def("clear", &CentreProcessorKernel::clear)
      .def_property_readonly("pins", &CentreProcessorKernel::pins)
      .def_property_readonly("address_bits", &CentreProcessorKernel::address_bits);
}

void bind_sequencer(py::module_& k) {
  py::class_<MultisamplingSequencerPins>(k, "SequencerPins", "Output ports of the readout sequencer in one cycle.")
      .def_property_readonly("phase",
                             [](const MultisamplingSequencerPins& p) { return systemc::readout_phase_name(p.phase); })
      .def_readonly("pix_reset", &MultisamplingSequencerPins::pix_reset)
      .def_readonly("latch", &MultisamplingSequencerPins::latch)
      .def_readonly("search_start", &MultisamplingSequencerPins::search_start)
      .def_readonly("frame_done", &MultisamplingSequencerPins::frame_done)
      .def_readonly("sampling", &MultisamplingSequencerPins::sampling)
      .def_readonly("frame", &MultisamplingSequencerPins::frame)
      .def(py::self == py::self)
      .def("__repr__", [](const MultisamplingSequencerPins& p) {
        return fmt::format("SequencerPins(phase='{}', sampling={}, frame={}, search_start={:d}, frame_done={:d})",
                           systemc::readout_phase_name(p.phase), p.sampling, p.frame, p.search_start, p.frame_done);
      });
  py::class_<MultisamplingSequencerKernel>(
      k, "MultisamplingSequencer",
      "The ls-conventional readout sequencer of one frame access: reset, N samplings (latch, search, address "
      "stream), output (systemc/ls_conventional/multisampling_sequencer_kernel.h).")
      .def(
          "tick",
          [](MultisamplingSequencerKernel& s, bool rst) {
            s.tick(rst);
            return s.pins();
          },
          py::arg("rst") = false, "One rising clock edge; returns the pins of the new cycle.")
      .def_property_readonly("pins", &MultisamplingSequencerKernel::pins)
      .def("pins_at", &MultisamplingSequencerKernel::pins_at, py::arg("cycle"))
      .def_property_readonly("cycle", &MultisamplingSequencerKernel::cycle)
      .def_property_readonly("cycle_in_frame", &MultisamplingSequencerKernel::cycle_in_frame)
      .def_property_readonly("frame_cycles", &MultisamplingSequencerKernel::frame_cycles)
      .def_property_readonly("samplings", &MultisamplingSequencerKernel::samplings)
      .def("next_event_cycle", &MultisamplingSequencerKernel::next_event_cycle)
      .def(
          "advance_to",
          [](MultisamplingSequencerKernel& s, long long cycle) {
            if (cycle < s.cycle())
              bad_argument("cycle", fmt::format("cycle = {}: allowed >= the current cycle {}", cycle, s.cycle()));
            s.advance_to(cycle);
            return s.pins();
          },
          py::arg("cycle"), "Jumps to a later cycle as if ticked (event skipping); returns its pins.");
}

void bind_lockin(py::module_& k) {
  py::class_<LockinGateGeneratorKernel>(
      k, "LockinGateGenerator",
      "tof-lockin gate timing: per accumulation period PHASE1 (TX1, light), PHASE2 (TX2), PHASE3 (TXD) "
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
                              "tof-lockin column ADC: code = floor(v / LSB) clipped to 0 .. 2^bits - 1 "
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

}  // namespace

void bind_kernels(py::module_& m, SensorClass& sensor) {
  py::module_ k = m.def_submodule("kernels", "The clock kernels of the readout blocks, step by step (docs/python.md).");
  bind_activation_row(k);
  bind_address_search(k);
  bind_centre_processor(k);
  bind_sequencer(k);
  bind_lockin(k);
  bind_tdc(k);

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

// ---- the blocks a preset makes ----

namespace {

py::object make_address_search(const ParamSet& p) {
  const LsConventionalConfig c = ls_conventional_from_params(p);
  return py::cast(AddressSearchKernel(c.search, c.timing.search_cycles));
}
py::object make_centre_processor(const ParamSet& p) {
  return py::cast(CentreProcessorKernel(ls_conventional_from_params(p).search.address_bits));
}
py::object make_sequencer(const ParamSet& p) {
  const LsConventionalConfig c = ls_conventional_from_params(p);
  return py::cast(MultisamplingSequencerKernel(c.timing, c.multisampling.samplings));
}
py::object make_gate_generator(const ParamSet& p) {
  return py::cast(LockinGateGeneratorKernel(tof_lockin_from_params(p)));
}
py::object make_column_adc(const ParamSet& p) { return py::cast(ColumnAdcKernel(tof_lockin_from_params(p))); }

}  // namespace

const std::vector<KernelBlock>& kernel_blocks() {
  // Block names as in rtl/, systemc/ and tb/ (one block, one name); the sensor is the preset id
  // whose configuration sizes the block.
  static const std::vector<KernelBlock> list = {
      {"multisampling_sequencer", "ls-conventional", "readout sequencer of a frame access (MultisamplingSequencer)",
       &make_sequencer},
      {"address_search", "ls-conventional", "row address search with bit-serial addresses (AddressSearch)",
       &make_address_search},
      {"centre_processor", "ls-conventional", "row centre processor (CentreProcessor)", &make_centre_processor},
      {"lockin_gate_generator", "tof-lockin", "gate timing PHASE1/2/3 (LockinGateGenerator)", &make_gate_generator},
      {"column_adc", "tof-lockin", "column ADC (ColumnAdc)", &make_column_adc},
      {"tdc", "tof-spad", "TDC shared by a group of columns, hit by hit (TdcGroup)", &make_tdc_group},
  };
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
