#pragma once
// The one exception type for bad scene input. Every message names the source,
// the line (0 when the problem belongs to the file as a whole) and the rule
// that was broken, so a user can fix the file without reading our code.

#include <stdexcept>
#include <string>

namespace facet::scene {

class InputError : public std::runtime_error {
 public:
  InputError(std::string source, int line, std::string rule, const std::string& detail);

  const std::string& source() const { return source_; }
  int line() const { return line_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string source_;
  int line_;
  std::string rule_;
};

}  // namespace facet::scene
