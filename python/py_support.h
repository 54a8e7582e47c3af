#pragma once
// What the bindings of the Python module share: the loaded sensor, JSON to Python, result
// objects, bad-argument errors, and running C++ without the GIL so that Ctrl-C still works.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <atomic>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/params.h"

namespace rangesim::python {

namespace py = pybind11;

// A preset as `rangesim.load` resolved it (inheritance and `set` applied, validated).
struct Sensor {
  ParamSet params;
};

// The JSON the command prints, as the dicts, lists and numbers `json.load` would give.
py::object to_python(const nlohmann::json& j);

// A result with named fields (types.SimpleNamespace: attribute access, readable repr, vars()).
py::object make_result(py::dict fields);

// A 2-D float array of shape (rows, columns) filled by value(row, column).
template <class F>
py::array_t<double> grid_array(std::size_t rows, std::size_t columns, F value) {
  py::array_t<double> a({rows, columns});
  auto m = a.mutable_unchecked<2>();
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < columns; ++c) m(r, c) = value(r, c);
  return a;
}

py::array_t<double> vector_array(const std::vector<double>& v);

// Bad argument of a Python call: rangesim.Error (a ValueError) naming `key`.
[[noreturn]] void bad_argument(const std::string& key, const std::string& message);

// Ctrl-C while C++ runs without the GIL. Python's SIGINT handler only records the signal; the
// C++ code's progress hooks call poll(), which takes the GIL back for a moment and lets Python run
// its handlers. Hooks that may throw call check(); those that must not (the Monte Carlo sweep's,
// whose workers must be joined first) raise stop_flag() instead.
struct Interrupted : std::exception {
  const char* what() const noexcept override { return "interrupted"; }
};

class Interruption {
 public:
  Interruption() = default;
  Interruption(const Interruption&) = delete;
  Interruption& operator=(const Interruption&) = delete;
  ~Interruption();  // with the GIL held

  // From the thread that released the GIL. True once a handler raised (the exception is kept).
  bool poll();
  void check() {
    if (poll()) throw Interrupted();
  }
  const std::atomic<bool>* stop_flag() const { return &stop_; }
  void raise_stop() { stop_ = true; }
  // With the GIL held: makes the kept exception (KeyboardInterrupt) the current Python error.
  [[noreturn]] void rethrow();

  // The interruption of the innermost without_gil() on this thread, for hooks that are plain
  // function pointers (golden::ProgressFn); nullptr outside.
  static Interruption* current();

 private:
  PyObject* type_ = nullptr;  // the exception a signal handler raised (owned references)
  PyObject* value_ = nullptr;
  PyObject* traceback_ = nullptr;
  std::atomic<bool> stop_{false};  // raised for hooks that must not throw
};

// Makes `in` the current interruption of this thread for its lifetime.
class CurrentInterruption {
 public:
  explicit CurrentInterruption(Interruption* in);
  ~CurrentInterruption();

 private:
  Interruption* previous_;
};

// Runs f(interruption) with the GIL released; an Interrupted from its hooks comes out as the
// KeyboardInterrupt Python raised, any other exception as it is (pybind11 translates it).
template <class F>
auto without_gil(F&& f) -> decltype(f(std::declval<Interruption&>())) {
  Interruption in;
  CurrentInterruption current(&in);
  try {
    py::gil_scoped_release release;
    return f(in);
  } catch (const Interrupted&) {
    in.rethrow();  // the GIL is held again: `release` ended before the handler
  }
}

// golden::ProgressFn that checks for Ctrl-C (throws Interrupted).
void check_interrupt_progress(int done, int total);

}  // namespace rangesim::python
