#pragma once
// Helpers for the preset tests: the source-tree preset directory, temporary preset files made by
// editing one line of a real preset, and capturing the message of a UserError.
#include <functional>
#include <string>
#include <vector>

namespace rangesim::test {

// The four preset ids, in thesis order.
const std::vector<std::string>& preset_ids();

// Path of presets/<id>.toml in the source tree.
std::string source_preset_path(const std::string& id);

std::string read_text(const std::string& path);

// One TOML line edit of a preset text. Lines are matched inside `[section]` by `name = ...`.
struct Edit {
  std::string text;  // the edited file
  int line = 0;      // 1-based line number of the edited (or inserted) line; 0 for a deletion
};
// Replaces the line `name = ...` of [section] by `new_line`; throws std::logic_error if absent.
Edit replace_line(const std::string& text, const std::string& section, const std::string& name,
                  const std::string& new_line);
// Replaces only what follows `name = ` on that line.
Edit replace_rhs(const std::string& text, const std::string& section, const std::string& name,
                 const std::string& new_rhs);
// Deletes the line `name = ...` of [section].
Edit delete_line(const std::string& text, const std::string& section, const std::string& name);
// Inserts `line` right after the `[section]` header.
Edit insert_after_header(const std::string& text, const std::string& section, const std::string& line);

// A preset file in a fresh temporary directory, removed with the object.
class TempPreset {
 public:
  explicit TempPreset(const std::string& content, const std::string& file_name = "preset.toml");
  ~TempPreset();
  TempPreset(const TempPreset&) = delete;
  TempPreset& operator=(const TempPreset&) = delete;
  const std::string& path() const { return path_; }
  const std::string& dir() const { return dir_; }

 private:
  std::string dir_;
  std::string path_;
};

// Runs f and returns the message of the UserError it throws. Records a test failure (and returns
// "") when f returns normally or throws anything else.
std::string user_error_of(const std::function<void()>& f);

}  // namespace rangesim::test
