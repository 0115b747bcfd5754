// Only regular files are read as input (docs/reliability.md, "What is
// rejected"): a FIFO would block the read for ever, a device such as
// /dev/zero (or a link to one) would never end it, and a folder cannot be
// decoded. Checked before a loader opens the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace facet::scene {

// No input facet reads comes near this; a larger file is refused before it is read.
constexpr std::uintmax_t kLargestInputFile = std::uintmax_t(8) << 30;

// Throws InputError "<path>: cannot open <what>: <rule>" unless `path` is an
// existing regular file (links followed) of at most kLargestInputFile bytes.
void checkInputFile(const std::filesystem::path& path, const std::string& what);

}  // namespace facet::scene
