#pragma once
// Reading an input file (preset, scene, depth-map image, shard) so that every way it can be
// unreadable is reported as what it is: missing, a directory, a FIFO, a device, a socket, a loop
// of symbolic links, permission denied, too large. Only regular files are read, so /dev/zero or
// a FIFO cannot hang the process or exhaust its memory before any content check runs.
#include <cstdint>
#include <optional>
#include <string>

namespace rangesim {

// Why `path` cannot be read as a regular file ("" when it can be opened as one). Never throws.
std::string unreadable_reason(const std::string& path);

// Throws the UserError of read_input_file when `path` cannot be read as a regular file.
void check_readable(const std::string& path, const std::string& what, std::uintmax_t max_bytes,
                    const std::string& where = "");

// The whole content of the regular file `path`. `what` names it in messages ("preset file",
// "scene file", ...). Throws UserError "<where>: cannot read <what>: <reason>; allowed: a regular
// file of at most <max_bytes> bytes" for anything else; `where` defaults to the path.
std::string read_input_file(const std::string& path, const std::string& what, std::uintmax_t max_bytes,
                            const std::string& where = "");

}  // namespace rangesim
