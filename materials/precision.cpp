#include "materials/precision.h"

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <numbers>

#include "materials/models.h"
#include "rules/rules.h"

namespace facet::materials {

namespace {

constexpr double kNegligible = 1e-20;
constexpr double kBenign = 0.01;

const double kAlphas[] = {0,   1e-4, 5e-4, 1e-3, 2e-3, 5e-3, 0.01, 0.02, 0.05, 0.1,
                          0.2, 0.3,  0.4,  0.5,  0.6,  0.7,  0.8,  0.9,  1.0};
const double kAlphaBucketTops[] = {1e-3, 1e-2, 0.1, 0.5, 1.0};
const char* const kAlphaLabels[] = {"[0, 1e-3] (clamped to 1e-3)", "(1e-3, 0.01]", "(0.01, 0.1]", "(0.1, 0.5]",
                                    "(0.5, 1]"};
// The first bucket holds the grid's cosines below the horizon epsilon 1e-4
// (1e-4 itself, rounded to float, may land on either side).
const double kCosBucketTops[] = {9.9e-5, 1e-3, 1e-2, 0.1, 1.0};
const char* const kCosLabels[] = {"< 1e-4 (horizon)", "[1e-4, 1e-3]", "(1e-3, 0.01]", "(0.01, 0.1]", "(0.1, 1]"};
const double kPhiDegrees[] = {0, 90, 179.9, 180};

// Cosines of the sweep: both signs, 0, and a geometric run into the horizon.
std::vector<double> cosines() {
  std::vector<double> positive = {1, 0.9, 0.7, 0.5, 0.3, 0.1, 0.03, 1e-2, 1e-3, 2.0e-4, 1e-4, 5e-5, 1e-6, 1e-8};
  std::vector<double> all = {0};
  for (double c : positive) {
    all.push_back(c);
    all.push_back(-c);
  }
  return all;
}

int bucketOf(double value, std::span<const double> tops) {
  for (size_t i = 0; i < tops.size(); ++i)
    if (value <= tops[i]) return static_cast<int>(i);
  return static_cast<int>(tops.size()) - 1;
}

// describe() formats the inputs; called only for a new maximum.
template <class Describe>
void record(PrecisionCell& cell, double error, const Describe& describe) {
  ++cell.evaluations;
  if (error > cell.max_relative_error) {
    cell.max_relative_error = error;
    cell.worst_case = describe();
  }
}

template <class Vec3>
bool finite(Vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

double relativeError(glm::vec3 single, glm::dvec3 reference) {
  double worst = 0;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(reference[i]) < kNegligible) continue;
    worst = std::max(worst, std::abs(double(single[i]) - reference[i]) / std::abs(reference[i]));
  }
  return worst;
}

}  // namespace

