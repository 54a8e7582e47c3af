#pragma once
// The VCD of a scene run (`rangesim simulate --trace`), arranged for a person reading it:
//  - signals sit in scopes that follow the block tree ("tof_lockin.gates.tx1": SystemC's VCD writer
//    turns each '.' into a $scope level under its top scope "SystemC");
//  - the time unit is the kernel's time resolution (1 ps by default), so the edges of every clock
//    (10 ns gates, 27.8 ns readout, ...) are representable and SystemC prints no W713 per edge;
//  - beside <base>.vcd goes <base>.gtkw, a GTKWave save file that opens the trace with the signals
//    grouped by block in the order they were added, and for each signal with named values (a
//    phase) a translate filter <base>.<signal>.txt, so GTKWave shows "latch" instead of 1.
// Open it from the trace's folder: `gtkwave <base>.gtkw`.
#include <sys/types.h>

#include <cstdint>
#include <string>
#include <systemc>
#include <type_traits>
#include <utility>
#include <vector>

namespace rangesim::systemc {

class Waveform {
 public:
  // Names of a signal's values, for the translate filter (value, name).
  using ValueNames = std::vector<std::pair<long long, std::string>>;

  // Opens <vcd_base>.vcd (creating its folder); "" = off (every call below is a no-op).
  // `save_file` false: the VCD only (a part merged into another trace).
  explicit Waveform(const std::string& vcd_base, bool save_file = true);
  ~Waveform();  // close()
  Waveform(const Waveform&) = delete;
  Waveform& operator=(const Waveform&) = delete;

  bool enabled() const { return tf_ != nullptr; }

  // Traces `object` (a signal, port or value SystemC can trace) as scope.name, where scope is a
  // dotted block path; `names` gives its values names (phases). Call after elaboration.
  template <class T>
  void add(const T& object, const std::string& scope, const std::string& name, ValueNames names = {}) {
    if (!tf_) return;
    sc_core::sc_trace(tf_, object, scope + "." + name);
    signals_.push_back({scope, name, width_of(object), std::move(names)});
  }

  // Closes the VCD and writes the save file and filters. Idempotent.
  void close();

  struct Signal {
    std::string scope, name;
    int width;  // bits (1: a wire)
    ValueNames names;
  };
  // What was traced, in the order added (a co-simulation's save file pairs them with the RTL's).
  const std::vector<Signal>& signals() const { return signals_; }

 private:
  template <class T>
  static int width_of(const T&) {
    using V = std::decay_t<decltype(std::declval<const T&>().read())>;
    return value_width<V>();
  }
  template <class V>
  static int value_width() {
    if constexpr (std::is_same_v<V, bool>)
      return 1;
    else if constexpr (std::is_integral_v<V>)
      return static_cast<int>(8 * sizeof(V));
    else
      return 0;  // a real or a user type: no bit range in the name
  }
  void write_save_file() const;

  std::string base_;
  bool save_file_ = true;
  sc_core::sc_trace_file* tf_ = nullptr;
  std::vector<Signal> signals_;
};

// Plain values traced by reference (kernel pins) have no read(): their width from the type.
template <>
inline int Waveform::width_of<bool>(const bool&) {
  return 1;
}
template <>
inline int Waveform::width_of<int>(const int&) {
  return 32;
}
template <>
inline int Waveform::width_of<long long>(const long long&) {
  return 64;
}
template <>
inline int Waveform::width_of<double>(const double&) {
  return 0;
}
template <>
inline int Waveform::width_of<std::uint32_t>(const std::uint32_t&) {
  return 32;
}

}  // namespace rangesim::systemc
