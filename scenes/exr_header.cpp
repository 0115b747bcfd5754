#include "scenes/exr_header.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <system_error>

#include "scenes/input_error.h"
#include "scenes/input_file.h"

namespace facet::scene {

namespace {

// The attribute types whose OpenEXR reader reads a fixed layout, whatever
// size the file declares: their declared size must be that layout's.
const std::map<std::string_view, std::uint32_t> kFixedSizes = {{"box2i", 16},
                                                               {"box2f", 16},
                                                               {"chromaticities", 32},
                                                               {"compression", 1},
                                                               {"deepImageState", 1},
                                                               {"double", 8},
                                                               {"envmap", 1},
                                                               {"float", 4},
                                                               {"int", 4},
                                                               {"keycode", 28},
                                                               {"lineOrder", 1},
                                                               {"m33d", 72},
                                                               {"m33f", 36},
                                                               {"m44d", 128},
                                                               {"m44f", 64},
                                                               {"rational", 8},
                                                               {"tiledesc", 9},
                                                               {"timecode", 8},
                                                               {"v2d", 16},
                                                               {"v2f", 8},
                                                               {"v2i", 8},
                                                               {"v3d", 24},
                                                               {"v3f", 12},
                                                               {"v3i", 12}};

std::uint32_t le32(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[at + std::size_t(i)]);
  return value;
}

}  // namespace

void checkExrHeaders(const std::filesystem::path& file, const WindowCheck& checkSize) {
  const std::string source = file.string();
  std::ifstream in(file, std::ios::binary);
  std::error_code error;
  const std::uintmax_t fileSize = std::filesystem::file_size(file, error);
  if (!in || error) throw InputError(source, 0, "cannot open the OpenEXR file", "check the permissions");
  // Headers are read from the first 16 MiB: past it, what a header could
  // still claim is at most 128 times the file.
  std::string bytes(std::size_t(std::min<std::uintmax_t>(fileSize, 16u << 20)), '\0');
  in.read(bytes.data(), std::streamsize(bytes.size()));
  auto fail = [&](const std::string& detail) { return InputError(source, 0, "cannot read the OpenEXR file", detail); };
  // Truncated headers and names without their terminator: OpenEXR says so.
  std::size_t at = 8;
  auto text = [&](std::string& out) {
    const std::size_t end = bytes.find('\0', at);
    if (end == std::string::npos) return false;
    out.assign(bytes, at, end - at);
    at = end + 1;
    return true;
  };
  const bool multipart = bytes.size() >= 8 && (le32(bytes, 4) & 0x1000) != 0;
  for (bool more = true; more;) {
    std::string name, type;
    for (;;) {
      if (!text(name)) return;
      if (name.empty()) break;
      if (!text(type) || bytes.size() - at < 4) return;
      const std::uint32_t size = le32(bytes, at);
      at += 4;
      const std::string what = "attribute '" + name + "' (" + type + ") claims " + std::to_string(size) + " bytes";
      if (size > fileSize - at) throw fail(what + ", more than the file holds");
      const auto fixed = kFixedSizes.find(type);
      if (fixed != kFixedSizes.end() && size != fixed->second)
        throw fail(what + ", where its type has " + std::to_string(fixed->second));
      if (size > bytes.size() - at) return;
      const std::string_view value(bytes.data() + at, size);
      if (type == "box2i" && (name == "dataWindow" || name == "displayWindow"))
        checkSize(name, std::int64_t(std::int32_t(le32(value, 8))) - std::int32_t(le32(value, 0)) + 1,
                  std::int64_t(std::int32_t(le32(value, 12))) - std::int32_t(le32(value, 4)) + 1);
      // OpenEXR reads a channel list up to its empty name, and a preview as
      // width x height RGBA bytes: both must end where the size says.
      if (type == "chlist") {
        std::size_t end = 0;
        while (end < size && value[end] != '\0') {
          end = value.find('\0', end);
          if (end == std::string_view::npos || size - end - 1 < 16) throw fail(what + ", fewer than its channels");
          end += 1 + 16;
        }
        if (end + 1 != size) throw fail(what + ", other than its channels");
      }
      if (type == "preview" && (size < 8 || std::uint64_t(le32(value, 0)) * le32(value, 4) * 4 != size - 8))
        throw fail(what + ", other than its preview's pixels");
      // A string vector is strings of int32 length, each read at that length.
      if (type == "stringvector")
        for (std::size_t read = 0; read < size;) {
          if (size - read < 4 || le32(value, read) > size - read - 4) throw fail(what + ", fewer than its strings");
          read += 4 + le32(value, read);
        }
      at += size;
    }
    more = multipart && at < bytes.size() && bytes[at] != '\0';
  }
}

void checkTileFile(const std::filesystem::path& file, const std::string& what) {
  checkInputFile(file, what);
  checkExrHeaders(file, [&](const std::string& window, std::int64_t width, std::int64_t height) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384)
      throw InputError(
          file.string(), 0, window,
          "must be 1..16384 texels on each side, is " + std::to_string(width) + " x " + std::to_string(height));
  });
}

}  // namespace facet::scene
