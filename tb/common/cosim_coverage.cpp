#include "tb/common/cosim_coverage.h"

#include <verilated.h>
#include <verilated_cov.h>

#include <cstdio>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <unistd.h>

namespace rangesim::tb {

RtlCoverage parse_coverage_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read coverage data " + path);
  RtlCoverage cov;
  std::string line;
  // A point: C '<key>\x02<value>\x01<key>\x02<value>...' <count>; the page key is "page".
  const std::string page_key = std::string("\001page\002");
  while (std::getline(in, line)) {
    if (line.size() < 4 || line[0] != 'C') continue;
    const std::size_t close = line.rfind('\'');
    if (close == std::string::npos || close + 1 >= line.size()) continue;
    const long long count = std::stoll(line.substr(close + 1));
    const std::size_t p = line.find(page_key);
    if (p == std::string::npos) continue;
    const std::string page = line.substr(p + page_key.size(), 8);
    const bool hit = count > 0;
    if (page.rfind("v_line", 0) == 0 || page.rfind("v_branch", 0) == 0) {
      ++cov.line_points;
      cov.line_hit += hit;
    } else if (page.rfind("v_toggle", 0) == 0) {
      ++cov.toggle_points;
      cov.toggle_hit += hit;
    }
  }
  cov.available = cov.line_points + cov.toggle_points > 0;
  return cov;
}

namespace {

std::optional<RtlCoverage>& captured() {
  static std::optional<RtlCoverage> c;
  return c;
}

RtlCoverage read_live_counters() {
  char tmpl[] = "/tmp/rangesim_coverage_XXXXXX";
  const int fd = mkstemp(tmpl);
  if (fd < 0) throw std::runtime_error("cannot create a temporary coverage file");
  close(fd);
  Verilated::defaultContextp()->coveragep()->write(tmpl);
  RtlCoverage cov = parse_coverage_file(tmpl);
  std::remove(tmpl);
  return cov;
}

}  // namespace

void capture_rtl_coverage() { captured() = read_live_counters(); }

RtlCoverage rtl_coverage() { return captured() ? *captured() : read_live_counters(); }

}  // namespace rangesim::tb
