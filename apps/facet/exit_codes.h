// facet's exit codes, one per kind of failure (the table in
// docs/reliability.md#exit-codes), and the error a check that fails throws.
#pragma once

#include <stdexcept>

namespace facet::cli {

enum ExitCode : int {
  kSuccess = 0,
  kBadInput = 1,       // the command line or an input file breaks a rule
  kOutputFailed = 2,   // an output path cannot be written
  kGpuFailed = 3,      // no Vulkan driver, no matching adapter, or a device error
  kInternal = 4,       // anything else: a bug, or the machine ran out of memory
  kCheckFailed = 5,    // the command ran and its verdict is negative (parity out of tolerance)
  kNotComparable = 6,  // compare: the renders estimate different pictures, so there is no verdict
};

class CheckFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace facet::cli
