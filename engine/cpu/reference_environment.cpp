#include "engine/cpu/reference_environment.h"

#include <cmath>
#include <vector>

#include "engine/ibl/environment_lookup.h"
#include "engine/ibl/environment_mip_chain.h"

namespace facet::cpu {
namespace {

namespace m = rules::f64;

// A sample of either technique, of `share` above the surface: offered, and
// arriving where, with occlusion, its shadow ray is not blocked.
template <class Share>
void addSample(EnvironmentLight& light, const m::MisSample& s, const glm::dvec3& n, const glm::dvec3& ng,
               bool occlusion, std::uint32_t passThroughKey, const ShadowTest& blocked, const Share& share) {
  if (!m::mis_sample_arrives(s, n, ng)) return;
  const glm::dvec3 radiance = share();
  light.offered += radiance;
  if (!(occlusion && blocked(s.direction, passThroughKey))) light.arriving += radiance;
}

}  // namespace

glm::dvec3 ReferenceEnvironment::toMap(const glm::dvec3& world) const {
  return m::environment_to_map(world, lighting_.cosRotation, lighting_.sinRotation);
}

glm::dvec3 ReferenceEnvironment::fromMap(const glm::dvec3& map) const {
  return m::environment_from_map(map, lighting_.cosRotation, lighting_.sinRotation);
}

glm::dvec3 ReferenceEnvironment::radiance(const glm::dvec3& world) const {
  const scene::EnvironmentMap& map = *lighting_.environment->map;
  return lighting_.environment->intensity *
         ibl::bilinearLookup(map.rgb.data(), map.width, map.height, m::environment_uv(toMap(world)));
}

EnvironmentLight ReferenceEnvironment::at(const m::BrdfParams& params, const glm::dvec3& specularScale, int material,
                                          const glm::dvec3& n, const glm::dvec3& ng, const glm::dvec3& v,
                                          const VertexKey& key, const ShadowTest& blocked) const {
  switch (lighting_.environment->method) {
    case scene::IblMethod::Sampled:
      return sampled(params, specularScale, n, ng, v, key, blocked);
    case scene::IblMethod::Filtered:
      return filtered(params, specularScale, n, ng, v, key, blocked);
    case scene::IblMethod::Prefiltered:
      break;
  }
  const glm::dvec3 offered = prefiltered(params, specularScale, material, n, v);
  return {offered, offered};
}

// The sampled method (rules/environment/sampled_environment.h), with the
// environment's distribution in vectors.
EnvironmentLight ReferenceEnvironment::sampled(const m::BrdfParams& params, const glm::dvec3& specularScale,
                                               const glm::dvec3& n, const glm::dvec3& ng, const glm::dvec3& v,
                                               const VertexKey& key, const ShadowTest& blocked) const {
  const scene::Environment& environment = *lighting_.environment;
  const ibl::EnvironmentDistribution& distribution = lighting_.distribution;
  const auto pairs = std::uint32_t(environment.samples);
  EnvironmentLight light;
  auto add = [&](const m::MisSample& s, std::uint32_t slot) {
    addSample(light, s, n, ng, environment.occlusion, key.shadowRay(slot), blocked,
              [&] { return m::mis_sample_share(params, n, v, s, radiance(s.direction), pairs, specularScale); });
  };
  for (std::uint32_t k = 0; k < pairs; ++k) {
    const m::EnvironmentPair pair = m::environment_pair(params, n, v, key.pixel, key.sample, key.seed, k, pairs);
    const ibl::EnvironmentSample e = ibl::sampleEnvironment(distribution, pair.texel_bits, pair.environment_u);
    add(m::environment_technique_sample(params, n, v, fromMap(e.direction), e.pdf), key.lights + 2 * k);
    add(m::brdf_technique_sample(params, n, v, pair.brdf_direction,
                                 ibl::environmentPdf(distribution, toMap(pair.brdf_direction))),
        key.lights + 2 * k + 1);
  }
  return light;
}

// The filtered method (rules/environment/filtered_environment.h): the
// sampled method's pairs, BRDF samples read from the mip chain.
EnvironmentLight ReferenceEnvironment::filtered(const m::BrdfParams& params, const glm::dvec3& specularScale,
                                                const glm::dvec3& n, const glm::dvec3& ng, const glm::dvec3& v,
                                                const VertexKey& key, const ShadowTest& blocked) const {
  const scene::Environment& environment = *lighting_.environment;
  const std::vector<ibl::MipLevel>& chain = lighting_.mipChain;
  const bool withEnvironment = lighting_.environmentSamples;
  const ibl::EnvironmentDistribution& distribution = lighting_.distribution;
  const auto pairs = std::uint32_t(environment.samples);
  EnvironmentLight light;
  // Per pair, the environment technique's slot (if drawn), then the BRDF technique's.
  const std::uint32_t stride = withEnvironment ? 2 : 1;
  auto add = [&](const m::MisSample& s, double lod, std::uint32_t slot) {
    addSample(light, s, n, ng, environment.occlusion, key.shadowRay(slot), blocked, [&] {
      const glm::dvec3 incoming =
          environment.intensity * ibl::mipChainRadiance(chain, m::environment_uv(toMap(s.direction)), lod);
      return m::mis_sample_share(params, n, v, s, incoming, pairs, specularScale);
    });
  };
  for (std::uint32_t k = 0; k < pairs; ++k) {
    const m::EnvironmentPair pair = m::environment_pair(params, n, v, key.pixel, key.sample, key.seed, k, pairs);
    if (withEnvironment) {
      const ibl::EnvironmentSample e = ibl::sampleEnvironment(distribution, pair.texel_bits, pair.environment_u);
      add(m::environment_technique_sample(params, n, v, fromMap(e.direction), e.pdf), 0.0, key.lights + stride * k);
    }
    m::MisSample s = m::brdf_technique_sample(params, n, v, pair.brdf_direction, 0.0);
    const double lod = m::filtered_sample_lod(s, pairs, chain.front().width, chain.front().height, int(chain.size()));
    if (withEnvironment)
      s.other_pdf = ibl::mipChainRadiance(lighting_.pdfChain, m::environment_uv(toMap(s.direction)), lod).x;
    add(s, lod, key.lights + stride * k + stride - 1);
  }
  return light;
}

glm::dvec3 ReferenceEnvironment::prefiltered(const m::BrdfParams& params, const glm::dvec3& specularScale, int material,
                                             const glm::dvec3& n, const glm::dvec3& v) const {
  const ibl::PrefilteredEnvironment& prefiltered = lighting_.prefiltered;
  const m::SplitSumLookups l = m::split_sum_lookups(params, n, v);
  if (!l.visible) return glm::dvec3(0.0);
  const glm::dvec3 lobe = ibl::prefilteredRadiance(prefiltered, toMap(l.lobe), l.alpha);
  const glm::dvec2 dfg =
      ibl::dfgLookup(prefiltered.dfg[std::size_t(lighting_.dfgTable[std::size_t(material)])], l.nv, l.alpha);
  const glm::dvec3 irradiance = ibl::irradianceOverPi(prefiltered, toMap(n));
  glm::dvec3 coatRadiance(0.0);
  glm::dvec2 coatDfg(0.0);
  if (l.coated) {
    coatRadiance = ibl::prefilteredRadiance(prefiltered, toMap(l.coat_lobe), l.coat_alpha);
    coatDfg = ibl::dfgLookup(prefiltered.dfg[std::size_t(lighting_.coatDfgTable)], l.nv_coat, l.coat_alpha);
  }
  return lighting_.environment->intensity *
         m::environment_split_sum(params, l, lobe, dfg, irradiance, specularScale, coatRadiance, coatDfg);
}

}  // namespace facet::cpu
