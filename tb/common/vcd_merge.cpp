// Merging two VCD files: see vcd_merge.h. Both files are streamed (headers read whole, value
// changes one time step at a time), so a trace of several GB merges in constant memory.
#include "tb/common/vcd_merge.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rangesim::tb {
namespace {

// One VCD read front to back: the header at construction, then its time steps in order.
class VcdReader {
 public:
  explicit VcdReader(const std::string& path) : in_(path) {
    if (!in_) throw std::runtime_error("cannot read the waveform " + path);
    read_header();
  }
  const std::string& timescale() const { return timescale_; }                     // without spaces, e.g. "1ps"
  const std::vector<std::string>& declarations() const { return declarations_; }  // $scope/$var/$upscope
  const std::set<std::string>& ids() const { return ids_; }                       // of the $var lines

  // The next time step: its time and value changes; false at the end of the file. Changes before
  // the first #time belong to time 0.
  bool next(std::uint64_t& time, std::vector<std::string>& changes) {
    changes.clear();
    std::string line, first;
    while (std::getline(in_, line)) {
      std::istringstream words(line);
      if (!(words >> first)) continue;
      if (in_comment_ || first == "$comment") {  // free text up to $end (SystemC writes some)
        in_comment_ = line.find("$end") == std::string::npos;
        continue;
      }
      if (first[0] == '#') {
        const std::uint64_t t = std::stoull(first.substr(1));
        if (!changes.empty() && t != current_) {  // the step read so far is complete
          time = current_;
          current_ = t;
          return true;
        }
        current_ = t;  // a step without changes is skipped
      } else if (first[0] != '$') {
        changes.push_back(line);
      }
    }
    time = current_;
    return !changes.empty();
  }

 private:
  void read_header() {
    std::string line, first;
    bool in_timescale = false;
    while (std::getline(in_, line)) {
      std::istringstream words(line);
      if (!(words >> first)) continue;
      if (in_timescale || first == "$timescale") {
        for (std::string w = first; !w.empty(); w.clear(), words >> w) {
          if (w == "$end")
            in_timescale = false;
          else if (w != "$timescale")
            timescale_ += w;
        }
        if (first == "$timescale" && line.find("$end") == std::string::npos) in_timescale = true;
      } else if (first == "$scope" || first == "$upscope") {
        declarations_.push_back(line);
      } else if (first == "$var") {
        std::string type, width, id;
        words >> type >> width >> id;
        ids_.insert(id);
        declarations_.push_back(line);
      } else if (first == "$enddefinitions") {
        return;
      }
    }
  }

  std::ifstream in_;
  std::string timescale_;
  std::vector<std::string> declarations_;
  std::set<std::string> ids_;
  std::uint64_t current_ = 0;  // the #time read last: the step being read
  bool in_comment_ = false;
};

// "1ps" -> 1e-12 s (0 when unreadable).
double timescale_seconds(const std::string& t) {
  std::size_t digits = 0;
  while (digits < t.size() && std::isdigit(static_cast<unsigned char>(t[digits]))) ++digits;
  if (digits == 0) return 0;
  const double n = std::stod(t.substr(0, digits));
  const std::string unit = t.substr(digits);
  const std::map<std::string, double> units{{"s", 1},     {"ms", 1e-3},  {"us", 1e-6},
                                            {"ns", 1e-9}, {"ps", 1e-12}, {"fs", 1e-15}};
  const auto u = units.find(unit);
  return u == units.end() ? 0 : n * u->second;
}

// The identifier a value change refers to: "1!" -> "!", "b0101 #" -> "#".
std::string change_id(const std::string& c, std::string* value) {
  if (c[0] == 'b' || c[0] == 'B' || c[0] == 'r' || c[0] == 'R') {
    const std::size_t sp = c.find(' ');
    *value = c.substr(0, sp + 1);
    return c.substr(sp + 1);
  }
  *value = c.substr(0, 1);
  return c.substr(1);
}

// The header of the merged file: a's declarations, then b's under `scope` with renamed ids.
void write_header(std::ostream& out, const VcdReader& a, const VcdReader& b, const std::string& scope,
                  const std::map<std::string, std::string>& rename) {
  out << "$version rangesim co-simulation: the RTL (Verilator) and, under " << scope
      << ", the model's expected values $end\n";
  out << "$timescale " << a.timescale() << " $end\n";
  for (const auto& d : a.declarations()) out << d << "\n";
  bool top = true;  // b's top scope (SystemC's) becomes `scope`
  for (const auto& d : b.declarations()) {
    std::istringstream w(d);
    std::string first;
    w >> first;
    if (first == "$scope" && top) {
      out << "$scope module " << scope << " $end\n";
      top = false;
    } else if (first == "$var") {
      std::string type, width, id, rest;
      w >> type >> width >> id;
      std::getline(w, rest);
      out << "$var " << type << " " << width << " " << rename.at(id) << rest << "\n";
    } else {
      out << d << "\n";
    }
  }
  out << "$enddefinitions $end\n";
}

}  // namespace

