#include "scenes/environment_map.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

// stb_image's Radiance reader, static so that no stbi symbol leaves the
// binary: a shared library that links Debian's full stb_image (tinygltf
// decoding PNG and JPEG) would otherwise bind to this HDR-only copy. The
// PNG and JPEG decoders of texture files are scenes/image_decoder.cpp's.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_HDR
#define STBI_NO_STDIO
#include <stb_image.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>
#include <string_view>
#include <system_error>

#include "scenes/exr_header.h"
#include "scenes/input_error.h"
#include "scenes/input_file.h"

namespace facet::scene {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kMaxWidth = 16384;

std::string sizeText(std::int64_t width, std::int64_t height) {
  return "the image is " + std::to_string(width) + " x " + std::to_string(height);
}

// Checked before any texel is allocated, so a hostile header cannot ask for
// gigabytes.
void checkSize(const std::string& source, std::int64_t width, std::int64_t height) {
  if (width <= 0 || height <= 0)
    throw InputError(source, 0, "an environment map must not be empty", sizeText(width, height));
  if (width % 2 != 0 || width / 2 != height)  // 2 x height could overflow
    throw InputError(source, 0, "an environment map must be 2:1 (width = 2 x height)", sizeText(width, height));
  if (width > kMaxWidth)
    throw InputError(source, 0, "an environment map must be at most 16384 x 8192", sizeText(width, height));
}

EnvironmentMap allocate(const fs::path& file, std::int64_t width, std::int64_t height) {
  EnvironmentMap map;
  map.source = file;
  map.width = int(width);
  map.height = int(height);
  map.rgb.resize(3 * std::size_t(width) * std::size_t(height));
  return map;
}

// Checked after zeroBadTexels, so only finite values remain.
void checkRadiance(const EnvironmentMap& map) {
  for (std::size_t i = 0; i < map.rgb.size(); ++i) {
    if (map.rgb[i] <= kMaxEnvironmentRadiance) continue;
    const std::size_t texel = i / 3, x = texel % std::size_t(map.width), y = texel / std::size_t(map.width);
    std::ostringstream detail;
    detail << "texel (" << x << ", " << y << ") holds " << map.rgb[i];
    throw InputError(map.source.string(), 0, "environment radiance must be at most 1e30", detail.str());
  }
}

// Renderers sum and importance-sample the map, where one NaN or negative
// texel would poison every pixel; 0 keeps the rest of the map usable.
void zeroBadTexels(EnvironmentMap& map) {
  for (std::size_t i = 0; i < map.rgb.size(); i += 3) {
    bool bad = false;
    for (std::size_t c = i; c < i + 3; ++c) {
      if (!(map.rgb[c] >= 0.0f) || std::isinf(map.rgb[c])) {  // !(x >= 0) also catches NaN
        map.rgb[c] = 0.0f;
        bad = true;
      }
    }
    map.clampedTexels += bad ? 1 : 0;
  }
}

EnvironmentMap readExr(const fs::path& file) {
  const std::string source = file.string();
  checkExrHeaders(file, [&](const std::string& window, std::int64_t width, std::int64_t height) {
    if (window == "dataWindow") checkSize(source, width, height);
  });
  try {
    Imf::InputFile in(source.c_str());
    const Imath::Box2i window = in.header().dataWindow();
    const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
    const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
    checkSize(source, width, height);

    const Imf::ChannelList& channels = in.header().channels();
    const bool rgb = channels.findChannel("R") && channels.findChannel("G") && channels.findChannel("B");
    const bool grey = !rgb && channels.findChannel("Y");
    if (!rgb && !grey) {
      std::string found;
      for (auto c = channels.begin(); c != channels.end(); ++c)
        found += (found.empty() ? "" : ", ") + std::string(c.name());
      throw InputError(source, 0, "an OpenEXR environment map needs channels R, G and B (or Y)",
                       "the file has " + (found.empty() ? std::string("no channels") : found));
    }

    EnvironmentMap map = allocate(file, width, height);
    Imf::FrameBuffer frame;
    const std::size_t stride = 3 * sizeof(float);
    if (rgb) {
      frame.insert("R", Imf::Slice::Make(Imf::FLOAT, &map.rgb[0], window, stride));
      frame.insert("G", Imf::Slice::Make(Imf::FLOAT, &map.rgb[1], window, stride));
      frame.insert("B", Imf::Slice::Make(Imf::FLOAT, &map.rgb[2], window, stride));
    } else {
      frame.insert("Y", Imf::Slice::Make(Imf::FLOAT, &map.rgb[0], window, stride));
    }
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    if (grey)
      for (std::size_t i = 0; i < map.rgb.size(); i += 3) map.rgb[i + 1] = map.rgb[i + 2] = map.rgb[i];
    return map;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {  // Iex::BaseExc and std::bad_alloc alike
    throw InputError(source, 0, "cannot read the OpenEXR file", e.what());
  }
}

struct RadianceImage {
  std::size_t pixels;  // offset of the first scanline
  std::int64_t width;
  std::int64_t height;
};

// The header as stb_image reads it: a magic line, variables up to an empty
// line, then the resolution line. Only stb's layout, "-Y H +X W", is taken.
RadianceImage radianceHeader(const std::string& source, std::string_view bytes) {
  auto malformed = [&](const std::string& detail) {
    return InputError(source, 0, "not a valid Radiance .hdr file", detail);
  };
  std::size_t at = 0;
  auto line = [&]() {
    const std::size_t end = bytes.find('\n', at);
    if (end == std::string_view::npos) throw malformed("the header is incomplete");
    const std::string_view text = bytes.substr(at, end - at);
    at = end + 1;
    return text;
  };
  const std::string_view magic = line();
  if (magic != "#?RADIANCE" && magic != "#?RGBE") throw malformed("it does not start with #?RADIANCE");
  bool rgbe = false;
  for (std::string_view variable = line(); !variable.empty(); variable = line())
    rgbe = rgbe || variable == "FORMAT=32-bit_rle_rgbe";
  if (!rgbe) throw malformed("only FORMAT=32-bit_rle_rgbe is supported");

  const std::string_view resolution = line();
  RadianceImage image{at, 0, 0};
  const char* p = resolution.data();
  const char* const end = p + resolution.size();
  auto literal = [&](std::string_view text) {
    const bool found = std::string_view(p, std::size_t(end - p)).substr(0, text.size()) == text;
    if (found) p += text.size();
    return found;
  };
  auto number = [&](std::int64_t& value) {
    const auto [next, error] = std::from_chars(p, end, value);
    p = next;
    return error == std::errc();
  };
  if (!(literal("-Y ") && number(image.height) && literal(" +X ") && number(image.width) && p == end))
    throw malformed("the resolution line must read -Y <height> +X <width>, not '" + std::string(resolution) + "'");
  return image;
}

// stb_image reads zeros past the end of its input: a truncated file would
// decode as black, or spin forever on a zero run length. So the pixel data
// is walked here first, byte for byte as stb_image will read it.
void checkRadiancePixels(const std::string& source, std::string_view bytes, const RadianceImage& image) {
  auto malformed = [&](const std::string& detail) {
    return InputError(source, 0, "not a valid Radiance .hdr file", detail);
  };
  const std::size_t size = bytes.size();
  const std::size_t flat = 4 * std::size_t(image.width) * std::size_t(image.height);
  auto byte = [&](std::size_t i) { return static_cast<unsigned char>(bytes[i]); };
  std::size_t at = image.pixels;
  if (image.width < 8 || image.width >= 32768) {  // stb reads such images uncompressed
    if (size - at < flat) throw malformed("the pixel data is truncated");
    return;
  }
  for (std::int64_t y = 0; y < image.height; ++y) {
    const std::string where = " in scanline " + std::to_string(y);
    if (size - at < 4) throw malformed("the pixel data is truncated" + where);
    if (byte(at) != 2 || byte(at + 1) != 2 || (byte(at + 2) & 0x80)) {
      // stb then starts again, uncompressed, from the first pixel.
      if (size - at < flat) throw malformed("the pixel data is truncated" + where);
      return;
    }
    if (((std::int64_t(byte(at + 2)) << 8) | byte(at + 3)) != image.width)
      throw malformed("the run-length scanline length differs from the width" + where);
    at += 4;
    for (int channel = 0; channel < 4; ++channel) {
      for (std::int64_t x = 0; x < image.width;) {
        if (at >= size) throw malformed("the pixel data is truncated" + where);
        const int count = byte(at++);
        const bool run = count > 128;
        const std::int64_t length = run ? count - 128 : count;
        if (length == 0 || length > image.width - x) throw malformed("bad run-length data" + where);
        const std::size_t payload = run ? 1 : std::size_t(length);
        if (size - at < payload) throw malformed("the pixel data is truncated" + where);
        at += payload;
        x += length;
      }
    }
  }
}

EnvironmentMap readHdr(const fs::path& file) {
  const std::string source = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(source, 0, "cannot open the environment map", "check the permissions");
  const std::string bytes(std::istreambuf_iterator<char>(in), {});
  if (bytes.size() > std::size_t(INT_MAX)) throw InputError(source, 0, "not a valid Radiance .hdr file", "too large");

  const RadianceImage image = radianceHeader(source, bytes);
  checkSize(source, image.width, image.height);
  checkRadiancePixels(source, bytes, image);

  int width = 0, height = 0, components = 0;
  const std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &width, &height,
                             &components, 3),
      stbi_image_free);
  if (!pixels) throw InputError(source, 0, "not a valid Radiance .hdr file", stbi_failure_reason());
  if (width != image.width || height != image.height)
    throw InputError(source, 0, "not a valid Radiance .hdr file", "the decoded size differs from the header");
  EnvironmentMap map = allocate(file, width, height);
  std::copy_n(pixels.get(), map.rgb.size(), map.rgb.begin());
  return map;
}

}  // namespace

