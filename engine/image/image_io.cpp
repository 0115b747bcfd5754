#include "engine/image/image_io.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <system_error>

#include "engine/image/color.h"

namespace facet {
namespace {

struct Channel {
  const char* name;
  Imf::PixelType type;
  char* base;
  std::size_t stride;  // bytes between pixels
};

// The channel table shared by the writer and the reader.
std::vector<Channel> channels(Image& image) {
  auto f = [](auto& plane, int component) { return reinterpret_cast<char*>(plane.data()) + component * sizeof(float); };
  const std::size_t v4 = sizeof(glm::vec4), v3 = sizeof(glm::vec3), v2 = sizeof(glm::vec2);
  return {
      {"R", Imf::FLOAT, f(image.beauty, 0), v4},
      {"G", Imf::FLOAT, f(image.beauty, 1), v4},
      {"B", Imf::FLOAT, f(image.beauty, 2), v4},
      {"A", Imf::FLOAT, f(image.beauty, 3), v4},
      {"Z", Imf::FLOAT, f(image.depth, 0), sizeof(float)},
      {"P.X", Imf::FLOAT, f(image.position, 0), v3},
      {"P.Y", Imf::FLOAT, f(image.position, 1), v3},
      {"P.Z", Imf::FLOAT, f(image.position, 2), v3},
      {"Ng.X", Imf::FLOAT, f(image.geometricNormal, 0), v3},
      {"Ng.Y", Imf::FLOAT, f(image.geometricNormal, 1), v3},
      {"Ng.Z", Imf::FLOAT, f(image.geometricNormal, 2), v3},
      {"N.X", Imf::FLOAT, f(image.shadingNormal, 0), v3},
      {"N.Y", Imf::FLOAT, f(image.shadingNormal, 1), v3},
      {"N.Z", Imf::FLOAT, f(image.shadingNormal, 2), v3},
      {"patchId", Imf::UINT, reinterpret_cast<char*>(image.patchId.data()), sizeof(std::uint32_t)},
      {"faceId", Imf::UINT, reinterpret_cast<char*>(image.faceId.data()), sizeof(std::uint32_t)},
      {"uv.U", Imf::FLOAT, f(image.uv, 0), v2},
      {"uv.V", Imf::FLOAT, f(image.uv, 1), v2},
      {"st.s", Imf::FLOAT, f(image.texcoord, 0), v2},
      {"st.t", Imf::FLOAT, f(image.texcoord, 1), v2},
  };
}

// OpenEXR addresses slices by absolute pixel coordinates: the plane's first
// pixel is pixel (x0, y0) of the display window.
char* slicesOrigin(const Channel& c, int x0, int y0, int width) {
  return c.base - (std::ptrdiff_t(x0) + std::ptrdiff_t(y0) * width) * std::ptrdiff_t(c.stride);
}

}  // namespace

void checkOutputPath(const std::string& flag, const std::filesystem::path& path) {
  const auto reject = [&](const std::string& rule) { throw OutputError(flag + " '" + path.string() + "': " + rule); };
  if (path.empty()) reject("the output path is empty");
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) reject("is a folder; name a file in it");
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(folder, error)) reject("the folder '" + folder.string() + "' does not exist");
  if (::access(folder.c_str(), W_OK) != 0) reject("the folder '" + folder.string() + "' is not writable");
}

void writeAllOrNothing(const std::vector<OutputFile>& files) {
  std::random_device entropy;
  std::vector<std::filesystem::path> temporaries;
  const auto removeTemporaries = [&](std::size_t first) {
    std::error_code ignored;
    for (std::size_t i = first; i < temporaries.size(); ++i) std::filesystem::remove(temporaries[i], ignored);
  };
  try {
    for (const OutputFile& file : files) {
      temporaries.push_back(file.path);
      temporaries.back() += ".tmp-" + std::to_string(entropy());
      file.write(temporaries.back());
    }
  } catch (const OutputError&) {
    removeTemporaries(0);
    throw;
  } catch (const std::runtime_error& e) {  // a writer's own failure, as OutputError
    removeTemporaries(0);
    throw OutputError(e.what());
  } catch (...) {
    removeTemporaries(0);
    throw;
  }
  // rename(2) within one folder does not fail once the temporary is written
  // there, short of the folder itself changing under us.
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code error;
    std::filesystem::rename(temporaries[i], files[i].path, error);
    if (error) {
      removeTemporaries(i);
      throw OutputError(files[i].path.string() + ": cannot move the written file into place: " + error.message());
    }
  }
}

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write) {
  writeAllOrNothing({{path, write}});
}

