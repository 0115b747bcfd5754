// The float-vs-double sweep: every D x G x F combination evaluated by the
// float and the double instantiation of the shared shading source on the same
// (float-representable) inputs, over a dense grid reaching past the course's
// domain: alpha in [0, 1] with 0, n.l and n.v in [-1, 1], l = v, l = -v,
// grazing angles. Published in docs/shading.md.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <string>
#include <vector>

namespace facet::materials {

struct PrecisionCell {
  double max_relative_error = 0;
  long evaluations = 0;
  std::string worst_case;  // the inputs at which max_relative_error occurred
};

struct PrecisionReport {
  long evaluations = 0;
  long nonfinite_float = 0;                // NaN or Inf in any value or pdf, float
  long nonfinite_double = 0;               // same, double
  std::vector<std::string> alpha_buckets;  // row labels of by_alpha_and_cos
  std::vector<std::string> cos_buckets;    // column labels, by min(n.l, n.v)
  std::vector<std::vector<PrecisionCell>> by_alpha_and_cos;
  // Per model part (D, G, F, each by name): over the whole sweep, and over
  // the "benign" part alpha >= 0.01, min(n.l, n.v) >= 0.01.
  struct Part {
    std::string kind;  // "D", "G" or "F"
    std::string name;
    PrecisionCell all;
    PrecisionCell benign;
  };
  std::vector<Part> by_part;
};

// Relative error of one evaluation: max over RGB of |f_float - f_double| /
// |f_double|, over channels where |f_double| >= 1e-20 (smaller radiance
// factors are negligible and may underflow in float); 0 where both are 0.
PrecisionReport precisionSweep();

std::string toMarkdown(const PrecisionReport& report);
nlohmann::json toJson(const PrecisionReport& report);

}  // namespace facet::materials
