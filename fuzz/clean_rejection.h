// What every harness asks of a loader's rejection: it names the input and
// the rule it broke, as the command line prints it (docs/reliability.md).
// A rejection that names neither is a finding, like a crash.
#pragma once

#include <cstdlib>

#include "scenes/input_error.h"

namespace facet::fuzz {

inline void checkCleanRejection(const scene::InputError& error) {
  if (error.source().empty() || error.rule().empty()) std::abort();
}

}  // namespace facet::fuzz
