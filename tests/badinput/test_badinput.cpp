// Bad-input corpus (cases.toml) through the built rangesim binary: exit code 2, an empty stdout,
// stderr naming the file or flag, the key and the allowed range, and nothing in --out.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <toml++/toml.h>

#include "run_command.h"

namespace fs = std::filesystem;

namespace {

struct Case {
  std::string name;
  std::string preset;                // sensor id of the preset to copy ("" = none)
  std::vector<std::string> replace;  // section, key, new rhs
  std::vector<std::string> remove;   // section, key
  std::vector<std::string> insert;   // section, line
  std::optional<std::string> text;   // whole file
  std::string make_file;             // a regular file to create in {tmp}
  std::string make_dir;              // a directory to create in {tmp}
  std::string make_fifo;             // a FIFO (named pipe) to create in {tmp}
  std::string make_loop;             // a symbolic link to itself to create in {tmp}
  std::string args;
  std::vector<std::string> fragments;
};

std::vector<std::string> strings(const toml::table& t, const char* key) {
  std::vector<std::string> v;
  if (const auto* a = t[key].as_array())
    for (const auto& e : *a) v.push_back(e.value<std::string>().value());
  return v;
}

std::vector<Case> load_cases() {
  std::vector<Case> cases;
  const toml::table root = toml::parse_file(RANGESIM_BADINPUT_CASES);
  for (const auto& node : *root["case"].as_array()) {
    const toml::table& t = *node.as_table();
    Case c;
    c.name = t["name"].value_or(std::string());
    c.preset = t["preset"].value_or(std::string());
    c.replace = strings(t, "replace");
    c.remove = strings(t, "delete");
    c.insert = strings(t, "insert");
    if (auto s = t["text"].value<std::string>()) c.text = *s;
    c.make_file = t["make_file"].value_or(std::string());
    c.make_dir = t["make_dir"].value_or(std::string());
    c.make_fifo = t["make_fifo"].value_or(std::string());
    c.make_loop = t["make_loop"].value_or(std::string());
    c.args = t["args"].value_or(std::string());
    c.fragments = strings(t, "stderr");
    cases.push_back(c);
  }
  return cases;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all = load_cases();
  return all;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string substitute(std::string s, const std::map<std::string, std::string>& vars) {
  for (const auto& [k, v] : vars)
    for (size_t p; (p = s.find(k)) != std::string::npos;) s.replace(p, k.size(), v);
  return s;
}

// Applies the case's edit to presets/<id>.toml, line by line inside [section].
std::string edited_preset(const Case& c) {
  if (c.text) return *c.text;
  std::istringstream in(read_text(std::string(RANGESIM_PRESET_SOURCE_DIR) + "/" + c.preset + ".toml"));
  const std::string& section = !c.replace.empty()  ? c.replace[0]
                               : !c.remove.empty() ? c.remove[0]
                               : !c.insert.empty() ? c.insert[0]
                                                   : std::string();
  std::string out, line, current;
  bool done = section.empty();
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '[') current = line.substr(1, line.find(']') - 1);
    bool keep = true;
    if (!done && current == section) {
      if (!c.insert.empty() && line[0] == '[') {
        out += line + "\n" + c.insert[1] + "\n";
        keep = false;
        done = true;
      } else {
        const std::string& key = !c.replace.empty() ? c.replace[1] : !c.remove.empty() ? c.remove[1] : "";
        if (!key.empty() && line.rfind(key + " = ", 0) == 0) {
          if (!c.replace.empty()) out += key + " = " + c.replace[2] + "\n";
          keep = false;
          done = true;
        }
      }
    }
    if (keep) out += line + "\n";
  }
  if (!done) throw std::logic_error(c.name + ": the edit did not match any line of presets/" + c.preset + ".toml");
  return out;
}

// Test names and failure messages show the case name, not the struct's bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class BadInput : public ::testing::TestWithParam<Case> {};

TEST_P(BadInput, ExitsWithCode2AndAClearMessageAndWritesNothing) {
  const Case& c = GetParam();
  const std::string tmp = make_temp_dir();
  const std::string out = tmp + "/out", file = tmp + "/preset.toml";
  const std::map<std::string, std::string> vars = {
      {"{file}", file}, {"{out}", out}, {"{tmp}", tmp}, {"{presets}", RANGESIM_PRESET_SOURCE_DIR}};
  if (!c.preset.empty() || c.text) std::ofstream(file, std::ios::binary) << edited_preset(c);
  if (!c.make_file.empty()) std::ofstream(tmp + "/" + c.make_file) << "not a directory\n";
  if (!c.make_dir.empty()) fs::create_directory(tmp + "/" + c.make_dir);
  if (!c.make_fifo.empty()) {
    ASSERT_EQ(::mkfifo((tmp + "/" + c.make_fifo).c_str(), 0644), 0);
  }
  if (!c.make_loop.empty()) fs::create_symlink(c.make_loop, tmp + "/" + c.make_loop);
  const std::string args = substitute(c.args, vars);

  const CommandResult r =
      run_command(std::string("RANGESIM_PRESET_DIR=") + RANGESIM_PRESET_SOURCE_DIR + " " + RANGESIM_BIN + " " + args);
  SCOPED_TRACE("rangesim " + args);
  EXPECT_EQ(r.exit_code, 2) << "stderr: " << r.err;
  EXPECT_TRUE(r.out.empty()) << "stdout: " << r.out;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  for (const auto& f : c.fragments) {
    const std::string want = substitute(f, vars);
    EXPECT_NE(r.err.find(want), std::string::npos) << "stderr lacks '" << want << "':\n" << r.err;
  }
  // Nothing written: the --out directory is absent or empty (no staging folder left either).
  EXPECT_FALSE(fs::exists(out) && !fs::is_empty(out)) << out << " has files";
  for (const auto& e : fs::directory_iterator(tmp)) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(e.path() == file || name == c.make_file || name == c.make_dir || name == c.make_fifo ||
                name == c.make_loop)
        << "left behind: " << e.path();
  }
  if (!c.make_dir.empty()) {
    EXPECT_TRUE(fs::is_empty(tmp + "/" + c.make_dir)) << "written into " << c.make_dir;
  }
  fs::remove_all(tmp);
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadInput, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& i) { return i.param.name; });

TEST(BadInputCorpus, HasAtLeastFiftyCasesCoveringEverySensorAndSubcommand) {
  EXPECT_GE(cases().size(), 50u);
  for (const char* sensor : {"ls-conventional", "ls-demodulation", "tof-lockin", "tof-spad"}) {
    bool found = false;
    for (const auto& c : cases()) found = found || c.preset == sensor;
    EXPECT_TRUE(found) << "no bad preset of " << sensor;
  }
  for (const char* cmd : {"list", "show", "evaluate", "frame-rate", "table"}) {
    bool found = false;
    for (const auto& c : cases()) found = found || c.args.rfind(std::string(cmd) + " ", 0) == 0 || c.args == cmd;
    EXPECT_TRUE(found) << "no bad flag of " << cmd;
  }
}

}  // namespace
