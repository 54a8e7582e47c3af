#include "tests/core/preset_test_util.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/user_error.h"

#ifndef RANGESIM_TEST_PRESET_DIR
#error "RANGESIM_TEST_PRESET_DIR must name the source tree's presets/ directory"
#endif

namespace fs = std::filesystem;

namespace rangesim::test {

namespace {

// load_preset("<id>") must find this tree's presets, never an installed copy: point the search
// path's first entry at the source tree before any test runs.
class PresetDirEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { ::setenv("RANGESIM_PRESET_DIR", RANGESIM_TEST_PRESET_DIR, 1); }
};
[[maybe_unused]] ::testing::Environment* const preset_dir_env =
    ::testing::AddGlobalTestEnvironment(new PresetDirEnvironment);

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

std::string trim_left(const std::string& s) {
  const auto i = s.find_first_not_of(" \t");
  return i == std::string::npos ? "" : s.substr(i);
}

// Index of the `[section]` header line, or -1.
int find_header(const std::vector<std::string>& lines, const std::string& section) {
  for (size_t i = 0; i < lines.size(); ++i)
    if (trim_left(lines[i]).rfind("[" + section + "]", 0) == 0) return static_cast<int>(i);
  return -1;
}

// Index of `name = ...` inside [section], or throws.
size_t find_key_line(const std::vector<std::string>& lines, const std::string& section, const std::string& name) {
  const int header = find_header(lines, section);
  if (header < 0) throw std::logic_error("no [" + section + "] in preset text");
  for (size_t i = static_cast<size_t>(header) + 1; i < lines.size(); ++i) {
    const std::string t = trim_left(lines[i]);
    if (!t.empty() && t[0] == '[') break;
    if (t.rfind(name, 0) == 0) {
      const std::string rest = trim_left(t.substr(name.size()));
      if (!rest.empty() && rest[0] == '=') return i;
    }
  }
  throw std::logic_error("no " + section + "." + name + " in preset text");
}

}  // namespace

const std::vector<std::string>& preset_ids() {
  static const std::vector<std::string> ids = {"ls-conventional", "ls-demodulation", "tof-lockin", "tof-spad"};
  return ids;
}

std::string source_preset_path(const std::string& id) {
  return (fs::path(RANGESIM_TEST_PRESET_DIR) / (id + ".toml")).string();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Edit replace_line(const std::string& text, const std::string& section, const std::string& name,
                  const std::string& new_line) {
  auto lines = split_lines(text);
  const size_t i = find_key_line(lines, section, name);
  lines[i] = new_line;
  return {join_lines(lines), static_cast<int>(i) + 1};
}

Edit replace_rhs(const std::string& text, const std::string& section, const std::string& name,
                 const std::string& new_rhs) {
  return replace_line(text, section, name, name + " = " + new_rhs);
}

Edit delete_line(const std::string& text, const std::string& section, const std::string& name) {
  auto lines = split_lines(text);
  const size_t i = find_key_line(lines, section, name);
  lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(i));
  return {join_lines(lines), 0};
}

Edit insert_after_header(const std::string& text, const std::string& section, const std::string& line) {
  auto lines = split_lines(text);
  const int header = find_header(lines, section);
  if (header < 0) throw std::logic_error("no [" + section + "] in preset text");
  lines.insert(lines.begin() + header + 1, line);
  return {join_lines(lines), header + 2};
}

TempPreset::TempPreset(const std::string& content, const std::string& file_name) {
  static std::atomic<int> counter{0};
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string tag = info ? std::string(info->test_suite_name()) + "." + info->name() : "no-test";
  for (char& c : tag)
    if (c == '/') c = '_';
  dir_ = (fs::temp_directory_path() /
          ("rangesim-test-core-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" + tag))
             .string();
  fs::create_directories(dir_);
  path_ = (fs::path(dir_) / file_name).string();
  std::ofstream out(path_);
  out << content;
  if (!out) throw std::runtime_error("cannot write " + path_);
}

TempPreset::~TempPreset() {
  std::error_code ec;
  fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
  fs::remove_all(dir_, ec);
}

std::string user_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected a UserError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected a UserError, but the call succeeded";
  return "";
}

}  // namespace rangesim::test
