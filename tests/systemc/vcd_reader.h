#pragma once
// A small VCD reader for tests: enough of IEEE 1364 §18 to read what SystemC's VCD writer emits
// ($var wire/reg with identifier codes, scalar and bNNN vector changes, #time stamps). Values
// are kept as change lists; sample() gives a signal's value after all changes at a time.
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace rangesim::systemc::test {

struct VcdFile {
  std::string timescale;                     // e.g. "1 fs"
  std::map<std::string, std::string> id_of;  // signal name -> identifier code
  std::map<std::string, int> width_of;       // signal name -> bits
  std::map<std::string, std::vector<std::pair<std::uint64_t, std::uint64_t>>> changes;  // id -> (time, value)
  std::uint64_t end_time = 0;
  bool ok = false;
  std::string error;

  bool has(const std::string& name) const { return id_of.count(name) > 0; }
  const std::vector<std::pair<std::uint64_t, std::uint64_t>>& of(const std::string& name) const {
    return changes.at(id_of.at(name));
  }
  // Value after all changes at time t (x/z read as 0).
  std::uint64_t sample(const std::string& name, std::uint64_t t) const {
    std::uint64_t v = 0;
    for (const auto& [time, value] : of(name)) {
      if (time > t) break;
      v = value;
    }
    return v;
  }
  // Times of the 0 -> 1 transitions of a 1-bit signal.
  std::vector<std::uint64_t> rising_edges(const std::string& name) const {
    std::vector<std::uint64_t> t;
    std::uint64_t prev = 0;
    for (const auto& [time, value] : of(name)) {
      if (value && !prev) t.push_back(time);
      prev = value;
    }
    return t;
  }
};

inline std::uint64_t vcd_bits(const std::string& s) {
  std::uint64_t v = 0;
  for (char c : s) v = (v << 1) | (c == '1' ? 1U : 0U);
  return v;
}

inline VcdFile read_vcd(const std::string& path) {
  VcdFile f;
  std::ifstream in(path);
  if (!in) {
    f.error = "cannot open " + path;
    return f;
  }
  std::string tok;
  std::uint64_t now = 0;
  bool header = true;
  // A variable's name is its scope path below the top scope ("SystemC"), joined with '.', and
  // its own name: "ls_conventional.sequencer.phase".
  std::vector<std::string> scopes;
  while (in >> tok) {
    if (header) {
      if (tok == "$comment" || tok == "$date" || tok == "$version") {
        std::string w;
        while (in >> w && w != "$end") {
        }
      } else if (tok == "$timescale") {
        std::string w;
        while (in >> w && w != "$end") f.timescale += (f.timescale.empty() ? "" : " ") + w;
      } else if (tok == "$scope") {
        std::string kind, name, w;
        in >> kind >> name;
        while (in >> w && w != "$end") {
        }
        scopes.push_back(name);
      } else if (tok == "$upscope") {
        std::string w;
        in >> w;
        if (!scopes.empty()) scopes.pop_back();
      } else if (tok == "$var") {
        std::string type, width, id, name, w;
        in >> type >> width >> id >> name;
        while (in >> w && w != "$end") {
        }
        for (std::size_t i = scopes.size(); i-- > 1;) name = scopes[i] + "." + name;
        f.id_of[name] = id;
        f.width_of[name] = std::stoi(width);
        f.changes[id];
      } else if (tok == "$enddefinitions") {
        std::string w;
        in >> w;
        header = false;
      }
      continue;
    }
    if (tok == "$comment") {  // free text up to $end
      std::string w;
      while (in >> w && w != "$end") {
      }
      continue;
    }
    if (tok[0] == '$') continue;  // $dumpvars / $end
    if (tok[0] == '#') {
      now = std::stoull(tok.substr(1));
      f.end_time = now;
    } else if (tok[0] == 'b' || tok[0] == 'B') {
      std::string id;
      in >> id;
      auto it = f.changes.find(id);
      if (it == f.changes.end()) {
        f.error = "unknown identifier " + id;
        return f;
      }
      it->second.emplace_back(now, vcd_bits(tok.substr(1)));
    } else if (tok[0] == 'r' || tok[0] == 'R') {  // real value: not kept (skip its identifier)
      std::string id;
      in >> id;
    } else if (tok[0] == '0' || tok[0] == '1' || tok[0] == 'x' || tok[0] == 'z') {
      const std::string id = tok.substr(1);
      auto it = f.changes.find(id);
      if (it == f.changes.end()) {
        f.error = "unknown identifier " + id;
        return f;
      }
      it->second.emplace_back(now, tok[0] == '1' ? 1U : 0U);
    }
  }
  f.ok = !f.id_of.empty();
  if (!f.ok) f.error = "no $var in " + path;
  return f;
}

}  // namespace rangesim::systemc::test