std::uint64_t EnvironmentMap::contentHash() const {
  std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a 64
  auto add = [&](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
  };
  const std::int32_t size[2] = {width, height};
  add(size, sizeof size);
  add(rgb.data(), rgb.size() * sizeof(float));
  return hash;
}

EnvironmentMap loadEnvironmentMap(const fs::path& file) {
  const std::string source = file.string();
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".exr" && extension != ".hdr")
    throw InputError(source, 0, "unknown environment map format",
                     "expected .exr (OpenEXR) or .hdr (Radiance), not '" + file.extension().string() + "'");
  checkInputFile(file, "the environment map");

  EnvironmentMap map = extension == ".exr" ? readExr(file) : readHdr(file);
  zeroBadTexels(map);
  checkRadiance(map);
  return map;
}

float EnvironmentMap::largestRadiance() const {
  float largest = 0.0f;
  for (float channel : rgb) largest = std::max(largest, channel);
  return largest;
}

EnvironmentMap constantEnvironment(const glm::dvec3& color) {
  EnvironmentMap map;
  map.width = 8;
  map.height = 4;
  map.rgb.reserve(3 * 8 * 4);
  for (int i = 0; i < 8 * 4; ++i) map.rgb.insert(map.rgb.end(), {float(color.r), float(color.g), float(color.b)});
  return map;
}

}  // namespace facet::scene
