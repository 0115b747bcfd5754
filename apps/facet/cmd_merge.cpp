// facet merge: tiles of one render (facet render --tile / --crop) into the
// whole image.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "engine/image/image_io.h"
#include "engine/image/tile_merge.h"
#include "preview_options.h"
#include "scenes/exr_header.h"

namespace facet::cli {
namespace {

struct MergeOptions {
  std::vector<std::string> tiles;
  std::string exr;
  std::string png;
  PreviewFlags preview;
  bool quiet = false;
};

void runMerge(const MergeOptions& o) {
  const PreviewOptions preview = chosenPreview(o.preview);
  checkOutputPath("-o", o.exr);
  checkOutputExtension("-o", o.exr, ".exr");
  if (!o.png.empty()) {
    checkOutputPath("--png", o.png);
    checkOutputExtension("--png", o.png, ".png");
  }
  const std::vector<std::filesystem::path> tiles(o.tiles.begin(), o.tiles.end());
  checkNotAnInput("-o", o.exr, tiles);
  if (!o.png.empty()) checkNotAnInput("--png", o.png, tiles);
  for (const std::string& tile : o.tiles) scene::checkTileFile(tile);
  mergeTiles({o.tiles.begin(), o.tiles.end()}, {o.exr, o.png, preview});
  if (!o.quiet)
    std::printf("merged %zu tiles into %s%s%s\n", o.tiles.size(), o.exr.c_str(), o.png.empty() ? "" : " and ",
                o.png.c_str());
}

}  // namespace

void addMergeCommand(CLI::App& app) {
  auto o = std::make_shared<MergeOptions>();
  auto* c = app.add_subcommand("merge", "Merge the tiles of one render into the whole image");
  c->add_option("tiles", o->tiles, "Tile EXRs (facet render --tile or --crop), covering the image once")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("-o,--output", o->exr, "The whole image's EXR")->required();
  c->add_option("--png", o->png, "Also write an 8-bit sRGB preview");
  addPreviewOptions(*c, o->preview);
  c->add_flag("--quiet", o->quiet, "Print nothing but errors");
  c->callback([o] { runMerge(*o); });
}

}  // namespace facet::cli
