#include "analysis/gnuplot.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "engine/image/image_io.h"
#include "engine/image/output_folder.h"

extern char** environ;

namespace facet::analysis {

namespace fs = std::filesystem;

namespace {

void writeWhole(const fs::path& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + path.string() + "' (is the disk full?)");
}

// gnuplot exits 0 even when it could not finish its image (a full disk), so
// the image's own last bytes decide: PNG's IEND chunk, SVG's closing tag.
bool endsAsItMust(const fs::path& image, bool png) {
  std::ifstream file(image, std::ios::binary | std::ios::ate);
  if (!file) return false;
  const std::string tail = png ? std::string("IEND\xae\x42\x60\x82", 8) : "</svg>";
  const std::streamoff size = file.tellg();
  const std::streamoff reach = std::min<std::streamoff>(size, std::streamoff(tail.size() + 2));
  std::string end(std::size_t(reach), '\0');
  file.seekg(size - reach);
  file.read(end.data(), reach);
  return end.find(tail) != std::string::npos;
}

}  // namespace

void runGnuplot(std::string script, const std::string& data, const fs::path& out, int width, int height) {
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height);
  std::string terminal;
  if (out.extension() == ".svg")
    terminal = "svg" + size + " dynamic background rgb 'white'";
  else if (out.extension() == ".png")
    terminal = "pngcairo" + size;
  else
    throw std::invalid_argument("--out: must end in .svg or .png, got '" + out.string() + "'");
  checkOutputPath("--out", out);

  const ScratchFolder work("--out", "gnuplot's script and data", "plot");
  fs::path data_file = work.path() / "data.txt", script_file = work.path() / "plot.gp";
  fs::path partial = out;
  partial += ".partial";
  writeWhole(data_file, data);
  // The file names reach gnuplot as arguments (ARG1, ARG2 of `gnuplot -c`),
  // never as script text: a quote in a name cannot end a string and run
  // code, and no name is searched for placeholders.
  writeWhole(script_file, "DATA = ARG1\nOUTPUT = ARG2\nset terminal " + terminal + "\n" + script);

  std::string program = "gnuplot", call = "-c", script_argument = script_file.string(),
              data_argument = data_file.string(), output_argument = partial.string();
  char* argv[] = {program.data(),         call.data(), script_argument.data(), data_argument.data(),
                  output_argument.data(), nullptr};
  pid_t pid = 0;
  int spawn_error = posix_spawnp(&pid, "gnuplot", nullptr, nullptr, argv, environ);
  int status = 0;
  if (spawn_error == 0) waitpid(pid, &status, 0);
  if (spawn_error == ENOENT) throw std::runtime_error("gnuplot not found on PATH; install it (Debian: gnuplot-nox)");
  if (spawn_error != 0) throw std::runtime_error(std::string("cannot start gnuplot: ") + std::strerror(spawn_error));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !endsAsItMust(partial, out.extension() == ".png")) {
    fs::remove(partial);
    throw std::runtime_error("gnuplot failed to write '" + out.string() + "' (status " + std::to_string(status) +
                             "; a full disk?)");
  }
  fs::rename(partial, out);
}

}  // namespace facet::analysis
