// A check of an OpenEXR file's headers before OpenEXR reads them. OpenEXR
// allocates from a header before it reads any pixel (each attribute at the
// size the file declares, line buffers as wide as the data window), so a
// hostile header of a few bytes could ask for gigabytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>

namespace facet::scene {

// Walks every header as OpenEXR reads it (OpenEXR file layout, "Header
// Attributes") and throws InputError naming the file when an attribute
// claims more bytes than the file holds or than its type has. Each data
// window found is handed to `checkSize` (width, height) first.
void checkExrHeaders(const std::filesystem::path& file,
                     const std::function<void(std::int64_t width, std::int64_t height)>& checkSize);

}  // namespace facet::scene
