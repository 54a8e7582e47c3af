#pragma once
// Bad user input (preset, scene, flag). The CLI prints what() and exits with code 2; the
// message always names the file or flag, the key and the allowed range.
#include <stdexcept>
#include <string>

namespace rangesim {

class UserError : public std::runtime_error {
 public:
  explicit UserError(const std::string& message) : std::runtime_error(message) {}
  // `key`: the parameter or argument at fault (also named in the message), for callers that
  // report it apart from the text (the Python module's rangesim.Error.key).
  UserError(const std::string& message, std::string key) : std::runtime_error(message), key_(std::move(key)) {}
  const std::string& key() const { return key_; }  // "" when the error is not about one key

 private:
  std::string key_;
};

}  // namespace rangesim
