// Multiple importance sampling, one sample from each of two techniques.

#ifndef FACET_RULE_SAMPLING_MIS
#define FACET_RULE_SAMPLING_MIS

// Veach's power heuristic (beta = 2) for the technique of density `pdf`
// (Veach 1997, chapter 9).
FACET_FN real power_heuristic(real pdf, real other_pdf) {
  real a = pdf * pdf;
  real b = other_pdf * other_pdf;
  return a + b > real(0) ? a / (a + b) : real(0);
}

#endif
