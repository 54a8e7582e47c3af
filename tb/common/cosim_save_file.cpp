// The GTKWave save file of a co-simulation trace: see cosim_save_file.h.
#include "tb/common/cosim_save_file.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <stdexcept>

#include "tb/common/vcd_merge.h"

namespace rangesim::tb {
namespace {

namespace fs = std::filesystem;

// GTKWave trace flags (its save-file format, as systemc/common/waveform.cpp writes them).
constexpr unsigned kRjustify = 0x20, kHex = 0x2, kDec = 0x4, kBin = 0x8, kFileFilter = 0x2000, kBlank = 0x200,
                   kClosed = 0x400000, kGroupBegin = 0x800000, kGroupEnd = 0x1000000;

bool is_parameter(const VcdVariable& v) {
  return !v.name.empty() && std::isupper(static_cast<unsigned char>(v.name[0]));
}

// Order inside a module's group: clock and reset, inputs, outputs, the rest.
int rank(const std::string& n) {
  const auto ends = [&](const char* s) {
    const std::string e(s);
    return n.size() >= e.size() && n.compare(n.size() - e.size(), e.size(), e) == 0;
  };
  if (n == "clk" || n == "clk_i") return 0;
  if (n == "rst" || n == "rst_i" || n == "rst_n" || n == "rst_ni") return 1;
  return ends("_i") ? 2 : ends("_o") ? 3 : 4;
}

// "row12" -> ("row", 12); no trailing digits -> (scope, nullopt).
std::pair<std::string, std::optional<int>> split_index(const std::string& scope) {
  std::size_t i = scope.size();
  while (i > 0 && std::isdigit(static_cast<unsigned char>(scope[i - 1]))) --i;
  if (i == scope.size() || i == 0) return {scope, std::nullopt};
  return {scope.substr(0, i), std::stoi(scope.substr(i))};
}

class SaveFile {
 public:
  explicit SaveFile(std::ofstream& out) : out_(out) {}
  void begin(const std::string& name, bool closed) {
    flag(kGroupBegin | kBlank | (closed ? kClosed : 0)) << "-" << name << "\n";
  }
  void end(const std::string& name) { flag(kGroupEnd | kBlank) << "-" << name << "\n"; }
  void signal(const std::string& ref, int width, const std::string& filter) {
    unsigned f = kRjustify | (width <= 1 ? kBin : filter.empty() ? kHex : kDec);
    if (!filter.empty()) {
      out_ << "^1 " << filter << "\n";
      f |= kFileFilter;
    }
    flag(f) << ref << "\n";
  }

 private:
  std::ostream& flag(unsigned f) { return out_ << "@" << std::hex << f << std::dec << "\n"; }
  std::ofstream& out_;
};

class Pairing {
 public:
  explicit Pairing(const std::vector<VcdVariable>& rtl) : rtl_(rtl) {
    for (const auto& v : rtl_) top_depth_ = std::min(top_depth_, v.scopes.size());
  }
  // The RTL variable that shows what expected signal scope.name checks, if the naming finds one.
  const VcdVariable* counterpart(const std::string& scope, const std::string& name) const {
    const auto [stem, index] = split_index(scope);
    std::vector<std::string> names{name + "_o", stem + "_" + name + "_o", name, name + "_q"};
    if (const auto u = name.find('_'); u != std::string::npos) names.push_back(name.substr(u + 1) + "_o");
    const std::string tag = index ? "[" + std::to_string(*index) + "]" : "";
    for (int pass = 0; pass < 2; ++pass)  // the top first (what the scoreboard compares), then any depth
      for (const auto& n : names)
        for (const auto& v : rtl_) {
          if (v.name != n || (pass == 0 && v.scopes.size() != top_depth_)) continue;
          if (!tag.empty() && !in_instance(v, tag)) continue;
          return &v;
        }
    return nullptr;
  }

