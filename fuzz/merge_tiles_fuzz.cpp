// Tiles for `facet merge` (engine/image/tile_merge.h): any bytes, as the one
// tile of a render, are checked as the command checks them
// (scenes/exr_header.h) and merged into a scratch EXR and PNG. They are
// refused with the file and the rule named, or merged: never a crash, never
// an allocation the header alone asks for.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "engine/image/tile_merge.h"
#include "fuzz/clean_rejection.h"
#include "fuzz/scratch_file.h"
#include "scenes/exr_header.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path tile = facet::fuzz::writeScratchFile("tile.exr", data, size);
  const std::filesystem::path& folder = facet::fuzz::scratchFolder();
  try {
    facet::scene::checkTileFile(tile);
    facet::mergeTiles({tile}, {folder / "merged.exr", folder / "merged.png", {}});
  } catch (const facet::scene::InputError& error) {
    facet::fuzz::checkCleanRejection(error);
  } catch (const std::invalid_argument& error) {
    // mergeTiles' rules name the tile, or the merge for a gap between tiles.
    const std::string message = error.what();
    if (message.rfind(tile.string() + ": ", 0) != 0 && message.rfind("merge: ", 0) != 0) std::abort();
  }
  return 0;
}
