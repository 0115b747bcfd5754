#include "scenes/input_error.h"

#include <utility>

namespace facet::scene {

namespace {

// "file:line: rule: detail", or "file: rule: detail" when no line applies.
std::string message(const std::string& source, int line, const std::string& rule, const std::string& detail) {
  std::string text = source;
  if (line > 0) text += ':' + std::to_string(line);
  text += ": ";
  text += rule;
  text += ": ";
  text += detail;
  return text;
}

}  // namespace

InputError::InputError(std::string source, int line, std::string rule, const std::string& detail)
    : std::runtime_error(message(source, line, rule, detail)),
      source_(std::move(source)),
      line_(line),
      rule_(std::move(rule)) {}

}  // namespace facet::scene
