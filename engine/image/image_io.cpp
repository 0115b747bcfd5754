#include "engine/image/image_io.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <optional>
#include <random>
#include <stdexcept>
#include <system_error>

#include "engine/image/png_chunks.h"
#include "engine/image/signal_handlers.h"
#include "engine/image/stb_image_write_hidden.h"

namespace facet {

namespace {

// A temporary is named after its destination and its writer's process:
// "<name>.tmp-<pid>-<random>", at most this many bytes longer.
constexpr std::size_t kTemporarySuffix = 5 + 10 + 1 + 10;

}  // namespace

void checkOutputPath(const std::string& flag, const std::filesystem::path& path) {
  const auto reject = [&](const std::string& rule) { throw OutputError(flag + " '" + path.string() + "': " + rule); };
  if (path.empty()) reject("the output path is empty");
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) reject("is a folder; name a file in it");
  const std::filesystem::file_status status = std::filesystem::symlink_status(path, error);
  if (std::filesystem::is_symlink(status)) reject("is a symbolic link; facet writes only regular files");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    reject("is a device, FIFO or socket; facet replaces only regular files");
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(folder, error)) reject("the folder '" + folder.string() + "' does not exist");
  if (::access(folder.c_str(), W_OK) != 0) reject("the folder '" + folder.string() + "' is not writable");
  const std::size_t longest = std::size_t(NAME_MAX) - kTemporarySuffix;
  if (path.filename().string().size() > longest)
    reject("the file name is " + std::to_string(path.filename().string().size()) + " bytes, more than " +
           std::to_string(longest) + " (the system's " + std::to_string(NAME_MAX) +
           " less the temporary name's suffix facet writes it under first)");
}

void checkOutputExtension(const std::string& flag, const std::filesystem::path& path, const std::string& extension) {
  std::string found = path.extension().string();
  for (char& c : found) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (found != extension)
    throw OutputError(flag + " '" + path.string() + "': the extension chooses the format: expected " + extension);
}

bool namesSameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code error;
  if (std::filesystem::exists(a, error) && std::filesystem::exists(b, error))
    return std::filesystem::equivalent(a, b, error);
  return std::filesystem::absolute(a).lexically_normal() == std::filesystem::absolute(b).lexically_normal();
}

void checkNotAnInput(const std::string& flag, const std::filesystem::path& path,
                     const std::vector<std::filesystem::path>& inputs) {
  for (const std::filesystem::path& input : inputs)
    if (namesSameFile(path, input))
      throw OutputError(flag + " '" + path.string() + "': names '" + input.string() +
                        "', which this command reads: an output never replaces an input");
}

void removeLeftoversOfEndedProcesses(const std::filesystem::path& folder, const std::string& prefix) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    char* end = nullptr;
    const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
    if ((*end != '\0' && *end != '-') || pid <= 0) continue;
    if (::kill(pid_t(pid), 0) != 0 && errno == ESRCH) std::filesystem::remove_all(entry.path(), error);
  }
}

namespace {

std::string temporaryPrefix(const std::filesystem::path& destination) {
  return destination.filename().string() + ".tmp-";
}

// Temporaries of `destination` whose writer no longer runs (it was killed
// between writing and renaming): removed, so a killed run leaves nothing
// behind once the next one starts.
void removeOrphanedTemporaries(const std::filesystem::path& destination) {
  removeLeftoversOfEndedProcesses(destination.has_parent_path() ? destination.parent_path() : ".",
                                  temporaryPrefix(destination));
}

}  // namespace

namespace {

constexpr int kHeldSignals[] = {SIGINT, SIGTERM, SIGHUP};
std::mutex heldMutex;
int heldCount = 0;  // SignalsHeld alive
std::optional<SignalHandlers> holding;
volatile sig_atomic_t held[std::size(kHeldSignals)] = {};  // each signal held back, to raise again

extern "C" void holdSignal(int signal) {
  for (std::size_t i = 0; i < std::size(kHeldSignals); ++i)
    if (kHeldSignals[i] == signal) held[i] = 1;
}

}  // namespace

SignalsHeld::SignalsHeld() {
  const std::scoped_lock lock(heldMutex);
  if (heldCount++ > 0) return;
  for (volatile sig_atomic_t& signal : held) signal = 0;
  holding.emplace(std::initializer_list<int>{SIGINT, SIGTERM, SIGHUP}, holdSignal);
}

SignalsHeld::~SignalsHeld() {
  const std::scoped_lock lock(heldMutex);
  if (--heldCount > 0) return;
  holding.reset();
  for (std::size_t i = 0; i < std::size(kHeldSignals); ++i)
    if (held[i] != 0) raise(kHeldSignals[i]);
}

void writeAllOrNothing(const std::vector<OutputFile>& files) {
  std::random_device entropy;
  std::vector<std::filesystem::path> temporaries;
  for (const OutputFile& file : files) removeOrphanedTemporaries(file.path);
  const auto removeTemporaries = [&](std::size_t first) {
    std::error_code ignored;
    for (std::size_t i = first; i < temporaries.size(); ++i) std::filesystem::remove(temporaries[i], ignored);
  };
  try {
    for (const OutputFile& file : files) {
      temporaries.push_back(file.path.parent_path() / (temporaryPrefix(file.path) + std::to_string(::getpid()) + "-" +
                                                       std::to_string(entropy())));
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
  const SignalsHeld held;
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

void writeBytes(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes,
                const std::filesystem::path& destination) {
  const auto fail = [&](int error) {
    throw OutputError(destination.string() + ": cannot write: " + std::strerror(error));
  };
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) fail(errno);
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t wrote = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) {
      const int error = wrote < 0 ? errno : ENOSPC;
      ::close(fd);
      fail(error);
    }
    done += std::size_t(wrote);
  }
  if (::close(fd) != 0) fail(errno);
}

OutputFile rgbaPngFile(const std::filesystem::path& path, int width, int height,
                       const std::vector<std::uint8_t>& rgba) {
  return {path, [path, width, height, &rgba](const std::filesystem::path& temporary) {
            std::vector<std::uint8_t> png;
            const auto append = [](void* context, void* data, int size) {
              auto& bytes = *static_cast<std::vector<std::uint8_t>*>(context);
              bytes.insert(bytes.end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
            };
            if (!stbi_write_png_to_func(append, &png, width, height, 4, rgba.data(), width * 4))
              throw OutputError(path.string() + ": cannot encode the PNG");
            const std::vector<std::uint8_t> tagged = withSrgbChunks(png.data(), png.size());
            writeBytes(temporary, tagged, path);
          }};
}

OutputFile pngFile(const std::filesystem::path& path, const Image& image, const PreviewOptions& options) {
  return {path, [path, &image, options](const std::filesystem::path& temporary) {
            const std::vector<std::uint8_t> pixels = previewPixels(image.beauty, image.width, image.height, options);
            rgbaPngFile(path, image.width, image.height, pixels).write(temporary);
          }};
}

void writePng(const std::filesystem::path& path, const Image& image, float exposure) {
  writeAllOrNothing({pngFile(path, image, {exposure, ToneCurve::Clamp})});
}

}  // namespace facet
