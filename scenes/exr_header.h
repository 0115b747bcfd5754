// A check of an OpenEXR file's headers before OpenEXR reads them. OpenEXR
// allocates from a header before it reads any pixel (each attribute at the
// size the file declares, line buffers as wide as the data window), so a
// hostile header of a few bytes could ask for gigabytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

namespace facet::scene {

// Walks every header as OpenEXR reads it (OpenEXR file layout, "Header
// Attributes") and throws InputError naming the file when an attribute
// claims more bytes than the file holds or than its type has. Each data and
// display window found is handed to `checkSize` ("dataWindow" or
// "displayWindow", width, height) first.
using WindowCheck = std::function<void(const std::string& window, std::int64_t width, std::int64_t height)>;
void checkExrHeaders(const std::filesystem::path& file, const WindowCheck& checkSize);

// A tile `facet merge` reads (or another render facet reads back, `what`
// in the error): a regular file (scenes/input_file.h) whose headers pass
// checkExrHeaders with each window 1..16384 texels on a side, the image size
// limit, so that no header makes the reader allocate more than the image it
// claims to be part of could need.
void checkTileFile(const std::filesystem::path& file, const std::string& what = "the tile");

}  // namespace facet::scene