OutputFile exrFile(const std::filesystem::path& path, const Image& image,
                   const std::optional<ExrPlacement>& placement) {
  return {path, [path, &image, placement](const std::filesystem::path& temporary) {
            const ExrPlacement where = placement.value_or(
                ExrPlacement{PixelRect::whole(image.width, image.height), image.width, image.height, {}});
            const PixelRect& data = where.dataWindow;
            Imf::Header header(Imath::Box2i({0, 0}, {where.displayWidth - 1, where.displayHeight - 1}),
                               Imath::Box2i({data.x0, data.y0}, {data.x1 - 1, data.y1 - 1}));
            header.compression() = Imf::ZIP_COMPRESSION;
            if (!where.digest.empty()) header.insert(kSettingsDigestAttribute, Imf::StringAttribute(where.digest));
            Imf::FrameBuffer frame;
            // The slices only read through these pointers; the table is shared with readExr.
            for (const Channel& c : channels(const_cast<Image&>(image))) {
              header.channels().insert(c.name, Imf::Channel(c.type));
              frame.insert(c.name, Imf::Slice(c.type, slicesOrigin(c, data.x0, data.y0, image.width), c.stride,
                                              c.stride * std::size_t(image.width)));
            }
            try {
              Imf::OutputFile file(temporary.c_str(), header);
              file.setFrameBuffer(frame);
              file.writePixels(image.height);
            } catch (const std::exception& e) {
              throw OutputError(path.string() + ": cannot write EXR: " + e.what());
            }
          }};
}

void writeExr(const std::filesystem::path& path, const Image& image) { writeAllOrNothing({exrFile(path, image)}); }

Image readExr(const std::filesystem::path& path) {
  try {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    Image image(window.max.x - window.min.x + 1, window.max.y - window.min.y + 1);
    Imf::FrameBuffer frame;
    for (const Channel& c : channels(image)) {
      if (!file.header().channels().findChannel(c.name)) continue;  // keep the miss default
      frame.insert(c.name, Imf::Slice(c.type, slicesOrigin(c, window.min.x, window.min.y, image.width), c.stride,
                                      c.stride * std::size_t(image.width)));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const std::exception& e) {
    throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
  }
}

void previewPixels(const glm::vec4* beauty, std::size_t count, float exposure, std::uint8_t* rgba) {
  const float scale = std::exp2(exposure);
  for (std::size_t i = 0; i < count; ++i) {
    const glm::vec4& p = beauty[i];
    for (int c = 0; c < 3; ++c) rgba[4 * i + c] = std::uint8_t(std::lround(previewToneCurve(p[c], scale) * 255.0));
    rgba[4 * i + 3] = std::uint8_t(std::lround(std::clamp(p.a, 0.0f, 1.0f) * 255.0f));
  }
}

OutputFile rgbaPngFile(const std::filesystem::path& path, int width, int height,
                       const std::vector<std::uint8_t>& rgba) {
  return {path, [path, width, height, &rgba](const std::filesystem::path& temporary) {
            if (!stbi_write_png(temporary.c_str(), width, height, 4, rgba.data(), width * 4))
              throw OutputError(path.string() + ": cannot write PNG (is the folder writable?)");
          }};
}

OutputFile pngFile(const std::filesystem::path& path, const Image& image, float exposure) {
  return {path, [path, &image, exposure](const std::filesystem::path& temporary) {
            std::vector<std::uint8_t> pixels(image.pixelCount() * 4);
            previewPixels(image.beauty.data(), image.pixelCount(), exposure, pixels.data());
            rgbaPngFile(path, image.width, image.height, pixels).write(temporary);
          }};
}

void writePng(const std::filesystem::path& path, const Image& image, float exposure) {
  writeAllOrNothing({pngFile(path, image, exposure)});
}

}  // namespace facet
