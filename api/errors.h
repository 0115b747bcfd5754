// Every engine exception that reaches the API becomes one facet::Error, with
// the kind the `facet` command maps it to (apps/facet/main.cpp).
#pragma once

#include <utility>

#include "facet/error.h"

namespace facet::api {

[[noreturn]] void rethrowAsError();

template <class F>
auto translateErrors(F&& work) {
  try {
    return std::forward<F>(work)();
  } catch (...) {
    rethrowAsError();
  }
}

}  // namespace facet::api
