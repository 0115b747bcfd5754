// The shared shading source, compiled as GLSL and run on the device, against
// its C++ double instantiation: the two sides of "one source of truth".
#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "facet_materials_spirv/spirv.h"
#include "materials/models.h"
#include "rules/rules.h"
#include "tests/support/gpu_device.h"

namespace facet::materials {
namespace {

using gpu::BufferUsage;

struct Variant {
  int d, g, f;
  double anisotropy = 0.0;
};

struct alignas(16) Parameters {
  glm::vec4 f0Alpha, eta, k, diffuse, tangentAnisotropy;
  std::uint32_t count;
};

class BrdfGpuParity : public gpu::testing::GpuTest, public ::testing::WithParamInterface<Variant> {};

glm::dvec3 randomDirection(std::mt19937& rng, double minCos) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double z = minCos + (1.0 - minCos) * u(rng);
  const double phi = 2.0 * std::numbers::pi * u(rng);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

TEST_P(BrdfGpuParity, GlslFloatMatchesCppDouble) {
  const Variant variant = GetParam();
  rules::f64::BrdfParams p{variant.d,
                           variant.g,
                           variant.f,
                           0.0,
                           glm::dvec3(0.9, 0.6, 0.3),
                           glm::dvec3(1.5, 1.6, 1.7),
                           glm::dvec3(3.0, 2.5, 2.0),
                           0.0,
                           glm::dvec3(0.2, 0.3, 0.4),
                           variant.anisotropy,
                           glm::normalize(glm::dvec3(0.8, 0.6, 0.3))};
  // Directions at least 0.01 above the horizon and alpha >= 0.05: the domain
  // where docs/shading.md's float-vs-double table stays below 1e-4.
  std::mt19937 rng(1234 + variant.d * 100 + variant.g * 10 + variant.f);
  const std::uint32_t count = 4096;
  std::vector<glm::vec4> cases;
  std::vector<glm::dvec3> ls, vs;
  std::vector<double> alphas;
  const glm::dvec3 n(0.0, 0.0, 1.0);
  for (std::uint32_t i = 0; i < count; ++i) {
    ls.push_back(randomDirection(rng, 0.01));
    vs.push_back(randomDirection(rng, 0.01));
    cases.insert(cases.end(),
                 {glm::vec4(glm::vec3(n), 0), glm::vec4(glm::vec3(ls.back()), 0), glm::vec4(glm::vec3(vs.back()), 0)});
  }
  // One alpha per dispatch keeps the kernel's parameters uniform.
  const double alpha = 0.05 + 0.95 * std::uniform_real_distribution<double>(0, 1)(rng);
  p.alpha = alpha;
  Parameters parameters{glm::vec4(glm::vec3(p.f0), float(alpha)),
                        glm::vec4(glm::vec3(p.eta), 0),
                        glm::vec4(glm::vec3(p.k), 0),
                        glm::vec4(glm::vec3(p.diffuse), 0),
                        glm::vec4(glm::vec3(p.tangent), float(p.anisotropy)),
                        count};

  gpu::Buffer caseBuffer = upload(cases);
  gpu::Buffer results = poisoned(count * 3 * sizeof(glm::vec4));
  gpu::Buffer uniforms =
      device_.createBuffer({"parameters", sizeof(Parameters), BufferUsage::Uniform | BufferUsage::CopyDst});
  device_.queue().writeBuffer(uniforms, 0, &parameters, sizeof(Parameters));
  auto pipeline =
      derivedPipeline("brdf", spirv::brdf_eval,
                      {{"D_MODEL", double(variant.d)}, {"G_MODEL", double(variant.g)}, {"F_MODEL", double(variant.f)}});
  auto layout = pipeline.getBindGroupLayout(0);
  auto group = device_.createBindGroup({"brdf", &layout, {{0, &caseBuffer}, {1, &results}, {2, &uniforms}}});
  dispatchOnce(pipeline, group, count / 64);
  const std::vector<glm::vec4> out = readBack<glm::vec4>(results);

  // Tolerance: 1e-4 relative to the largest channel of f, the bound the
  // float-vs-double sweep (docs/shading.md) holds the shared source to in this
  // domain; lavapipe's exp and pow stay far inside it.
  double worst = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const glm::dvec3 expected = rules::f64::brdf_evaluate(p, n, ls[i], vs[i]);
    const glm::dvec3 gpu = glm::dvec3(glm::vec3(out[3 * i]));
    ASSERT_TRUE(std::isfinite(gpu.x) && std::isfinite(gpu.y) && std::isfinite(gpu.z)) << "case " << i;
    const double scale = std::max({expected.x, expected.y, expected.z, 1e-30});
    const double error = glm::length(gpu - expected) / scale;
    worst = std::max(worst, error);
    ASSERT_LE(error, 1e-4) << "case " << i << ": n.l " << ls[i].z << ", n.v " << vs[i].z << ", alpha " << alpha;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
}

std::vector<Variant> variants() {
  // Every D, G and F at least once, each with the defaults of the other two.
  std::vector<Variant> v;
  for (const ModelName& d : kDistributions)
    v.push_back({d.id, rules::f64::G_SMITH_GGX_CORRELATED, rules::f64::F_SCHLICK});
  for (const ModelName& g : kGeometryTerms)
    if (g.id != rules::f64::G_SMITH_GGX_CORRELATED) v.push_back({rules::f64::D_GGX, g.id, rules::f64::F_SCHLICK});
  for (const ModelName& f : kFresnelTerms)
    if (f.id != rules::f64::F_SCHLICK) v.push_back({rules::f64::D_GGX, rules::f64::G_SMITH_GGX_CORRELATED, f.id});
  // Anisotropic lobes: both microsurfaces, separable and height-correlated
  // Smith G, and a G without a microsurface.
  for (const Variant a :
       {Variant{rules::f64::D_GGX, rules::f64::G_SMITH_GGX_CORRELATED, rules::f64::F_SCHLICK, 0.8},
        Variant{rules::f64::D_GGX, rules::f64::G_SMITH_GGX, rules::f64::F_SCHLICK, 0.5},
        Variant{rules::f64::D_BECKMANN, rules::f64::G_SMITH_BECKMANN_CORRELATED, rules::f64::F_SCHLICK, 0.8},
        Variant{rules::f64::D_BECKMANN, rules::f64::G_SMITH_BECKMANN, rules::f64::F_SCHLICK, 1.0},
        Variant{rules::f64::D_GGX, rules::f64::G_KELEMEN, rules::f64::F_SCHLICK, 0.8}})
    v.push_back(a);
  return v;
}

INSTANTIATE_TEST_SUITE_P(Models, BrdfGpuParity, ::testing::ValuesIn(variants()), [](const auto& info) {
  auto name = [](std::span<const ModelName> table, int id) {
    std::string s(modelName(table, id));
    for (char& c : s) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return s;
  };
  return name(kDistributions, info.param.d) + "_" + name(kGeometryTerms, info.param.g) + "_" +
         name(kFresnelTerms, info.param.f) +
         (info.param.anisotropy > 0 ? "_anisotropy" + std::to_string(int(info.param.anisotropy * 10)) : "");
});

}  // namespace
}  // namespace facet::materials
