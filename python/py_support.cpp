#include "python/py_support.h"

#include "core/user_error.h"

namespace rangesim::python {

py::object to_python(const nlohmann::json& j) {
  using T = nlohmann::json::value_t;
  switch (j.type()) {
    case T::null: return py::none();
    case T::boolean: return py::bool_(j.get<bool>());
    case T::number_integer: return py::int_(j.get<long long>());
    case T::number_unsigned: return py::int_(j.get<unsigned long long>());
    case T::number_float: return py::float_(j.get<double>());
    case T::string: return py::str(j.get<std::string>());
    case T::array: {
      py::list l;
      for (const auto& e : j) l.append(to_python(e));
      return std::move(l);
    }
    case T::object: {
      py::dict d;
      for (const auto& [k, v] : j.items()) d[py::str(k)] = to_python(v);
      return std::move(d);
    }
    case T::binary:
    case T::discarded: break;
  }
  return py::none();
}

py::object make_result(py::dict fields) {
  static py::object* namespace_type =
      new py::object(py::module_::import("types").attr("SimpleNamespace"));  // kept for the process
  return (*namespace_type)(**fields);
}

py::array_t<double> vector_array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  auto m = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < v.size(); ++i) m(static_cast<py::ssize_t>(i)) = v[i];
  return a;
}

void bad_argument(const std::string& key, const std::string& message) { throw UserError(message, key); }

// ---- Ctrl-C ----

namespace {
thread_local Interruption* t_current = nullptr;
}

Interruption::~Interruption() {
  Py_XDECREF(type_);
  Py_XDECREF(value_);
  Py_XDECREF(traceback_);
}

bool Interruption::poll() {
  if (type_) return true;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() == 0) return false;
  PyErr_Fetch(&type_, &value_, &traceback_);
  if (!type_) {  // a handler failed without an exception object: report Ctrl-C all the same
    type_ = PyExc_KeyboardInterrupt;
    Py_INCREF(type_);
  }
  return true;
}

void Interruption::rethrow() {
  if (!type_) {  // not polled: cannot happen through check(), but a stop must still read as Ctrl-C
    type_ = PyExc_KeyboardInterrupt;
    Py_INCREF(type_);
  }
  PyErr_Restore(type_, value_, traceback_);  // hands the references over
  type_ = value_ = traceback_ = nullptr;
  throw py::error_already_set();
}

Interruption* Interruption::current() { return t_current; }

CurrentInterruption::CurrentInterruption(Interruption* in) : previous_(t_current) { t_current = in; }
CurrentInterruption::~CurrentInterruption() { t_current = previous_; }

void check_interrupt_progress(int, int) {
  if (Interruption* in = Interruption::current()) in->check();
}

}  // namespace rangesim::python
