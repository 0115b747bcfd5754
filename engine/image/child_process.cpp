#include "engine/image/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "engine/image/signal_handlers.h"

extern char** environ;

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

constexpr auto kPoll = std::chrono::milliseconds(20);
constexpr auto kGrace = std::chrono::seconds(5);  // after SIGTERM, before SIGKILL

volatile sig_atomic_t received = 0;
extern "C" void noteSignal(int signal) { received = signal; }

double timeLimit(const ChildRun& run) {
  const char* given = std::getenv("FACET_CHILD_TIME_LIMIT");
  if (!given || !*given) return run.timeLimitSeconds;
  char* end = nullptr;
  const double seconds = std::strtod(given, &end);
  if (*end != '\0' || !std::isfinite(seconds) || seconds <= 0)
    throw std::invalid_argument(std::string("FACET_CHILD_TIME_LIMIT '") + given +
                                "': expected a number of seconds > 0");
  return seconds;
}

pid_t start(const ChildRun& run) {
  std::vector<char*> pointers;
  for (const std::string& a : run.arguments) pointers.push_back(const_cast<char*>(a.c_str()));
  pointers.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (run.log) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, run.log->c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  }
  pid_t pid = 0;
  const int error = posix_spawn(&pid, pointers[0], &actions, nullptr, pointers.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("cannot start " + run.arguments[0] + ": " + std::strerror(error));
  return pid;
}

// Whether it ended within `wait`, its status in `status`.
bool endedWithin(pid_t pid, Clock::duration wait, int& status) {
  const Clock::time_point until = Clock::now() + wait;
  while (true) {
    const pid_t ended = waitpid(pid, &status, WNOHANG);
    if (ended == pid || (ended < 0 && errno != EINTR)) return true;
    if (Clock::now() >= until) return false;
    std::this_thread::sleep_for(kPoll);
  }
}

// SIGTERM, then SIGKILL where it has not ended after the grace period.
void end(pid_t pid) {
  int status = 0;
  kill(pid, SIGTERM);
  if (endedWithin(pid, kGrace, status)) return;
  kill(pid, SIGKILL);
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
}

}  // namespace

std::optional<std::filesystem::path> findOnPath(const std::string& name, const std::string& path) {
  std::istringstream folders(path);
  for (std::string folder; std::getline(folders, folder, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / name;
    if (std::filesystem::is_regular_file(candidate) && access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

void runChild(const ChildRun& run) {
  const double limit = timeLimit(run);
  const std::string program = run.arguments.at(0);
  const std::string see = run.log ? "; see " + run.log->string() : std::string();
  received = 0;
  const SignalHandlers noted({SIGINT, SIGTERM}, noteSignal);  // passed on to the program
  const pid_t pid = start(run);
  const Clock::time_point deadline =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limit));
  int status = 0;
  const auto interrupted = [&] {
    const int signal = received;
    return Interrupted(signal, std::string(strsignal(signal)) + " while " + program + " ran: it was ended");
  };
  while (!endedWithin(pid, kPoll, status)) {
    if (received != 0) {
      end(pid);
      throw interrupted();
    }
    if (Clock::now() >= deadline) {
      end(pid);
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", limit);
      throw std::runtime_error(program + " did not finish within " + seconds + " s, and was ended" + see);
    }
  }
  // A Ctrl-C reaches the program too, which may end on it first.
  if (received != 0) throw interrupted();
  if (WIFSIGNALED(status))
    throw std::runtime_error(program + " was ended by signal " + std::to_string(WTERMSIG(status)) + see);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(program + " exited with status " + std::to_string(WEXITSTATUS(status)) + see);
}

}  // namespace facet
