// SignalsHeld holds a signal back for the whole process: one that another
// thread receives while it lives (a driver's worker, whose signal mask the
// holder does not set) is raised again when it ends, not handled at once.
#include <gtest/gtest.h>
#include <signal.h>

#include <thread>

#include "engine/image/image_io.h"

namespace facet {
namespace {

volatile sig_atomic_t terminations = 0;
extern "C" void countTermination(int) { terminations = terminations + 1; }

TEST(SignalsHeld, ASignalAnotherThreadReceivesWaitsForTheHolderToEnd) {
  struct sigaction counting {
  }, before{};
  counting.sa_handler = countTermination;
  sigemptyset(&counting.sa_mask);
  ASSERT_EQ(sigaction(SIGTERM, &counting, &before), 0);
  terminations = 0;
  {
    const SignalsHeld held;
    std::thread([] { raise(SIGTERM); }).join();
    EXPECT_EQ(terminations, 0) << "handled while the outputs were being put in place";
    {
      const SignalsHeld nested;  // a second holder keeps it held until the outer ends
    }
    EXPECT_EQ(terminations, 0);
  }
  EXPECT_EQ(terminations, 1) << "raised again once the holder ended";
  { const SignalsHeld nothingHappened; }
  EXPECT_EQ(terminations, 1) << "nothing held, nothing raised";
  sigaction(SIGTERM, &before, nullptr);
}

}  // namespace
}  // namespace facet
