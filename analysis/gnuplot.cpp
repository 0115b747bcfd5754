#include "analysis/gnuplot.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>

extern char** environ;

namespace facet::analysis {

namespace fs = std::filesystem;

void runGnuplot(std::string script, const std::string& data, const fs::path& out, int width, int height) {
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height);
  std::string terminal;
  if (out.extension() == ".svg")
    terminal = "svg" + size + " dynamic background rgb 'white'";
  else if (out.extension() == ".png")
    terminal = "pngcairo" + size;
  else
    throw std::invalid_argument("--out: must end in .svg or .png, got '" + out.string() + "'");

  fs::path work = fs::temp_directory_path() / ("facet-plot-" + std::to_string(getpid()));
  fs::create_directories(work);
  fs::path data_file = work / "data.txt", script_file = work / "plot.gp";
  fs::path partial = out;
  partial += ".partial";
  std::ofstream(data_file) << data;
  auto quote = [](const fs::path& p) { return std::string(1, '\'').append(p.string()).append(1, '\''); };
  for (auto [placeholder, value] :
       {std::pair{std::string("DATA"), quote(data_file)}, std::pair{std::string("OUTPUT"), quote(partial)}})
    for (size_t at; (at = script.find(placeholder)) != std::string::npos;)
      script.replace(at, placeholder.size(), value);
  std::ofstream(script_file) << "set terminal " << terminal << "\n" << script;

  std::string program = "gnuplot", argument = script_file.string();
  char* argv[] = {program.data(), argument.data(), nullptr};
  pid_t pid = 0;
  int spawn_error = posix_spawnp(&pid, "gnuplot", nullptr, nullptr, argv, environ);
  int status = 0;
  if (spawn_error == 0) waitpid(pid, &status, 0);
  fs::remove_all(work);
  if (spawn_error == ENOENT) throw std::runtime_error("gnuplot not found on PATH; install it (Debian: gnuplot-nox)");
  if (spawn_error != 0) throw std::runtime_error(std::string("cannot start gnuplot: ") + std::strerror(spawn_error));
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !fs::exists(partial)) {
    fs::remove(partial);
    throw std::runtime_error("gnuplot failed (status " + std::to_string(status) + ")");
  }
  fs::rename(partial, out);
}

}  // namespace facet::analysis
