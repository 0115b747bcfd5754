// Every engine exception that reaches the API becomes one facet::Error, with
// the kind the `facet` command maps it to (apps/facet/main.cpp).
#pragma once

#include <string>
#include <utility>

#include "facet/error.h"

namespace facet::api {

[[noreturn]] void rethrowAsError();

// A value that breaks its rule: an InputError "<source>: <field>: <rule>",
// `source` naming what holds the value ("scene", "preview settings").
[[noreturn]] void refuse(const std::string& source, const std::string& field, const std::string& rule);

template <class F>
auto translateErrors(F&& work) {
  try {
    return std::forward<F>(work)();
  } catch (...) {
    rethrowAsError();
  }
}

}  // namespace facet::api
