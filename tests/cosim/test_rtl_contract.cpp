// docs/rtl-contract.md is the port contract a user's RTL is checked against; this test holds it
// to rangesim's own RTL: every block's table lists exactly the ports Verilator elaborates from
// rtl/ at the parameters the section names (name, direction, width). A port changed in rtl/ fails
// here until the contract changes too (a new contract version).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tb/common/rtl_ports.h"
#include "tb/common/rtl_process.h"

namespace rangesim::tb {
namespace {

struct ContractSection {
  std::string module, file;
  VerilogParameters parameters;
  std::vector<RtlPort> ports;
};

std::vector<ContractSection> read_contract(const std::string& path) {
  std::ifstream in(path);
  std::vector<ContractSection> out;
  const std::regex head(R"(^### `(\w+)` \(`(rtl/[\w/]+\.sv)`\))"), widths(R"(^Widths at: `([^`]*)`)"),
      row(R"(^\| `(\w+)` \| (input|output|inout) \| (\d+) \|)");
  std::smatch m;
  for (std::string line; std::getline(in, line);) {
    if (std::regex_search(line, m, head)) {
      out.push_back({m[1], m[2], {}, {}});
    } else if (!out.empty() && std::regex_search(line, m, widths)) {
      std::istringstream kv(m[1].str());
      for (std::string p; kv >> p;)
        out.back().parameters.push_back({p.substr(0, p.find('=')), std::stoll(p.substr(p.find('=') + 1))});
    } else if (!out.empty() && std::regex_search(line, m, row)) {
      out.back().ports.push_back({m[1], m[2], std::stoi(m[3])});
    }
  }
  return out;
}

TEST(RtlContract, EveryBlockOfRtlIsInTheContractWithItsPorts) {
  const std::string verilator = find_program("verilator");
  if (verilator.empty()) GTEST_SKIP() << "verilator not on PATH";
  const std::string src = RANGESIM_SOURCE_DIR;
  const std::vector<ContractSection> sections = read_contract(src + "/docs/rtl-contract.md");
  // Every module file of rtl/ has its section.
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(src + "/rtl"))
    if (e.path().extension() == ".sv") files.push_back(std::filesystem::relative(e.path(), src).string());
  ASSERT_EQ(sections.size(), files.size());
  const std::string scratch = testing::TempDir();
  for (const auto& s : sections) {
    SCOPED_TRACE(s.module);
    EXPECT_NE(std::find(files.begin(), files.end(), s.file), files.end()) << s.file;
    const std::string folder = std::filesystem::path(s.file).parent_path().filename().string();
    RtlElaboration e{
        verilator, {src + "/" + s.file}, {src + "/rtl/common", src + "/rtl/" + folder}, src + "/rtl", scratch};
    const ElaboratedModule m = elaborate_module(e, s.module, s.parameters);
    ASSERT_FALSE(s.ports.empty());
    EXPECT_EQ(m.ports, s.ports);
    EXPECT_NO_THROW(check_port_contract(s.file, s.module, s.ports, m.ports, s.parameters));
  }
}

TEST(RtlContract, AMissingOrNarrowerPortIsNamed) {
  const std::vector<RtlPort> want{{"clk", "input", 1}, {"sum_o", "output", 8}, {"count_o", "output", 3}};
  const std::vector<RtlPort> have{{"clk", "input", 1}, {"sum_o", "output", 7}, {"extra_o", "output", 1}};
  try {
    check_port_contract("my.sv", "centre_processor", want, have, {{"ADDRESS_BITS", 4}});
    FAIL() << "no error";
  } catch (const std::exception& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("my.sv: module centre_processor"), std::string::npos) << msg;
    EXPECT_NE(msg.find("port sum_o is 7 bits wide; expected: 8 bits"), std::string::npos) << msg;
    EXPECT_NE(msg.find("port count_o is missing; expected: output [3 bits]"), std::string::npos) << msg;
    EXPECT_NE(msg.find("port extra_o is not in the contract"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at ADDRESS_BITS=4"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace rangesim::tb