 private:
  static bool in_instance(const VcdVariable& v, const std::string& tag) {
    for (const auto& s : v.scopes)
      if (s.size() >= tag.size() && s.compare(s.size() - tag.size(), tag.size(), tag) == 0) return true;
    return false;
  }
  const std::vector<VcdVariable>& rtl_;
  std::size_t top_depth_ = static_cast<std::size_t>(-1);
};

std::string scope_name(const VcdVariable& v) {
  std::string s;
  for (const auto& p : v.scopes) s += (s.empty() ? "" : ".") + p;
  return s;
}

}  // namespace

std::vector<std::string> write_cosim_save_file(const std::string& vcd,
                                               const std::vector<systemc::Waveform::Signal>& expected) {
  std::vector<VcdVariable> rtl;
  std::map<std::string, VcdVariable> model;  // expected.<scope>.<name> -> its variable
  for (auto& v : vcd_variables(vcd)) {
    if (!v.scopes.empty() && v.scopes.front() == "expected") {
      std::string key;
      for (std::size_t i = 1; i < v.scopes.size(); ++i) key += v.scopes[i] + ".";
      model.emplace(key + v.name, std::move(v));
    } else if (!is_parameter(v)) {
      rtl.push_back(std::move(v));
    }
  }
  const fs::path path(vcd);
  const std::string stem = path.stem().string();
  const fs::path folder = path.parent_path();
  std::vector<std::string> written{stem + ".gtkw"};
  std::ofstream out(folder / written.front());
  out << "[*] GTKWave save file of a rangesim cosim trace (tb/common/cosim_save_file.h)\n";
  out << "[dumpfile] \"" << path.filename().string() << "\"\n[timestart] 0\n";
  SaveFile g(out);
  const Pairing pairing(rtl);

  std::size_t top = static_cast<std::size_t>(-1);
  for (const auto& v : rtl) top = std::min(top, v.scopes.size());
  g.begin("clock and reset", false);
  for (const auto& v : rtl)
    if (v.scopes.size() == top && rank(v.name) < 2) g.signal(v.full_name(), v.width, "");
  g.end("clock and reset");

  if (!expected.empty()) {
    const std::string group = "checked (RTL, then the model's expected value)";
    g.begin(group, false);
    for (const auto& e : expected) {
      const auto m = model.find(e.scope + "." + e.name);
      if (m == model.end()) continue;  // not in this trace (a traced-but-empty scope)
      std::string filter;
      if (!e.names.empty()) {
        filter = stem + "." + e.scope + "." + e.name + ".txt";
        std::ofstream f(folder / filter);
        for (const auto& [value, name] : e.names) f << value << " " << name << "\n";
        if (!f) throw std::runtime_error("cannot write " + (folder / filter).string());
        written.push_back(filter);
      }
      if (const VcdVariable* r = pairing.counterpart(e.scope, e.name)) g.signal(r->full_name(), r->width, filter);
      g.signal(m->second.full_name(), m->second.width, filter);
    }
    g.end(group);
  }

  // One closed group per module instance, in the order the tree declares them.
  std::vector<std::string> order;
  std::map<std::string, std::vector<const VcdVariable*>> by_scope;
  for (const auto& v : rtl) {
    const std::string s = scope_name(v);
    if (!by_scope.count(s)) order.push_back(s);
    by_scope[s].push_back(&v);
  }
  for (const auto& s : order) {
    auto& vars = by_scope[s];
    std::stable_sort(vars.begin(), vars.end(),
                     [](const VcdVariable* a, const VcdVariable* b) { return rank(a->name) < rank(b->name); });
    g.begin(s, true);
    for (const VcdVariable* v : vars) g.signal(v->full_name(), v->width, "");
    g.end(s);
  }
  out.close();
  if (!out) throw std::runtime_error("cannot write " + (folder / written.front()).string());
  return written;
}

}  // namespace rangesim::tb
