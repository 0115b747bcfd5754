// Internal: how errors name an object — "buffer 'positions'" or "buffer (unlabelled)".
#pragma once

#include <string>

namespace facet::gpu::detail {

inline std::string describe(const char* kind, const std::string& label) {
  return std::string(kind) + (label.empty() ? std::string(" (unlabelled)") : " '" + label + "'");
}

}  // namespace facet::gpu::detail
