// The programs facet runs for its images (ffmpeg for movies, Blender for the
// bench's Cycles renders, gnuplot for the bench's charts) under control: each within a time limit, after
// which it is ended, and ended with facet: where SIGINT or SIGTERM reaches
// facet while one runs, facet ends it (SIGTERM, then SIGKILL), waits for
// it, and the command then ends, cleaning up as it unwinds
// (docs/reliability.md, "Programs facet runs").
#pragma once

#include <filesystem>
#include <optional>
#include <exception>
#include <string>
#include <utility>
#include <vector>

namespace facet {

struct ChildRun {
  std::vector<std::string> arguments;        // arguments[0]: the program's path
  std::optional<std::filesystem::path> log;  // its stdout and stderr; none: facet's own
  double timeLimitSeconds = 0;               // > 0; FACET_CHILD_TIME_LIMIT, where set, overrides it
};

// SIGINT or SIGTERM reached facet while a program ran: the program has
// ended; the command ends with the signal once it has cleaned up.
// Not a runtime_error, so that no handler of a program's failure takes it
// for one.
class Interrupted : public std::exception {
 public:
  Interrupted(int signal, std::string what) : signal_(signal), what_(std::move(what)) {}
  int signal() const { return signal_; }
  const char* what() const noexcept override { return what_.c_str(); }

 private:
  int signal_;
  std::string what_;
};

// The first executable `name` in the folders of `path` (PATH's syntax).
std::optional<std::filesystem::path> findOnPath(const std::string& name, const std::string& path);

// Runs the program and waits for it. Throws std::runtime_error "<program>
// exited with status N", "... was ended by signal N" or "... did not finish
// within S s, and was ended" (each with "; see <log>" where it has one),
// and Interrupted.
void runChild(const ChildRun& run);

}  // namespace facet
