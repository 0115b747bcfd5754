// Charts of one material in the spirit of Disney's BRDF Explorer (`facet
// plot`), drawn by gnuplot into SVG or PNG after the extension of `out`.
#pragma once

#include <filesystem>
#include <vector>

#include "materials/material.h"

namespace facet::analysis {

// Polar lobe in the plane of incidence: r(theta_l) = f(l, v)(n.l), v fixed
// at theta_v (degrees, in [0, 90)) on the left, l sweeping the upper half
// plane (BRDF Explorer's polar plot).
void writeLobeChart(const materials::Material& material, double theta_v, const std::filesystem::path& out);

// Directional albedo E(theta_v) from 0 to 90 degrees, one curve per alpha.
void writeAlbedoChart(const materials::Material& material, const std::vector<double>& alphas,
                      const std::filesystem::path& out);

}  // namespace facet::analysis
