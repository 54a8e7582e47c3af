// Merging two VCD files: see vcd_merge.h.
#include "tb/common/vcd_merge.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rangesim::tb {
namespace {

struct Vcd {
  std::string timescale;                                      // without spaces, e.g. "1ps"
  std::vector<std::string> declarations;                      // $scope/$var/$upscope lines
  std::set<std::string> ids;                                  // of the $var lines
  std::map<std::uint64_t, std::vector<std::string>> changes;  // time -> value changes
};

Vcd read_vcd(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the waveform " + path);
  Vcd v;
  std::string line;
  bool header = true, in_timescale = false, in_comment = false;
  std::uint64_t now = 0;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    if (header) {
      if (in_timescale || first == "$timescale") {
        for (std::string w = first; !w.empty(); w.clear(), words >> w) {
          if (w == "$end")
            in_timescale = false;
          else if (w != "$timescale")
            v.timescale += w;
        }
        if (first == "$timescale" && line.find("$end") == std::string::npos) in_timescale = true;
      } else if (first == "$scope" || first == "$upscope") {
        v.declarations.push_back(line);
      } else if (first == "$var") {
        std::string type, width, id;
        words >> type >> width >> id;
        v.ids.insert(id);
        v.declarations.push_back(line);
      } else if (first == "$enddefinitions") {
        header = false;
      }
      continue;
    }
    if (in_comment || first == "$comment") {  // free text up to $end (SystemC writes some)
      in_comment = line.find("$end") == std::string::npos;
      continue;
    }
    if (first[0] == '#') {
      now = std::stoull(first.substr(1));
    } else if (first[0] != '$') {
      v.changes[now].push_back(line);
    }
  }
  return v;
}

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

}  // namespace

void merge_vcd(const std::string& vcd, const std::string& extra, const std::string& scope) {
  const Vcd a = read_vcd(vcd), b = read_vcd(extra);
  // b's times in a's unit: both are powers of ten, so the ratio is a whole multiple or divisor.
  const double ta = timescale_seconds(a.timescale), tb = timescale_seconds(b.timescale);
  if (ta <= 0 || tb <= 0)
    throw std::runtime_error("cannot merge " + extra + " into " + vcd + ": time units " + b.timescale + " and " +
                             a.timescale);
  const double ratio = tb / ta;
  const auto in_a = [&](std::uint64_t t) {
    return ratio >= 1 ? t * static_cast<std::uint64_t>(ratio + 0.5)
                      : t / static_cast<std::uint64_t>(1 / ratio + 0.5);  // finer: rounded down to a's grid
  };
  // New names for b's identifiers: '~' in front until none collides with a's.
  std::map<std::string, std::string> rename;
  for (const auto& id : b.ids) {
    std::string n = "~" + id;
    while (a.ids.count(n)) n = "~" + n;
    rename[id] = n;
  }
  std::ostringstream out;
  out << "$version rangesim co-simulation: the RTL (Verilator) and, under " << scope
      << ", the model's expected values $end\n";
  out << "$timescale " << a.timescale << " $end\n";
  for (const auto& d : a.declarations) out << d << "\n";
  // b's top scope (SystemC's) becomes `scope`; its $var lines get the new identifiers.
  bool top = true;
  for (const auto& d : b.declarations) {
    std::istringstream w(d);
    std::string first, kind, name;
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
  std::map<std::uint64_t, std::vector<std::string>> b_changes;
  for (const auto& [t, c] : b.changes) {
    auto& at = b_changes[in_a(t)];
    at.insert(at.end(), c.begin(), c.end());
  }
  std::set<std::uint64_t> times;
  for (const auto& [t, c] : a.changes) times.insert(t);
  for (const auto& [t, c] : b_changes) times.insert(t);
  for (const std::uint64_t t : times) {
    out << "#" << t << "\n";
    if (const auto it = a.changes.find(t); it != a.changes.end())
      for (const auto& c : it->second) out << c << "\n";
    if (const auto it = b_changes.find(t); it != b_changes.end())
      for (const auto& c : it->second) {
        std::string value;
        const std::string id = change_id(c, &value);
        const auto r = rename.find(id);
        out << value << (r == rename.end() ? id : r->second) << "\n";
      }
  }
  const std::string tmp = vcd + ".merging";
  std::ofstream(tmp) << out.str();
  if (std::rename(tmp.c_str(), vcd.c_str()) != 0) throw std::runtime_error("cannot write the waveform " + vcd);
}

}  // namespace rangesim::tb
