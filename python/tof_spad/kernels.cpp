// rangesim.kernels for tof-spad: TdcGroup, the TDC shared by one group of columns, hit by hit
// (systemc/tof_spad/tdc_kernel.h), sized and timed by a preset as the sensor kernel sizes it.
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "core/tof_spad/config.h"
#include "python/kernel_blocks.h"
#include "systemc/tof_spad/sensor_kernel.h"
#include "systemc/tof_spad/tdc_kernel.h"

namespace rangesim::python {

namespace {

namespace sp = systemc::spad;

// One row integration of one group's TDC. The sensor kernel (one group wide) supplies the bins,
// dead times and laser cycles exactly as TofSpadKernel::simulate_group builds its TDC.
class TdcGroup {
 public:
  explicit TdcGroup(const TofSpadConfig& cfg)
      : sensor_(cfg, 1, cfg.tdc.columns_per_tdc, sp::TofSpadKernelOptions{}), tdc_(make()) {}

  sp::TdcHit hit(int who, long long cycle, int bin) {
    if (finished_) bad_argument("hit", "hit: finish() ended this integration; allowed after reset()");
    check("who", who, columns() - 1);
    check("cycle", cycle, sensor_.laser_cycles() - 1);
    check("bin", bin, sensor_.phase_bins() - 1);
    return tdc_.hit(who, cycle, bin);
  }
  void lose() { tdc_.lose(); }
  py::object finish() {
    if (finished_) bad_argument("finish", "finish: called already for this integration; allowed after reset()");
    finished_ = true;
    const sp::GroupHistogram g = tdc_.finish();
    py::array_t<long long> events({g.events.size(), static_cast<std::size_t>(codes())});
    auto e = events.mutable_unchecked<2>();
    for (std::size_t c = 0; c < g.events.size(); ++c)
      for (std::size_t k = 0; k < g.events[c].size(); ++k) e(c, k) = g.events[c][k];
    py::array_t<long long> armed(static_cast<py::ssize_t>(g.armed.size()));
    auto a = armed.mutable_unchecked<1>();
    for (std::size_t k = 0; k < g.armed.size(); ++k) a(static_cast<py::ssize_t>(k)) = g.armed[k];
    return make_result(py::dict(py::arg("events") = events, py::arg("armed") = armed, py::arg("starts") = g.starts,
                                py::arg("overflows") = g.overflows, py::arg("lost_busy") = g.lost_busy));
  }
  void reset() { tdc_ = make(), finished_ = false; }

  const sp::TofSpadKernel& sensor() const { return sensor_; }
  int columns() const { return sensor_.config().tdc.columns_per_tdc; }
  int codes() const { return sensor_.codes(); }
  long long armed_from() const { return tdc_.armed_from(); }

 private:
  sp::TdcGroupKernel make() const {
    return sp::TdcGroupKernel(sensor_.phase_bins(), sensor_.codes(), sensor_.block_event_bins(),
                              sensor_.block_overflow_bins(), sensor_.laser_cycles(), columns());
  }
  static void check(const char* key, long long v, long long hi) {
    if (v < 0 || v > hi) bad_argument(key, fmt::format("{} = {}: allowed 0 .. {}", key, v, hi));
  }

  sp::TofSpadKernel sensor_;  // bins, dead times, laser cycles (one group wide)
  sp::TdcGroupKernel tdc_;    // the TDC of the current integration
  bool finished_ = false;     // finish() called: the next integration needs reset()
};

const char* kind_name(sp::TdcHit::Kind k) {
  switch (k) {
    case sp::TdcHit::Kind::Lost: return "lost";
    case sp::TdcHit::Kind::Event: return "event";
    case sp::TdcHit::Kind::Overflow: return "overflow";
  }
  return "?";
}

py::object make_tdc_group(const ParamSet& p) { return py::cast(TdcGroup(tof_spad_from_params(p))); }

}  // namespace

std::vector<KernelBlock> tof_spad_kernel_blocks() {
  return {{"tdc", "TDC shared by a group of columns, hit by hit (TdcGroup)", &make_tdc_group}};
}

void tof_spad_bind_kernels(py::module_& k) {
  py::class_<sp::TdcHit>(k, "TdcHit", "What the TDC made of one hit: its transaction.")
      .def_property_readonly("kind", [](const sp::TdcHit& h) { return kind_name(h.kind); })
      .def_readonly("abs_bin", &sp::TdcHit::abs_bin)
      .def_readonly("code", &sp::TdcHit::code)
      .def("__repr__", [](const sp::TdcHit& h) {
        return fmt::format("TdcHit(kind='{}', abs_bin={}, code={})", kind_name(h.kind), h.abs_bin, h.code);
      });
  py::class_<TdcGroup>(
      k, "TdcGroup",
      "The TDC shared by one group of columns over one row integration: hits in time order "
      "(after first-hit arbitration) become events, overflows or losses (dead time, stop until the "
      "next START); finish() gives the histograms and the armed counts (systemc/tof_spad/tdc_kernel.h).")
      .def("hit", &TdcGroup::hit, py::arg("who"), py::arg("cycle"), py::arg("bin"),
           "Hit of column `who` of the group in laser cycle `cycle` falling in phase bin `bin`.")
      .def("lose", &TdcGroup::lose, "An avalanche before the first START: counted as lost.")
      .def("finish", &TdcGroup::finish,
           "Ends the integration: events [column][code], armed [code], starts, overflows, lost_busy.")
      .def("reset", &TdcGroup::reset, "A new row integration.")
      .def_property_readonly("armed_from", &TdcGroup::armed_from, "Absolute bin from which the TDC is armed.")
      .def(
          "phase_bin", [](const TdcGroup& t, double phase_s) { return t.sensor().phase_bin(phase_s); },
          py::arg("phase_s"), "TDC code of a time in the laser period (coarse count + interpolation on the edges).")
      .def_property_readonly("columns", &TdcGroup::columns)
      .def_property_readonly("codes", &TdcGroup::codes)
      .def_property_readonly("phase_bins", [](const TdcGroup& t) { return t.sensor().phase_bins(); })
      .def_property_readonly("laser_cycles", [](const TdcGroup& t) { return t.sensor().laser_cycles(); })
      .def_property_readonly("block_event_bins", [](const TdcGroup& t) { return t.sensor().block_event_bins(); })
      .def_property_readonly("block_overflow_bins", [](const TdcGroup& t) { return t.sensor().block_overflow_bins(); })
      .def_property_readonly("lsb_s", [](const TdcGroup& t) { return t.sensor().bins().lsb_s; })
      .def_property_readonly("clock_Hz", [](const TdcGroup& t) { return t.sensor().clock_Hz(); });
}

}  // namespace rangesim::python
