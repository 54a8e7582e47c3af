#pragma once
// Checks of flag values on their text, before CLI11 converts them: no value wraps around (--seed -1
// read as 2^64 - 1), overflows, or is refused without its allowed range. Each returns "" when the
// text is allowed, else the message CLI11 prints after the flag's name ("--seed: ...").
#include <cstdint>
#include <string>

namespace rangesim::app {

// An integer in [lo, hi]: decimal digits with an optional sign, or a number such as 1e3 whose value
// is an integer, which is rewritten to plain digits for the conversion that follows.
std::string check_integer_text(std::string& text, long long lo, long long hi);
std::string check_unsigned_text(std::string& text, std::uint64_t lo, std::uint64_t hi);

// A finite number > lo (lo_exclusive) or >= lo, and <= hi; `unit` is shown with the range.
std::string check_real_text(const std::string& text, double lo, bool lo_exclusive, double hi, const std::string& unit);

// A file or directory name: not empty (an empty --out would silently mean the default folder).
std::string check_path_text(const std::string& text);

// A memory size: bytes, or a number with K, M, G or T (powers of 1024), e.g. 512M, 1.5G.
// `bytes` receives the value. Allowed 16M .. 1024T.
std::string check_memory_text(const std::string& text, std::uint64_t& bytes);

}  // namespace rangesim::app
