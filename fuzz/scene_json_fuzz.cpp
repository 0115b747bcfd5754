// facet's JSON scenes. The input is written into a copy of the layout of
// scenes/ (its cages, environments and examples linked in), so that the
// meshes and maps a seed names resolve and the fuzzer reaches past them. A
// scene that loads has its camera keys interpolated around and between
// every key, and each camera judged by the camera rule.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "fuzz/clean_rejection.h"
#include "fuzz/scratch_file.h"
#include "engine/camera/camera_path.h"
#include "scenes/camera_rules.h"
#include "scenes/scene_file.h"

namespace {

namespace fs = std::filesystem;

const fs::path& sceneName() {
  static const fs::path name = [] {
    const fs::path scenes = FACET_SCENES_DIR;
    const fs::path& scratch = facet::fuzz::scratchFolder();
    fs::create_directory_symlink(scenes / "cages", scratch / "cages");
    fs::create_directory_symlink(scenes / "environments", scratch / "environments");
    fs::create_directory(scratch / "examples");
    for (const fs::directory_entry& entry : fs::directory_iterator(scenes / "examples"))
      fs::create_symlink(entry.path(), scratch / "examples" / entry.path().filename());
    return fs::path("examples") / "fuzz_input.json";
  }();
  return name;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const facet::scene::Scene scene = facet::scene::loadScene(facet::fuzz::writeScratchFile(sceneName(), data, size));
    const std::vector<facet::scene::CameraKey>& keys = scene.cameraKeys;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const double frame = keys[i].frame;
      const double next = i + 1 < keys.size() ? keys[i + 1].frame : frame + 1;
      for (const double f : {frame - 1, frame, 0.5 * (frame + next)})
        facet::scene::cameraProblem(facet::camera::keyedCamera(keys, f));
    }
  } catch (const facet::scene::InputError& error) {
    facet::fuzz::checkCleanRejection(error);
  }
  return 0;
}
