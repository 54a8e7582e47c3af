// A scene run's VCD and its GTKWave save file: see waveform.h.
#include "systemc/common/waveform.h"

#include <filesystem>
#include <fstream>

namespace rangesim::systemc {
namespace {

namespace fs = std::filesystem;

// GTKWave trace flags (its save-file format): right-justified binary, hexadecimal or decimal
// values, a translate-filtered one, and the blank lines that open and close a group.
constexpr unsigned kRjustify = 0x20, kHex = 0x2, kDec = 0x4, kBin = 0x8, kFileFilter = 0x2000, kBlank = 0x200,
                   kGroupBegin = 0x800000, kGroupEnd = 0x1000000;

}  // namespace

Waveform::Waveform(const std::string& vcd_base, bool save_file) : base_(vcd_base), save_file_(save_file) {
  if (base_.empty()) return;
  const fs::path folder = fs::path(base_).parent_path();
  if (!folder.empty()) fs::create_directories(folder);
  tf_ = sc_core::sc_create_vcd_trace_file(base_.c_str());
  // The kernel's own resolution: every time the kernel can reach is representable.
  const double res = sc_core::sc_get_time_resolution().to_seconds();
  // SystemC reports the unit as an info message: nothing a reader needs.
  const sc_core::sc_actions info = sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  tf_->set_time_unit(1, res < 1e-14 ? sc_core::SC_FS : res < 1e-11 ? sc_core::SC_PS : sc_core::SC_NS);
  sc_core::sc_report_handler::set_actions(sc_core::SC_INFO, info);
}

Waveform::~Waveform() { close(); }

void Waveform::close() {
  if (!tf_) return;
  sc_core::sc_close_vcd_trace_file(tf_);
  tf_ = nullptr;
  if (save_file_) write_save_file();
}

void Waveform::write_save_file() const {
  const std::string stem = fs::path(base_).filename().string();
  std::ofstream g(base_ + ".gtkw");
  g << "[*] GTKWave save file of a rangesim simulate trace (systemc/common/waveform.h)\n";
  g << "[dumpfile] \"" << stem << ".vcd\"\n";
  g << "[timestart] 0\n";
  std::string group;
  for (const Signal& s : signals_) {
    if (s.scope != group) {
      if (!group.empty()) g << "@" << std::hex << (kGroupEnd | kBlank) << std::dec << "\n-" << group << "\n";
      group = s.scope;
      g << "@" << std::hex << (kGroupBegin | kBlank) << std::dec << "\n-" << group << "\n";
    }
    std::string ref = "SystemC." + s.scope + "." + s.name;
    if (s.width > 1) ref += "[" + std::to_string(s.width - 1) + ":0]";
    unsigned flags = kRjustify | (s.width == 1 ? kBin : s.names.empty() ? kHex : kDec);
    if (!s.names.empty()) {
      const std::string filter = stem + "." + s.scope + "." + s.name + ".txt";
      std::ofstream f(fs::path(base_).parent_path() / filter);
      for (const auto& [value, name] : s.names) f << value << " " << name << "\n";
      g << "^1 " << filter << "\n";
      flags |= kFileFilter;
    }
    g << "@" << std::hex << flags << std::dec << "\n" << ref << "\n";
  }
  if (!group.empty()) g << "@" << std::hex << (kGroupEnd | kBlank) << std::dec << "\n-" << group << "\n";
}

}  // namespace rangesim::systemc
