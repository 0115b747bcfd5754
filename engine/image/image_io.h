// Writing and reading images. Every writer goes through a temporary file in
// the destination's folder and renames it into place, so a failure never
// leaves a partial file behind; a set of outputs is renamed into place only
// once every one of them is written (docs/reliability.md#outputs). The EXR
// writer is exr_file.h.
#pragma once

#include <signal.h>

#include <filesystem>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/image/image.h"
#include "engine/image/preview.h"

namespace facet {

// An output that could not be written, or a path no output can be written to.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file to write: its destination, and how to write it to a given path.
struct OutputFile {
  std::filesystem::path path;
  std::function<void(const std::filesystem::path&)> write;
};

// Throws OutputError "<flag> '<path>': <rule>" unless `path` names a file
// that can be created or replaced: not empty, not a folder, not a symbolic
// link, a device, a FIFO or a socket (an output replaces a regular file or
// nothing), in an existing writable folder, with a name short enough to be
// written under a temporary name first. Checked before the work that
// produces the file.
void checkOutputPath(const std::string& flag, const std::filesystem::path& path);

// The extension chooses an output's format: throws OutputError unless
// `path` ends in `extension` (".exr", ".png"; any case).
void checkOutputExtension(const std::string& flag, const std::filesystem::path& path, const std::string& extension);

// Whether two paths name one file: the same file where both exist (links
// and other spellings included), else the same normalized absolute path.
bool namesSameFile(const std::filesystem::path& a, const std::filesystem::path& b);

// Throws OutputError "<flag> '<path>': names '<input>', which this command
// reads: an output never replaces an input" when `path` names one of
// `inputs` (namesSameFile: links and other spellings included). Checked
// once the inputs are known, before the work that produces the output.
void checkNotAnInput(const std::string& flag, const std::filesystem::path& path,
                     const std::vector<std::filesystem::path>& inputs);

// Writes every file to a temporary in its destination's folder, then renames
// them all into place with SIGINT, SIGTERM and SIGHUP held back. When a write
// fails, removes the temporaries and leaves every existing destination
// untouched; temporaries a killed run left of the same destinations are
// removed first.
void writeAllOrNothing(const std::vector<OutputFile>& files);

// Holds SIGINT, SIGTERM and SIGHUP back while it lives, so that the renames
// that put a set of outputs in place are not cut short: an interrupted
// command ends with the old set or the new one. It holds them for the whole
// process, whichever thread the kernel hands a signal to (a driver's worker
// threads included): while one lives, a handler of its own notes the signal,
// and when the last ends the previous handling comes back and the signal is
// raised again.
class SignalsHeld {
 public:
  SignalsHeld();
  ~SignalsHeld();
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;
};

// Removes what ended processes left in `folder`: the entries named
// `<prefix><pid>` or `<prefix><pid>-...` whose process no longer runs.
void removeLeftoversOfEndedProcesses(const std::filesystem::path& folder, const std::string& prefix);

// Writes `bytes` to `file`; a failure is an OutputError naming
// `destination` and the system's reason ("No space left on device").
void writeBytes(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes,
                const std::filesystem::path& destination);

// Calls write(temporaryPath), then renames the temporary onto `path`.
void writeAtomically(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);

// A PNG of 8-bit RGBA pixels, row 0 at the top, tagged sRGB
// (png_chunks.h); `rgba` must outlive the write.
OutputFile rgbaPngFile(const std::filesystem::path& path, int width, int height, const std::vector<std::uint8_t>& rgba);

// The preview of the beauty (engine/image/preview.h).
OutputFile pngFile(const std::filesystem::path& path, const Image& image, const PreviewOptions& options = {});

// Charts and heatmaps: the beauty exposed, clipped to [0, 1] without a tone
// curve, and opaque.
void writePng(const std::filesystem::path& path, const Image& image, float exposure = 0.0f);

}  // namespace facet
