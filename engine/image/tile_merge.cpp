#include "engine/image/tile_merge.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <half.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "engine/image/exr_file.h"
#include "engine/image/image_io.h"
#include "engine/image/pixel_rect.h"

namespace facet {
namespace {

// Rows merged at once: a few of OpenEXR's ZIP blocks of 16 scanlines.
constexpr int kRowsPerBand = 64;

struct Tile {
  std::filesystem::path path;
  std::unique_ptr<Imf::InputFile> file;
  PixelRect window;  // in the display window
};

PixelRect rect(const Imath::Box2i& box) { return {box.min.x, box.min.y, box.max.x + 1, box.max.y + 1}; }

std::string channelText(const Imf::ChannelList& channels) {
  std::string text;
  for (auto c = channels.begin(); c != channels.end(); ++c)
    text += std::string(text.empty() ? "" : " ") + c.name() + (c.channel().type == Imf::HALF ? ":half" : "");
  return text;
}

std::size_t pixelBytes(Imf::PixelType type) { return type == Imf::HALF ? 2 : 4; }

std::string digestOf(const Tile& tile) {
  const auto* digest = tile.file->header().findTypedAttribute<Imf::StringAttribute>(kSettingsDigestAttribute);
  if (!digest)
    throw std::invalid_argument(tile.path.string() + ": header: no " + kSettingsDigestAttribute +
                                " attribute; merge tiles written by facet render --tile or --crop");
  return digest->value();
}

// Every tile stays open while the bands stream (OpenEXR reads each from its
// own file), so the process must be allowed a file per tile, and a few for
// the outputs and the driver: the soft limit is raised up to the hard one
// when it is lower, and a merge past the hard limit is refused before any
// tile is opened, rather than blamed on whichever tile came last.
void allowOpenFiles(std::size_t tiles) {
  constexpr rlim_t kSpareFiles = 16;
  rlimit files{};
  if (getrlimit(RLIMIT_NOFILE, &files) != 0) return;
  const rlim_t needed = rlim_t(tiles) + kSpareFiles;
  if (files.rlim_cur != RLIM_INFINITY && files.rlim_cur < needed) {
    files.rlim_cur = files.rlim_max == RLIM_INFINITY ? needed : std::min(needed, files.rlim_max);
    setrlimit(RLIMIT_NOFILE, &files);
    getrlimit(RLIMIT_NOFILE, &files);
  }
  if (files.rlim_cur != RLIM_INFINITY && files.rlim_cur < needed)
    throw std::invalid_argument("merge: " + std::to_string(tiles) + " tiles are read at once and need " +
                                std::to_string(needed) + " open files; this process may open " +
                                std::to_string(files.rlim_cur) + " (ulimit -n); render fewer, larger tiles");
}

std::vector<Tile> openTiles(const std::vector<std::filesystem::path>& paths) {
  if (paths.empty()) throw std::invalid_argument("merge: no tiles given");
  allowOpenFiles(paths.size());
  std::vector<Tile> tiles;
  for (const std::filesystem::path& path : paths) {
    Tile tile{path, nullptr, {}};
    try {
      tile.file = std::make_unique<Imf::InputFile>(path.c_str());
    } catch (const std::exception& e) {
      throw std::invalid_argument(path.string() + ": cannot read EXR: " + e.what());
    }
    tile.window = rect(tile.file->header().dataWindow());
    tiles.push_back(std::move(tile));
  }
  const Tile& first = tiles.front();
  const std::string digest = digestOf(first);
  const PixelRect display = rect(first.file->header().displayWindow());
  const std::string channels = channelText(first.file->header().channels());
  for (const Tile& tile : tiles) {
    const std::string against = " differs from " + first.path.string() + "'s";
    if (digestOf(tile) != digest)
      throw std::invalid_argument(tile.path.string() + ": " + kSettingsDigestAttribute + ":" + against +
                                  ": the tiles come from different renders");
    if (!(rect(tile.file->header().displayWindow()) == display))
      throw std::invalid_argument(tile.path.string() + ": display window " +
                                  rect(tile.file->header().displayWindow()).text() + against + " " + display.text());
    if (channelText(tile.file->header().channels()) != channels)
      throw std::invalid_argument(tile.path.string() + ": channels '" + channelText(tile.file->header().channels()) +
                                  "'" + against + " '" + channels + "'");
    if (display.x0 != 0 || display.y0 != 0 || !tile.window.inside(display.x1, display.y1))
      throw std::invalid_argument(tile.path.string() + ": data window " + tile.window.text() +
                                  ": must lie inside the display window " + display.text());
  }
  return tiles;
}

// Every pixel of the display window in exactly one tile.
void checkCoverage(const std::vector<Tile>& tiles, const PixelRect& display) {
  for (std::size_t i = 0; i < tiles.size(); ++i)
    for (std::size_t j = i + 1; j < tiles.size(); ++j)
      if (tiles[i].window.overlaps(tiles[j].window))
        throw std::invalid_argument(tiles[j].path.string() + ": data window " + tiles[j].window.text() + ": overlaps " +
                                    tiles[i].path.string() + "'s " + tiles[i].window.text());
  // Without overlaps, a row is covered when its tiles' spans add up to its width.
  for (int y = display.y0; y < display.y1; ++y) {
    std::vector<std::pair<int, int>> spans;
    for (const Tile& tile : tiles)
      if (tile.window.y0 <= y && y < tile.window.y1) spans.emplace_back(tile.window.x0, tile.window.x1);
    std::sort(spans.begin(), spans.end());
    int x = display.x0;
    for (const auto& [x0, x1] : spans) {
      if (x0 > x) break;
      x = x1;
    }
    if (x < display.x1)
      throw std::invalid_argument("merge: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                  ") is in no tile: the tiles leave a gap in the display window " + display.text());
  }
}

struct Plane {
  std::string name;
  Imf::PixelType type;
  std::vector<char> rows;  // kRowsPerBand rows of the display window
};

// One frame buffer for reading the tiles and writing the output: the
// planes hold rows y0 .. y0 + kRowsPerBand of the display window.
Imf::FrameBuffer bandFrameBuffer(std::vector<Plane>& planes, int width, int y0) {
  Imf::FrameBuffer frame;
  for (Plane& p : planes) {
    const std::size_t bytes = pixelBytes(p.type);
    frame.insert(p.name, Imf::Slice(p.type, p.rows.data() - std::ptrdiff_t(y0) * width * std::ptrdiff_t(bytes), bytes,
                                    bytes * std::size_t(width)));
  }
  return frame;
}

float valueAt(const Plane& plane, std::size_t i) {
  return plane.type == Imf::HALF ? float(reinterpret_cast<const half*>(plane.rows.data())[i])
                                 : reinterpret_cast<const float*>(plane.rows.data())[i];
}

// The band's beauty rows into the preview, from its float or half R, G, B, A
// planes; with no encoder, only checks that the planes are there.
void previewBand(const std::vector<Plane>& planes, int width, int rows, PreviewEncoder* encoder) {
  const char* names[4] = {"R", "G", "B", "A"};
  const Plane* components[4] = {};
  for (int c = 0; c < 4; ++c) {
    auto plane = std::find_if(planes.begin(), planes.end(), [&](const Plane& p) { return p.name == names[c]; });
    if (plane == planes.end() || plane->type == Imf::UINT)
      throw std::invalid_argument(
          std::string("merge: --png needs float or half R, G, B and A channels; the tiles lack ") + names[c]);
    components[c] = &*plane;
  }
  if (!encoder) return;
  std::vector<glm::vec4> row(static_cast<std::size_t>(width));
  for (int y = 0; y < rows; ++y) {
    for (std::size_t x = 0, i = std::size_t(y) * std::size_t(width); x < row.size(); ++x, ++i)
      row[x] = {valueAt(*components[0], i), valueAt(*components[1], i), valueAt(*components[2], i),
                valueAt(*components[3], i)};
    encoder->push(row.data());
  }
}

// Rows `first`..`last` of `tile` into `frame`. A tile whose header is sound
// can still hold pixel data that does not decode (truncated, corrupt): that
// is the tile's fault, named as such, though only reading it finds it.
void readRows(Tile& tile, const Imf::FrameBuffer& frame, int first, int last) {
  try {
    tile.file->setFrameBuffer(frame);
    tile.file->readPixels(first, last);
  } catch (const std::exception& e) {
    throw std::invalid_argument(tile.path.string() + ": pixel data: cannot read rows " + std::to_string(first) + ".." +
                                std::to_string(last) + ": " + e.what());
  }
}

}  // namespace

void mergeTiles(const std::vector<std::filesystem::path>& paths, const MergeOutputs& outputs) {
  std::vector<Tile> tiles = openTiles(paths);
  const Imf::Header& firstHeader = tiles.front().file->header();
  const PixelRect display = rect(firstHeader.displayWindow());
  checkCoverage(tiles, display);
  const int width = display.width(), height = display.height();

  std::vector<Plane> planes;
  for (auto c = firstHeader.channels().begin(); c != firstHeader.channels().end(); ++c)
    planes.push_back({c.name(), c.channel().type,
                      std::vector<char>(pixelBytes(c.channel().type) * std::size_t(width) * kRowsPerBand)});
  const bool png = !outputs.png.empty();
  if (png) previewBand(planes, width, 0, nullptr);  // the channels it needs, checked before writing
  std::vector<std::uint8_t> preview(png ? std::size_t(width) * std::size_t(height) * 4 : 0);
  PreviewEncoder encoder(width, outputs.preview, preview.data());

  // The PNG's pixels are gathered while the EXR streams, so the EXR is the
  // first of the outputs written.
  OutputFile exr{outputs.exr, [&](const std::filesystem::path& temporary) {
                   Imf::Header header = firstHeader;
                   header.dataWindow() = header.displayWindow();
                   try {
                     Imf::OutputFile out(temporary.c_str(), header);
                     for (int y0 = 0; y0 < height; y0 += kRowsPerBand) {
                       const int y1 = std::min(height, y0 + kRowsPerBand);
                       const Imf::FrameBuffer frame = bandFrameBuffer(planes, width, y0);
                       for (Tile& tile : tiles) {
                         const int from = std::max(y0, tile.window.y0), to = std::min(y1, tile.window.y1);
                         if (from >= to) continue;
                         readRows(tile, frame, from, to - 1);
                       }
                       out.setFrameBuffer(frame);
                       out.writePixels(y1 - y0);
                       if (png) previewBand(planes, width, y1 - y0, &encoder);
                     }
                     encoder.finish();
                   } catch (const std::invalid_argument&) {
                     throw;  // a tile's fault, not the output's
                   } catch (const std::exception& e) {
                     throw OutputError(outputs.exr.string() + ": cannot merge the tiles: " + e.what());
                   }
                 }};
  std::vector<OutputFile> files{exr};
  if (png) files.push_back(rgbaPngFile(outputs.png, width, height, preview));
  writeAllOrNothing(files);
}

}  // namespace facet
