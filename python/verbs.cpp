// presets(), load(), table() and the Sensor's show() and frame_rate(): the data the command
// prints with --json, from the same functions (app/command_data.h).
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "app/cli_common.h"
#include "app/command_data.h"
#include "core/preset.h"
#include "python/bindings.h"

namespace rangesim::python {

namespace {

// One `set` entry as the command line's --set KEY=VALUE text: the same parser and checks then
// apply, so a value is accepted or refused with the command line's message.
std::string assignment(const py::handle& key, const py::handle& value) {
  if (!py::isinstance<py::str>(key))
    bad_argument("set", fmt::format("set: keys must be strings such as \"timing.clock_Hz\", got {}",
                                    py::str(py::repr(key)).cast<std::string>()));
  const std::string k = key.cast<std::string>();
  static py::object* numbers = new py::object(py::module_::import("numbers"));  // kept for the process
  std::string text;
  if (py::isinstance<py::bool_>(value))  // before int: bool is an int in Python
    text = value.cast<bool>() ? "true" : "false";
  else if (py::isinstance<py::str>(value))
    text = value.cast<std::string>();
  else if (py::isinstance(value, numbers->attr("Integral")))  // int, numpy.int64, ...
    text = py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
  else if (py::isinstance(value, numbers->attr("Real")))  // float, numpy.float32, ...
    text = py::repr(py::float_(py::reinterpret_borrow<py::object>(value)))
               .cast<std::string>();  // the shortest text that reads back exactly
  else
    bad_argument(k, fmt::format("set: {} = {}: allowed a number, a bool or a string", k,
                                py::str(py::repr(value)).cast<std::string>()));
  return k + "=" + text;
}

// `set` as --set assignments, in order: a mapping {key: value} or "KEY=VALUE" strings.
std::vector<std::string> assignments(const py::object& set) {
  std::vector<std::string> out;
  if (set.is_none()) return out;
  if (py::isinstance<py::dict>(set)) {
    for (const auto& [k, v] : set.cast<py::dict>()) out.push_back(assignment(k, v));
    return out;
  }
  if (!py::isinstance<py::str>(set) && py::isinstance<py::iterable>(set)) {
    for (const auto& item : set) {
      if (!py::isinstance<py::str>(item))
        bad_argument("set", "set: allowed a dict {key: value} or a list of \"KEY=VALUE\" strings");
      out.push_back(item.cast<std::string>());
    }
    return out;
  }
  bad_argument("set", "set: allowed a dict {key: value} or a list of \"KEY=VALUE\" strings");
}

Sensor load(const py::object& preset, const py::object& set) {
  const std::string id_or_path = py::str(preset).cast<std::string>();  // str or os.PathLike
  const std::vector<std::string> settings = assignments(set);
  Sensor s{load_preset(id_or_path)};
  apply_settings(s.params, settings);
  return s;
}

}  // namespace

void bind_verbs(py::module_& m, SensorClass& sensor) {
  m.def(
      "presets", [] { return to_python(app::list_json()); },
      "Every registered sensor: id, title, thesis_ref, golden_modelled, timing_modelled and its preset file "
      "(`rangesim list --json`).");
  m.def("load", &load, py::arg("preset"), py::arg("set") = py::none(),
        "A preset id or a path to a preset file (with `base = ...` inheritance), then `set` applied in order "
        "like --set KEY=VALUE: a dict {key: value} or a list of \"KEY=VALUE\" strings. Raises rangesim.Error "
        "with the command line's message.");
  m.def(
      "table",
      [] {
        const nlohmann::json j = without_gil([](Interruption&) { return app::table_json(&check_interrupt_progress); });
        return to_python(j);
      },
      "Thesis Table 5.1 beside each preset's default evaluation, and the published figures "
      "(`rangesim table --json`). Takes several seconds; Ctrl-C stops it.");

  sensor.def_property_readonly(
      "id", [](const Sensor& s) { return s.params.sensor_id(); }, "The sensor's preset id, e.g. \"tof-spad\".");
  sensor.def_property_readonly(
      "preset", [](const Sensor& s) { return s.params.origin(); }, "The preset file it was loaded from.");
  sensor.def("__repr__", [](const Sensor& s) {
    return fmt::format("rangesim.Sensor('{}', preset='{}')", s.params.sensor_id(), s.params.origin());
  });
  sensor.def(
      "show", [](const Sensor& s) { return to_python(app::show_json(s.params)); },
      "Resolved parameters with unit, source, file, meaning and allowed range (`rangesim show --json`).");
  sensor.def(
      "frame_rate",
      [](const Sensor& s, std::optional<int> samplings) {
        ParamSet params = s.params;
        app::require_modelled(params, "frame-rate");
        if (samplings) app::apply_frame_rate_samplings(params, *samplings);
        return to_python(app::frame_rate_json(params));
      },
      py::arg("samplings") = py::none(),
      "Frame timing from the clock schedule, by phase, and the rates (`rangesim frame-rate --json`).");
}

}  // namespace rangesim::python