std::string VcdVariable::full_name() const {
  std::string n;
  for (const auto& s : scopes) n += s + ".";
  return n + name + range;
}

std::vector<VcdVariable> vcd_variables(const std::string& vcd) {
  const VcdReader r(vcd);
  std::vector<VcdVariable> vars;
  std::vector<std::string> scopes;
  for (const auto& d : r.declarations()) {
    std::istringstream w(d);
    std::string first, kind, name;
    w >> first;
    if (first == "$scope") {
      w >> kind >> name;
      scopes.push_back(name);
    } else if (first == "$upscope") {
      if (!scopes.empty()) scopes.pop_back();
    } else if (first == "$var") {
      VcdVariable v;
      std::string type, width, id, word;
      w >> type >> width >> id >> v.name;
      v.width = std::atoi(width.c_str());
      while (w >> word && word != "$end") v.range += word;  // "[10:0]", possibly split by spaces
      v.scopes = scopes;
      vars.push_back(std::move(v));
    }
  }
  return vars;
}

void merge_vcd(const std::string& vcd, const std::string& extra, const std::string& scope) {
  VcdReader a(vcd), b(extra);
  // b's times in a's unit: both are powers of ten, so the ratio is a whole multiple or divisor.
  const double ta = timescale_seconds(a.timescale()), tb = timescale_seconds(b.timescale());
  if (ta <= 0 || tb <= 0)
    throw std::runtime_error("cannot merge " + extra + " into " + vcd + ": time units " + b.timescale() + " and " +
                             a.timescale());
  const double ratio = tb / ta;
  const auto in_a = [&](std::uint64_t t) {
    return ratio >= 1 ? t * static_cast<std::uint64_t>(ratio + 0.5)
                      : t / static_cast<std::uint64_t>(1 / ratio + 0.5);  // finer: rounded down to a's grid
  };
  // New names for b's identifiers: '~' in front until none collides with a's.
  std::map<std::string, std::string> rename;
  for (const auto& id : b.ids()) {
    std::string n = "~" + id;
    while (a.ids().count(n)) n = "~" + n;
    rename[id] = n;
  }
  const std::string tmp = vcd + ".merging";
  std::ofstream out(tmp);
  if (!out) throw std::runtime_error("cannot write the waveform " + vcd);
  write_header(out, a, b, scope, rename);

  // Both streams are in time order: merge them step by step (b's steps that fall on one step of
  // a's coarser grid are written together).
  std::uint64_t t_a = 0, t_b = 0;
  std::vector<std::string> c_a, c_b;
  bool has_a = a.next(t_a, c_a), has_b = b.next(t_b, c_b);
  if (has_b) t_b = in_a(t_b);
  auto write_b = [&](const std::vector<std::string>& changes) {
    for (const auto& c : changes) {
      std::string value;
      const std::string id = change_id(c, &value);
      const auto r = rename.find(id);
      out << value << (r == rename.end() ? id : r->second) << "\n";
    }
  };
  while (has_a || has_b) {
    const std::uint64_t t = !has_b ? t_a : !has_a ? t_b : std::min(t_a, t_b);
    out << "#" << t << "\n";
    if (has_a && t_a == t) {
      for (const auto& c : c_a) out << c << "\n";
      has_a = a.next(t_a, c_a);
    }
    while (has_b && t_b == t) {
      write_b(c_b);
      if ((has_b = b.next(t_b, c_b))) t_b = in_a(t_b);
    }
  }
  out.close();
  if (!out || std::rename(tmp.c_str(), vcd.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot write the waveform " + vcd);
  }
}

}  // namespace rangesim::tb
