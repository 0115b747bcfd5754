// The loaders read files by path, so a fuzz input is written to a file and
// loaded from there. Each process writes into a folder of its own under the
// system's temporary folder, removed when the process exits normally.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace facet::fuzz {

// This process's scratch folder, created on first use.
const std::filesystem::path& scratchFolder();

// Writes the input to scratchFolder() / `name` (replacing what was there)
// and returns that path.
std::filesystem::path writeScratchFile(const std::filesystem::path& name, const std::uint8_t* data, std::size_t size);

}  // namespace facet::fuzz
