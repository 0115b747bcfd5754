#include "farm_options.h"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <stdexcept>

#include "engine/camera/camera_path.h"
#include "scenes/camera_rules.h"

namespace facet::cli {

void addFarmOptions(CLI::App& command, FarmOptions& o) {
  auto* crop = command.add_option("--crop", o.crop,
                                  "Render only pixels x0 <= x < x1, y0 <= y < y1: an EXR whose data window is the crop "
                                  "inside the full image");
  command.add_option("--tile", o.tile, "Render tile I of N (0-based), a band of rows: --tile 2/8")->excludes(crop);
  auto* frames = command.add_option_function<std::string>(
      "--frames",
      [&o](const std::string& range) {
        o.frames = range;
        o.framesGiven = true;
      },
      "Render frames A to B (every STEP): A-B or A-B:STEP; '#' in -o and "
      "--png stands for the frame number, zero-padded");
  auto* frame =
      command.add_option("--frame", o.frame, "Render frame N alone")->excludes(frames)->check(CLI::NonNegativeNumber);
  auto* turntable = command
                        .add_option("--turntable", o.turntable,
                                    "Turn the model (see --turn) about the vertical through the camera's target: "
                                    "frame f of N at 2 pi f / N")
                        ->check(CLI::Range(1, 1000000));
  command
      .add_option_function<std::string>(
          "--seeds",
          [&o](const std::string& range) {
            o.seeds = range;
            o.seedsGiven = true;
          },
          "Render the still once per seed A to B (A-B), in one process: a golden set for facet compare; '#' in -o "
          "and --png stands for the seed, zero-padded")
      ->excludes(frames)
      ->excludes(frame)
      ->excludes(turntable);
  addTurnOption(command, o.turn)->needs(command.get_option("--turntable"));
  command
      .add_option("--threads", o.threads,
                  "CPU backend's threads, lavapipe's workers (default: "
                  "SLURM_CPUS_PER_TASK, else every core)")
      ->check(CLI::Range(1u, 4096u));
  command.add_flag("--quiet", o.quiet, "No progress and no summary; errors and --json only");
  command.add_flag("--json", o.json, "Print the summary as one JSON object (README.md, \"Rendering on a farm\")");
}

namespace {

// The whole numbers of `text`, separated by `separators` in that order:
// "-:" reads A-B:C, or A-B where the text ends early; none unless every
// character is read.
std::optional<std::vector<int>> wholeNumbers(const std::string& text, const std::string& separators) {
  std::vector<int> values;
  const char* p = text.c_str();
  for (std::size_t i = 0;; ++i) {
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(p, &end, 10);
    if (end == p || errno != 0 || value < INT_MIN || value > INT_MAX) return std::nullopt;
    values.push_back(int(value));
    p = end;
    if (*p == 0) return values;
    if (i >= separators.size() || *p != separators[i]) return std::nullopt;
    ++p;
  }
}

}  // namespace

std::optional<PixelRect> chosenCrop(const FarmOptions& o, int width, int height) {
  const std::string image = std::to_string(width) + "x" + std::to_string(height);
  if (!o.crop.empty()) {
    const auto v = wholeNumbers(o.crop, ",,,");
    const PixelRect crop = v && v->size() == 4 ? PixelRect{(*v)[0], (*v)[1], (*v)[2], (*v)[3]} : PixelRect{};
    if (crop.empty() || !crop.inside(width, height))
      throw std::invalid_argument("--crop '" + o.crop + "': expected x0,y0,x1,y1 with 0 <= x0 < x1 <= width and " +
                                  "0 <= y0 < y1 <= height of the " + image + " image");
    return crop;
  }
  if (!o.tile.empty()) {
    const auto v = wholeNumbers(o.tile, "/");
    if (!v || v->size() != 2 || (*v)[1] < 1 || (*v)[0] < 0 || (*v)[0] >= (*v)[1] || (*v)[1] > height)
      throw std::invalid_argument("--tile '" + o.tile + "': expected I/N with 0 <= I < N <= " + std::to_string(height) +
                                  " (the image's rows)");
    return tileRows(width, height, (*v)[0], (*v)[1]);
  }
  return std::nullopt;
}

std::vector<int> chosenFrames(const FarmOptions& o) {
  if (o.frame) return {*o.frame};
  if (o.framesGiven && o.frames.empty())
    throw std::invalid_argument("--frames '': expected A-B or A-B:STEP with 0 <= A <= B, STEP >= 1");
  if (o.frames.empty()) {
    if (!o.turntable) return {};
    std::vector<int> all;
    for (int f = 0; f < *o.turntable; ++f) all.push_back(f);
    return all;
  }
  std::optional<std::vector<int>> v = wholeNumbers(o.frames, "-:");
  if (v && v->size() == 2) v->push_back(1);
  if (!v || v->size() != 3 || (*v)[0] < 0 || (*v)[1] < (*v)[0] || (*v)[2] < 1)
    throw std::invalid_argument("--frames '" + o.frames + "': expected A-B or A-B:STEP with 0 <= A <= B, STEP >= 1");
  const long long count = ((long long)(*v)[1] - (*v)[0]) / (*v)[2] + 1;
  if (count > kMostFrames)
    throw std::invalid_argument("--frames '" + o.frames + "': " + std::to_string(count) + " frames, more than " +
                                std::to_string(kMostFrames) + " in one command; split the range across array tasks");
  std::vector<int> frames;
  for (long long f = (*v)[0]; f <= (*v)[1]; f += (*v)[2]) frames.push_back(int(f));
  return frames;
}

std::vector<std::uint32_t> chosenSeeds(const FarmOptions& o) {
  if (!o.seedsGiven) return {};
  const std::optional<std::vector<int>> v = wholeNumbers(o.seeds, "-");
  if (!v || v->size() != 2 || (*v)[0] < 0 || (*v)[1] < (*v)[0])
    throw std::invalid_argument("--seeds '" + o.seeds + "': expected A-B with 0 <= A <= B <= 2147483647");
  if ((long long)(*v)[1] - (*v)[0] + 1 > kMostSeeds)
    throw std::invalid_argument("--seeds '" + o.seeds + "': more than " + std::to_string(kMostSeeds) +
                                " seeds in one command");
  std::vector<std::uint32_t> seeds;
  for (long long s = (*v)[0]; s <= (*v)[1]; ++s) seeds.push_back(std::uint32_t(s));
  return seeds;
}

scene::Camera frameCamera(const scene::Camera& still, const std::vector<scene::CameraKey>& keys, int frame) {
  scene::Camera camera = keys.empty() ? still : camera::keyedCamera(keys, frame);
  // Each key is a valid camera, but the line between two may pass through
  // one that is not (the eye through the target, up through zero).
  if (const char* problem = scene::cameraProblem(camera))
    throw std::invalid_argument("frame " + std::to_string(frame) + ": the camera keys interpolate to a camera that " +
                                "cannot render (" + problem + "); add a key in between");
  return camera;
}

scene::Scene frameScene(const scene::Scene& still, const FarmOptions& o, int frame) {
  scene::Scene scene = still;
  scene.camera = frameCamera(still.camera, still.cameraKeys, frame);
  if (!o.turntable) return scene;
  return scene::turntableFrame(scene, frame, *o.turntable, chosenTurn(o.turn));
}

CLI::Option* addTurnOption(CLI::App& command, std::string& turn) {
  return command
      .add_option("--turn", turn,
                  "What --turntable turns before the fixed camera: the model (lights and environment fixed) or the "
                  "environment (default: model)")
      ->check(CLI::IsMember({"model", "environment"}));
}

scene::TurntableTurn chosenTurn(const std::string& turn) {
  return turn == "environment" ? scene::TurntableTurn::Environment : scene::TurntableTurn::Model;
}

std::string framePath(const std::string& flag, const std::string& pattern, int frame, const std::string& what) {
  const std::size_t first = pattern.find('#');
  if (first == std::string::npos)
    throw std::invalid_argument(flag + " '" + pattern + "': a " + what + " range needs '#' in the name for the " +
                                what + " number, e.g. " + what + "_####.exr");
  const std::size_t last = pattern.find_first_not_of('#', first);
  const std::size_t digits = (last == std::string::npos ? pattern.size() : last) - first;
  std::string number = std::to_string(frame);
  if (number.size() < digits) number.insert(0, digits - number.size(), '0');
  return pattern.substr(0, first) + number + pattern.substr(first + digits);
}

unsigned chosenThreads(const FarmOptions& o) {
  if (o.threads) return *o.threads;
  const char* slot = std::getenv("SLURM_CPUS_PER_TASK");
  if (!slot || !*slot) return 0;
  char* end = nullptr;
  const unsigned long cpus = std::strtoul(slot, &end, 10);
  if (*end != 0 || cpus < 1 || cpus > 4096)
    throw std::invalid_argument(std::string("SLURM_CPUS_PER_TASK '") + slot + "': expected a whole number in 1..4096");
  return unsigned(cpus);
}

void limitLavapipeThreads(unsigned threads) {
  if (threads > 0) setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), /*overwrite=*/0);
}

}  // namespace facet::cli
