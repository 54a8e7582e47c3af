#pragma once
// Bad user input (preset, scene, flag). The CLI prints what() and exits with code 2; the
// message always names the file or flag, the key and the allowed range.
#include <stdexcept>
#include <string>

namespace rangesim {

class UserError : public std::runtime_error {
 public:
  explicit UserError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace rangesim