PrecisionReport precisionSweep() {
  PrecisionReport report;
  for (const char* label : kAlphaLabels) report.alpha_buckets.push_back(label);
  for (const char* label : kCosLabels) report.cos_buckets.push_back(label);
  report.by_alpha_and_cos.assign(std::size(kAlphaLabels), std::vector<PrecisionCell>(std::size(kCosLabels)));
  auto addParts = [&](const char* kind, std::span<const ModelName> table) {
    for (const ModelName& model : table) report.by_part.push_back({kind, std::string(model.name), {}, {}});
  };
  addParts("D", kDistributions);
  addParts("G", kGeometryTerms);
  addParts("F", kFresnelTerms);
  auto part = [&](std::string_view kind, std::string_view name) {
    for (PrecisionReport::Part& p : report.by_part)
      if (p.kind == kind && p.name == name) return &p;
    return &report.by_part.front();
  };

  // A normal off the coordinate axes, so that no product in the dot and
  // cross products is exact by accident.
  const glm::dmat3 frame(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(1, 2, 3))));
  const std::vector<double> cos_grid = cosines();

  rules::f64::BrdfParams p64{};
  p64.f0 = glm::dvec3(1.00, 0.71, 0.29);   // gold, as printed in the course
  p64.eta = glm::dvec3(0.18, 0.42, 1.37);  // gold-like complex index: eta
  p64.k = glm::dvec3(3.42, 2.35, 1.77);    // and extinction k
  p64.diffuse = glm::dvec3(0);             // so the specular error is not diluted
  for (const ModelName& d : kDistributions) {
    for (const ModelName& g : kGeometryTerms) {
      for (const ModelName& f : kFresnelTerms) {
        p64.d_model = d.id;
        p64.g_model = g.id;
        p64.f_model = f.id;
        PrecisionReport::Part* parts[] = {part("D", d.name), part("G", g.name), part("F", f.name)};
        // Dielectric reads eta as a real index of refraction.
        p64.eta = f.id == rules::f64::F_DIELECTRIC ? glm::dvec3(1.5) : glm::dvec3(0.18, 0.42, 1.37);
        for (double alpha : kAlphas) {
          p64.alpha = alpha;
          rules::f32::BrdfParams p32{};
          p32.d_model = p64.d_model;
          p32.g_model = p64.g_model;
          p32.f_model = p64.f_model;
          p32.alpha = static_cast<float>(alpha);
          p32.f0 = glm::vec3(p64.f0);
          p32.eta = glm::vec3(p64.eta);
          p32.k = glm::vec3(p64.k);
          p32.diffuse = glm::vec3(p64.diffuse);
          for (double cos_l : cos_grid) {
            for (double cos_v : cos_grid) {
              for (double phi_degrees : kPhiDegrees) {
                double phi = phi_degrees * std::numbers::pi / 180;
                double sin_l = std::sqrt(1 - cos_l * cos_l);
                double sin_v = std::sqrt(1 - cos_v * cos_v);
                glm::vec3 n32(frame * glm::dvec3(0, 0, 1));
                glm::vec3 l32(frame * glm::dvec3(sin_l, 0, cos_l));
                glm::vec3 v32(frame * glm::dvec3(sin_v * std::cos(phi), sin_v * std::sin(phi), cos_v));
                glm::dvec3 n64(n32), l64(l32), v64(v32);
                glm::vec3 f32v = rules::f32::brdf_evaluate(p32, n32, l32, v32);
                glm::dvec3 f64v = rules::f64::brdf_evaluate(p64, n64, l64, v64);
                bool ok32 = finite(f32v), ok64 = finite(f64v);
                for (int technique :
                     {rules::f64::SAMPLE_COSINE, rules::f64::SAMPLE_D, rules::f64::SAMPLE_GGX_VISIBLE}) {
                  ok32 = ok32 && std::isfinite(rules::f32::direction_pdf(technique, p32, n32, l32, v32));
                  ok64 = ok64 && std::isfinite(rules::f64::direction_pdf(technique, p64, n64, l64, v64));
                }
                ++report.evaluations;
                report.nonfinite_float += !ok32;
                report.nonfinite_double += !ok64;

                double error = relativeError(f32v, f64v);
                double min_cos = std::min(cos_l, cos_v);
                auto where = [&] {
                  char text[240];
                  std::snprintf(text, sizeof text, "%s/%s/%s alpha=%g n.l=%g n.v=%g phi=%g: f.r float %.7g double %.7g",
                                d.name.data(), g.name.data(), f.name.data(), alpha, cos_l, cos_v, phi_degrees,
                                double(f32v.x), f64v.x);
                  return std::string(text);
                };
                record(report.by_alpha_and_cos[bucketOf(alpha, kAlphaBucketTops)][bucketOf(min_cos, kCosBucketTops)],
                       error, where);
                bool benign = alpha >= kBenign && min_cos >= kBenign;
                for (PrecisionReport::Part* entry : parts) {
                  record(entry->all, error, where);
                  if (benign) record(entry->benign, error, where);
                }
              }
            }
          }
        }
      }
    }
  }
  return report;
}

std::string toMarkdown(const PrecisionReport& report) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(1);
  out << "Evaluations: " << report.evaluations << "; non-finite values or pdfs: float " << report.nonfinite_float
      << ", double " << report.nonfinite_double << ".\n\n";
  out << "Max relative error of f, float vs double, by alpha (rows) and min(n.l, n.v) "
         "(columns):\n\n| alpha \\ min(n.l, n.v) |";
  for (const std::string& label : report.cos_buckets) out << " " << label << " |";
  out << "\n|---|";
  for (size_t i = 0; i < report.cos_buckets.size(); ++i) out << "---|";
  out << "\n";
  for (size_t a = 0; a < report.alpha_buckets.size(); ++a) {
    out << "| " << report.alpha_buckets[a] << " |";
    for (const PrecisionCell& cell : report.by_alpha_and_cos[a]) out << " " << cell.max_relative_error << " |";
    out << "\n";
  }
  out << "\nMax relative error by model part, over the whole sweep and over alpha >= 0.01, "
         "min(n.l, n.v) >= 0.01:\n\n"
         "| part | model | all | alpha, cos >= 0.01 | worst case (all) |\n|---|---|---|---|---|\n";
  for (const PrecisionReport::Part& p : report.by_part)
    out << "| " << p.kind << " | " << p.name << " | " << p.all.max_relative_error << " | "
        << p.benign.max_relative_error << " | " << p.all.worst_case << " |\n";
  return out.str();
}

nlohmann::json toJson(const PrecisionReport& report) {
  auto cell = [](const PrecisionCell& c) {
    return nlohmann::json{
        {"max_relative_error", c.max_relative_error}, {"evaluations", c.evaluations}, {"worst_case", c.worst_case}};
  };
  nlohmann::json grid = nlohmann::json::array();
  for (size_t a = 0; a < report.alpha_buckets.size(); ++a)
    for (size_t c = 0; c < report.cos_buckets.size(); ++c)
      grid.push_back({{"alpha", report.alpha_buckets[a]},
                      {"min_cos", report.cos_buckets[c]},
                      {"cell", cell(report.by_alpha_and_cos[a][c])}});
  nlohmann::json parts = nlohmann::json::array();
  for (const PrecisionReport::Part& p : report.by_part)
    parts.push_back({{"kind", p.kind}, {"name", p.name}, {"all", cell(p.all)}, {"benign", cell(p.benign)}});
  return {{"evaluations", report.evaluations},
          {"nonfinite_float", report.nonfinite_float},
          {"nonfinite_double", report.nonfinite_double},
          {"by_alpha_and_min_cos", grid},
          {"by_part", parts}};
}

}  // namespace facet::materials
