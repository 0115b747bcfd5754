#include "analysis/gnuplot.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <stdexcept>

#include "engine/image/child_process.h"
#include "engine/image/image_io.h"
#include "engine/image/output_folder.h"

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

  const char* path = std::getenv("PATH");
  const std::optional<fs::path> gnuplot = findOnPath("gnuplot", path ? path : "");
  if (!gnuplot) throw std::runtime_error("gnuplot not found on PATH; install it (Debian: gnuplot-nox)");
  try {
    runChild({{gnuplot->string(), "-c", script_file.string(), data_file.string(), partial.string()},
              std::nullopt,
              kGnuplotTimeLimit});
  } catch (const std::runtime_error& e) {
    fs::remove(partial);
    throw std::runtime_error("'" + out.string() + "': " + e.what());
  } catch (...) {
    fs::remove(partial);
    throw;
  }
  if (!endsAsItMust(partial, out.extension() == ".png")) {
    fs::remove(partial);
    throw std::runtime_error("gnuplot failed to write '" + out.string() + "' (a full disk?)");
  }
  fs::rename(partial, out);
}

}  // namespace facet::analysis
