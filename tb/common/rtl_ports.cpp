// Port contract of a user's RTL: see rtl_ports.h.
#include "tb/common/rtl_ports.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "core/user_error.h"
#include "tb/common/rtl_process.h"

namespace rangesim::tb {
namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string strip_comments(const std::string& v) {
  static const std::regex block(R"(/\*[\s\S]*?\*/)"), line(R"(//[^\n]*)");
  return std::regex_replace(std::regex_replace(v, block, " "), line, " ");
}

std::string attribute(const std::string& tag, const std::string& name) {
  const std::regex re("\\b" + name + "=\"([^\"]*)\"");
  std::smatch m;
  return std::regex_search(tag, m, re) ? m[1].str() : "";
}

// The widths of the XML's type table: dtype id -> bits (left - right + 1; 1 without a range).
std::map<std::string, int> dtype_widths(const std::string& xml) {
  std::map<std::string, int> w;
  static const std::regex tag(R"(<(basicdtype|packarraydtype|refdtype|structdtype|enumdtype)\b[^>]*>)");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator(); ++it) {
    const std::string t = it->str();
    const std::string left = attribute(t, "left"), right = attribute(t, "right");
    w[attribute(t, "id")] = left.empty() ? 1 : std::abs(std::stoi(left) - std::stoi(right)) + 1;
  }
  return w;
}

}  // namespace

std::vector<std::string> modules_defined_in(const std::string& file) {
  const std::string text = strip_comments(read_text(file));
  static const std::regex re(R"((?:^|[\s;])module\s+(?:automatic\s+|static\s+)?([A-Za-z_][A-Za-z0-9_$]*))");
  std::vector<std::string> names;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1].str());
  return names;
}

ElaboratedModule elaborate_module(const RtlElaboration& e, const std::string& module,
                                  const VerilogParameters& parameters) {
  const std::string xml_path = e.scratch + "/" + module + ".xml";
  const std::string log = e.scratch + "/" + module + ".xml.log";
  std::vector<std::string> args{e.verilator,   "--xml-only", "--xml-output", xml_path, "-f",
                                "verilator.f", "-Wno-fatal", "--top-module", module};
  for (const auto& d : e.search_dirs) args.insert(args.end(), {"-y", d});
  for (const auto& p : parameters) args.push_back("-G" + p.name + "=" + std::to_string(p.value));
  args.insert(args.end(), e.files.begin(), e.files.end());
  std::remove(log.c_str());
  if (run_program(args, e.rtl_dir, log) != 0)
    throw UserError(fmt::format("cosim: Verilator cannot elaborate module {} from {}:\n{}", module,
                                fmt::join(e.files, ", "), log_tail(log, 25)));
  const std::string xml = read_text(xml_path);
  const std::map<std::string, int> widths = dtype_widths(xml);
  ElaboratedModule out;
  static const std::regex mod(R"(<module\b[^>]*>)"), var(R"(<var\b[^>]*>)");
  // Ports: the <var dir=...> of the top module, which Verilator lists first.
  const std::size_t top_at = xml.find("topModule=\"1\"");
  const std::size_t top_end = top_at == std::string::npos ? std::string::npos : xml.find("</module>", top_at);
  if (top_end != std::string::npos) {
    const std::string body = xml.substr(top_at, top_end - top_at);
    for (auto it = std::sregex_iterator(body.begin(), body.end(), var); it != std::sregex_iterator(); ++it) {
      const std::string t = it->str(), dir = attribute(t, "dir");
      if (dir.empty()) continue;
      const auto w = widths.find(attribute(t, "dtype_id"));
      out.ports.push_back({attribute(t, "name"), dir, w == widths.end() ? 1 : w->second});
    }
  }
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), mod); it != std::sregex_iterator(); ++it)
    out.hierarchy.push_back(attribute(it->str(), "origName"));
  return out;
}

void check_port_contract(const std::string& file, const std::string& module, const std::vector<RtlPort>& want,
                         const std::vector<RtlPort>& have, const VerilogParameters& parameters) {
  std::vector<std::string> problems;
  for (const auto& w : want) {
    const RtlPort* h = nullptr;
    for (const auto& x : have)
      if (x.name == w.name) h = &x;
    if (!h)
      problems.push_back(fmt::format("port {} is missing; expected: {} [{} bits]", w.name, w.direction, w.width));
    else if (h->direction != w.direction)
      problems.push_back(fmt::format("port {} is an {}; expected: {}", w.name, h->direction, w.direction));
    else if (h->width != w.width)
      problems.push_back(fmt::format("port {} is {} bits wide; expected: {} bits", w.name, h->width, w.width));
  }
  for (const auto& h : have) {
    bool known = false;
    for (const auto& w : want) known = known || w.name == h.name;
    if (!known) problems.push_back(fmt::format("port {} is not in the contract", h.name));
  }
  if (problems.empty()) return;
  std::string msg = fmt::format("cosim: {}: module {} does not meet its port contract (docs/rtl-contract.md{}):", file,
                                module, parameters.empty() ? "" : ", at " + parameters_text(parameters));
  for (const auto& p : problems) msg += "\n  " + p;
  throw UserError(msg);
}

}  // namespace rangesim::tb
