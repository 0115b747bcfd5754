// The one exception facet's API throws: facet's message, and the kind of
// failure, which is also the exit code the `facet` command gives it
// (docs/reliability.md#exit-codes).
#pragma once

#include <stdexcept>
#include <string>

namespace facet {
namespace v0 {

enum class ErrorKind : int {
  BadInput = 1,      // a file, a field or an argument breaks a rule
  OutputFailed = 2,  // an output path cannot be written
  GpuFailed = 3,     // no Vulkan driver, no matching adapter, or a device error
  Internal = 4,      // anything else: a bug, or out of memory
};

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }
  int exitCode() const { return static_cast<int>(kind_); }

 private:
  ErrorKind kind_;
};

}  // namespace v0
#ifndef FACET_IMPLEMENTATION  // inside libfacet, facet:: is also the engine's
using namespace v0;
#endif
}  // namespace facet
