// rangesim.kernels for ls-conventional: its readout sequencer and centre processor, and the blocks
// its preset makes (the address search is bound with the blocks every sensor may share,
// python/kernels.cpp).
#include <pybind11/operators.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "core/ls_conventional/config.h"
#include "python/kernel_blocks.h"
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_conventional/centre_processor_kernel.h"
#include "systemc/ls_conventional/multisampling_sequencer_kernel.h"

namespace rangesim::python {

namespace {

using systemc::AddressSearchKernel;
using systemc::AddressSearchPins;
using systemc::CentreProcessorKernel;
using systemc::CentreProcessorPins;
using systemc::MultisamplingSequencerKernel;
using systemc::MultisamplingSequencerPins;

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
      "One row's centre processor: accumulates left + right of every streamed sampling; "
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
      "The readout sequencer of one frame access: reset, N samplings (latch, search, address "
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

}  // namespace

void ls_conventional_bind_kernels(py::module_& k) {
  bind_centre_processor(k);
  bind_sequencer(k);
}

std::vector<KernelBlock> ls_conventional_kernel_blocks() {
  return {
      {"multisampling_sequencer", "readout sequencer of a frame access (MultisamplingSequencer)", &make_sequencer},
      {"address_search", "row address search with bit-serial addresses (AddressSearch)", &make_address_search},
      {"centre_processor", "row centre processor (CentreProcessor)", &make_centre_processor},
  };
}

}  // namespace rangesim::python
