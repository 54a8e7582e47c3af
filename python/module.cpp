// The Python module `rangesim` (docs/python.md): the verbs of the command line returning data,
// and the clock kernels step by step for Python testbenches. Every sensor comes from the
// registries, as on the command line.
#include "python/bindings.h"

#include <regex>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "app/command_data.h"
#include "core/user_error.h"
#include "systemc/common/montecarlo.h"

namespace rangesim::python {

namespace {

// The key of an error raised without one, read from the message's own form: "--frames 0: ..." is
// the argument `frames`, "FILE:12: target.distance_m = ..." the file's key, "'x' is neither a
// preset nor a file" the preset. "" when the message names no one key.
std::string key_from_message(const std::string& m) {
  static const std::regex flag(R"(^--([a-z][a-z-]*)[ :=])");
  static const std::regex file_key(R"(^\S+:\d+: ([A-Za-z_][A-Za-z0-9_]*(\.[A-Za-z0-9_]+)+)\b)");
  std::smatch s;
  if (std::regex_search(m, s, flag)) {
    std::string k = s[1];
    for (char& c : k)
      if (c == '-') c = '_';
    return k;
  }
  if (std::regex_search(m, s, file_key)) return s[1];
  if (m.find("is neither a preset nor a file") != std::string::npos) return "preset";
  return "";
}

}  // namespace

void register_errors(py::module_& m) {
  // Kept for the life of the process: the translator below may run until the interpreter exits.
  static py::object* error = new py::object(py::reinterpret_steal<py::object>(PyErr_NewExceptionWithDoc(
      "rangesim.Error",
      "Bad input: the message the command line prints for it (naming the file or argument, the key and "
      "the allowed range); `key` is the parameter or argument at fault (None when there is no one key).",
      PyExc_ValueError, nullptr)));
  m.attr("Error") = *error;
  py::register_exception_translator([](std::exception_ptr p) {
    if (!p) return;
    try {
      std::rethrow_exception(p);
    } catch (const UserError& e) {
      py::object err = (*error)(py::str(e.what()));
      const std::string key = e.key().empty() ? key_from_message(e.what()) : e.key();
      err.attr("key") = key.empty() ? py::object(py::none()) : py::object(py::str(key));
      PyErr_SetObject(error->ptr(), err.ptr());
    } catch (const app::NotModelled& e) {  // the command's exit code 3: a sensor without the model
      PyErr_SetString(PyExc_NotImplementedError, e.message.c_str());
    }
  });
}

}  // namespace rangesim::python

PYBIND11_MODULE(rangesim, m) {
  namespace rp = rangesim::python;
  m.doc() =
      "rangesim: cycle-accurate simulator of 3-D range-finding image sensors, from Python.\n\n"
      "presets(), load(preset, set={...}) -> Sensor, table(); Sensor.show(), .frame_rate(), .evaluate(),\n"
      ".simulate(), .kernel(block); rangesim.kernels holds the clock kernels. See docs/python.md.";
  m.attr("__version__") = RANGESIM_VERSION;
  rp::register_errors(m);
  rp::SensorClass sensor(m, "Sensor",
                         "A sensor preset as rangesim.load() resolved it: inheritance and `set` applied, "
                         "checked as on the command line.");
  rp::bind_verbs(m, sensor);
  rp::bind_evaluate(sensor);
  rp::bind_simulate(sensor);
  rp::bind_kernels(m, sensor);
  // What presets() reports per sensor: the module runs simulate and the Monte Carlo, not cosim.
  rangesim::app::add_sensor_command({"simulate", &rangesim::app::simulate_runs});
  rangesim::app::add_sensor_command({"evaluate --trials", &rangesim::mc::has_mc_model});
}
