#include "engine/cpu/reference_renderer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "engine/camera/camera.h"
#include "engine/cpu/intersector.h"
#include "engine/cpu/limit_normal.h"
#include "engine/cpu/path_tracer.h"
#include "engine/cpu/punctual_light.h"
#include "engine/cpu/reference_environment.h"
#include "engine/cpu/textured_hit.h"
#include "engine/ibl/compensation_tables.h"
#include "engine/ibl/environment_lighting.h"
#include "materials/material.h"
#include "rules/rules.h"
#include "scenes/camera_medium.h"

namespace facet::cpu {
namespace {

namespace m = rules::f64;

struct SceneHit {
  SurfaceHit surface;
  int object = -1;
};

class ReferenceScene final : public PathScene {
 public:
  ReferenceScene(const scene::Scene& scene, const scene::SceneGeometry& geometry,
                 const ibl::EnvironmentLighting* environment)
      : scene_(scene),
        geometry_(geometry),
        compensation_(ibl::compensationTables(scene)),
        castsShadowRays_(environment && scene::castsShadowRays(*environment->environment)) {
    if (environment) environment_.emplace(*environment);
    ExactSettings exactSettings;
    if (scene.render.exactTolerance)
      exactSettings.tolerance = *scene.render.exactTolerance * geometry.bounds.diagonal();
    exactSettings.precisionFloor = precisionFloor(geometry.bounds);
    shadowOffset_ = m::shadow_ray_offset(geometry.bounds.diagonal(),
                                         std::max(exactSettings.tolerance, exactSettings.precisionFloor));
    coneSpread_ = m::camera_cone_spread(std::tan(glm::radians(0.5 * scene.camera.verticalFovDegrees)),
                                        double(scene.render.height));
    const bool crossings = std::any_of(scene.materials.begin(), scene.materials.end(), materials::isTransmissive);
    int patches = 0, faces = 0;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      const scene::ObjectGeometry& object = geometry.objects[i];
      patchOffset_.push_back(patches);
      faceOffset_.push_back(faces);
      patches += object.surface.patchCount();
      faces += scene.objects[i].cage.faceCount();
      intersectors_.push_back(objectIntersector(scene, i, object, exactSettings, crossings));
      const materials::Material& material = scene.materials[std::size_t(scene.objects[i].material)];
      params_.push_back(materials::toParams64(material));
      transmission_.push_back(materials::isTransmissive(material)
                                  ? std::optional(materials::transmissionParams64(material))
                                  : std::nullopt);
      sealed_.push_back(scene::sealsInside(scene.objects[i], object));
    }
  }

  // Nearest hit of all objects; each searches only nearer than the best so far.
  std::optional<SceneHit> closestHit(Ray ray) const {
    std::optional<SceneHit> nearest;
    for (std::size_t i = 0; i < intersectors_.size(); ++i) {
      std::optional<SurfaceHit> hit = intersectors_[i]->closestHit(ray);
      if (!hit) continue;
      nearest = SceneHit{*hit, int(i)};
      ray.tMax = hit->t;
    }
    return nearest;
  }

  // The nearest hit the camera ray of (pixel, sample) sees: it passes over a shadow catcher.
  std::optional<SceneHit> cameraHit(Ray ray, std::uint32_t pixel, std::uint32_t sample) const {
    ray.passThroughKey = m::pass_through_key(pixel, sample, environmentSeed(), m::PASS_THROUGH_NEAREST);
    std::optional<SceneHit> hit = closestHit(ray);
    if (hit && scene_.objects[std::size_t(hit->object)].shadowCatcher && !m::catcher_seen_at(1u)) return std::nullopt;
    return hit;
  }

  // Radiance leaving the hit towards -direction, from every punctual light
  // and the environment; (pixel, sample) name the sample's random numbers.
  glm::dvec3 shade(const SceneHit& hit, const glm::dvec3& direction, std::uint32_t pixel, std::uint32_t sample,
                   std::uint64_t& shadowRays) const {
    return shadeVertex(hit, direction, pixel, sample, environmentSeed(), shadowRays).radiance;
  }

  // The scene's seed: vertex 1's environment pairs (rules/sampling/path_samples.h).
  std::uint32_t environmentSeed() const { return environment_ ? environment_->seed() : 0u; }

  // shade(), its environment pairs drawn with `seed`, and the vertex a path continues from.
  ShadedVertex shadeVertex(const SceneHit& hit, const glm::dvec3& direction, std::uint32_t pixel, std::uint32_t sample,
                           std::uint32_t seed, std::uint64_t& shadowRays) const {
    const glm::dvec3 v = -direction;
    const int material = scene_.objects[std::size_t(hit.object)].material;
    const m::FacingNormals facing = m::facing_normals(hit.surface.shadingNormal, hit.surface.geometricNormal, v);
    const m::HitMaterial fetched = hitMaterial(hit, facing.ng, direction);
    m::SurfaceAtHit s = m::surface_at_hit(fetched, facing, v, hitPartials(hit));
    // The catcher is lit by the environment alone, whose share it measures.
    const bool catcher = scene_.objects[std::size_t(hit.object)].shadowCatcher && environment_;
    const glm::dvec3& position = hit.surface.position;
    const glm::dvec3 specularScale =
        ibl::specularScale(compensation_, material, s.params, glm::dot(s.n, v), fetched.transmissive, s.outside);
    const VertexKey vertexKey{pixel, sample, seed, std::uint32_t(scene_.lights.size())};
    glm::dvec3 radiance = s.emission;
    // Inside a sealed solid each of the environment's shadow rays would be blocked.
    if (environment_ && !(castsShadowRays_ && m::environment_sealed_off(fetched.transmissive, s.transmission, s.outside,
                                                                        sealed_[std::size_t(hit.object)]))) {
      const EnvironmentLight environment =
          environment_->at(s.params, specularScale, material, s.n, s.ng, v, vertexKey,
                           [&](const glm::dvec3& l, std::uint32_t passThroughKey) {
                             return occluded(position, s.ng, l, INFINITY, passThroughKey, shadowRays);
                           });
      if (catcher) {
        const glm::dvec3 behind = background(direction), offered = s.occlusion * environment.offered;
        radiance += m::catcher_slot_scale(behind, offered) * (s.occlusion * environment.arriving) +
                    m::catcher_unshadowed(behind, offered);
        s.params = m::catcher_path_params(s.params);
      } else {
        radiance += s.occlusion * environment.arriving;
      }
    }
    for (std::uint32_t slot = 0; slot < scene_.lights.size(); ++slot) {
      const m::LightIncidence incidence = m::light_incidence(punctualLight(scene_.lights[slot]), position);
      if (catcher || !m::light_arrives(incidence, s.n, s.ng)) continue;
      if (occluded(position, s.ng, incidence.direction, incidence.distance, vertexKey.shadowRay(slot), shadowRays))
        continue;
      radiance += m::punctual_radiance(s.params, s.n, incidence.direction, v, incidence.color, specularScale);
    }
    return {radiance,
            {position, s.n, s.ng, v, s.params, specularScale, fetched.transmissive, s.transmission, s.outside},
            hit.object};
  }

  std::optional<ShadedVertex> shadeNearest(const Ray& ray, std::uint32_t pixel, std::uint32_t sample, std::uint32_t seed,
                                         std::uint64_t& shadowRays) const override {
    Ray keyed = ray;
    keyed.passThroughKey = m::pass_through_key(pixel, sample, seed, m::PASS_THROUGH_NEAREST);
    const std::optional<SceneHit> hit = closestHit(keyed);
    if (!hit) return std::nullopt;
    return shadeVertex(*hit, ray.direction, pixel, sample, seed, shadowRays);
  }

  double leavingOffset() const override { return shadowOffset_; }

  glm::dvec3 escapedRadiance(const glm::dvec3& direction) const override { return background(direction); }

  void writeAovs(Image& image, std::size_t pixel, const SceneHit& hit, const glm::dvec3& direction) const {
    const m::FacingNormals facing =
        m::facing_normals(hit.surface.shadingNormal, hit.surface.geometricNormal, -direction);
    image.depth[pixel] = float(hit.surface.t);
    image.position[pixel] = glm::vec3(hit.surface.position);
    image.geometricNormal[pixel] = glm::vec3(facing.ng);
    image.shadingNormal[pixel] = glm::vec3(facing.n);
    image.patchId[pixel] = std::uint32_t(patchOffset_[std::size_t(hit.object)] + hit.surface.patch);
    image.faceId[pixel] = std::uint32_t(faceOffset_[std::size_t(hit.object)] + hit.surface.coarseFace);
    image.uv[pixel] = glm::vec2(float(hit.surface.u), float(hit.surface.v));
    image.texcoord[pixel] = glm::vec2(geometry_.objects[std::size_t(hit.object)]
                                          .surface.evaluateTexcoord(hit.surface.patch, hit.surface.u, hit.surface.v)
                                          .uv);
  }

  // What a camera ray that hits nothing sees.
  glm::dvec3 background(const glm::dvec3& direction) const {
    return environment_ ? environment_->radiance(direction) : glm::dvec3(0.0);
  }

 private:
  // What the material at `hit` offers surface_at_hit: its parameters, its
  // textures read at the hit (seen along `direction`, of geometric normal ng)
  // and its transmission.
  m::HitMaterial hitMaterial(const SceneHit& hit, const glm::dvec3& ng, const glm::dvec3& direction) const {
    const auto object = std::size_t(hit.object);
    const materials::Material& material = scene_.materials[std::size_t(scene_.objects[object].material)];
    m::HitMaterial fetched{};
    fetched.params = params_[object];
    fetched.emission = material.emission;
    fetched.textured = material.textures.has_value();
    if (fetched.textured) {
      fetched.factors = texturedFactors(*material.textures);
      fetched.texels = materialTexels(geometry_.objects[object].surface, hit.surface, scene_.textures,
                                      *material.textures, ng, direction, coneSpread_);
    }
    fetched.transmissive = transmission_[object].has_value();
    fetched.transmission = transmission_[object].value_or(m::TransmissionParams{});
    if (fetched.params.anisotropy != 0.0)
      fetched.anisotropy_rotation = {std::cos(material.anisotropyRotation), std::sin(material.anisotropyRotation)};
    return fetched;
  }

  // The mesh's tangent where it carries one (only where its material takes
  // it), and the partials the anisotropic lobe's tangent is made of
  // otherwise, evaluated only where the material is anisotropic (textures
  // may only scale its strength).
  m::HitPartials hitPartials(const SceneHit& hit) const {
    const scene::SubdivisionSurface& surface = geometry_.objects[std::size_t(hit.object)].surface;
    m::HitPartials partials{};
    partials.tangent = meshTangent(surface, hit.surface.patch, hit.surface.u, hit.surface.v);
    if (params_[std::size_t(hit.object)].anisotropy == 0.0) return partials;
    const scene::LimitPoint p = surface.evaluatePatch(hit.surface.patch, hit.surface.u, hit.surface.v);
    const scene::LimitTexcoord uv = surface.evaluateTexcoord(hit.surface.patch, hit.surface.u, hit.surface.v);
    partials.dp_ds = p.du;
    partials.dp_dt = p.dv;
    partials.duv_ds = uv.du;
    partials.duv_dt = uv.dv;
    return partials;
  }

  bool occluded(const glm::dvec3& position, const glm::dvec3& ng, const glm::dvec3& l, double distance,
                std::uint32_t passThroughKey, std::uint64_t& shadowRays) const {
    ++shadowRays;
    const Ray ray{m::shadow_ray_origin(position, ng, shadowOffset_), l, shadowOffset_, distance, passThroughKey};
    for (const std::unique_ptr<Intersector>& object : intersectors_)
      if (object->anyHit(ray)) return true;
    return false;
  }

  const scene::Scene& scene_;
  const scene::SceneGeometry& geometry_;
  std::optional<ReferenceEnvironment> environment_;
  const ibl::CompensationTables compensation_;
  double shadowOffset_;
  double coneSpread_;  // of camera rays: the angle of one pixel
  std::vector<int> patchOffset_, faceOffset_;
  std::vector<std::unique_ptr<Intersector>> intersectors_;  // parallel to the scene's objects
  std::vector<rules::f64::BrdfParams> params_;
  std::vector<std::optional<rules::f64::TransmissionParams>> transmission_;  // transmissive materials only
  const bool castsShadowRays_;  // the environment's light is decided by shadow rays
  std::vector<char> sealed_;    // per object: scene::sealsInside
};

}  // namespace

unsigned resolveThreadCount(unsigned threadCount) {
  return threadCount > 0 ? threadCount : std::max(1u, std::thread::hardware_concurrency());
}

Image renderReference(const scene::Scene& scene, const scene::SceneGeometry& geometry, ReferenceStatistics* statistics,
                      const std::function<void(double)>& progress, const std::optional<PixelRect>& crop,
                      unsigned threadCount) {
  if (!scene::pathsCountEnvironmentOnce(scene.render.bounces, scene.environment))
    throw std::invalid_argument("bounces " + std::to_string(scene.render.bounces) + ": " +
                                scene::kBouncesNeedOcclusionRule);
  checkTessellationFitsInMemory(scene, geometry);
  const int width = scene.render.width, height = scene.render.height;
  const PixelRect window = crop.value_or(PixelRect::whole(width, height));
  Image image(window.width(), window.height());
  const auto environmentStart = std::chrono::steady_clock::now();
  std::optional<ibl::EnvironmentLighting> environment;
  if (scene.environment)
    environment =
        ibl::prepareEnvironmentLighting(scene, [](const scene::EnvironmentMap& map, const ibl::ModelPairs& models) {
          const ibl::PrefilterSettings settings;
          return ibl::rememberedPrefilter(map, models, settings, "cpu",
                                          [&] { return ibl::prefilterOnCpu(map, models, settings); });
        });
  const double environmentMilliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - environmentStart).count();
  const ReferenceScene reference(scene, geometry, environment ? &*environment : nullptr);
  const rules::f64::CameraFrame frame = camera::cameraFrame(scene.camera, width, height);
  const std::uint32_t strata = rules::f64::sample_strata(std::uint32_t(scene.render.samplesPerPixel));
  const std::uint32_t raysPerPixel = rules::f64::rays_per_pixel(strata);
  const glm::dvec3 eyeSigma = scene::cameraMedium(scene, geometry).sigma;

  std::atomic<int> nextRow{window.y0}, finishedRows{0};
  std::atomic<std::uint64_t> primaryRays{0}, shadowRays{0};
  const int bounces = scene.render.bounces;
  const LobeLimits lobeLimits{scene.render.diffuseBounces, scene.render.glossyBounces,
                              scene.render.transmissionBounces};
  std::vector<BounceRays> raysPerBounce(bounces > 0 ? std::size_t(bounces) + 1 : 0);
  std::mutex progressMutex;
  auto worker = [&] {
    std::uint64_t primary = 0, shadow = 0;
    std::vector<BounceRays> bounceRays(raysPerBounce.size());
    for (int y = nextRow++; y < window.y1; y = nextRow++) {
      for (int x = window.x0; x < window.x1; ++x) {
        const std::size_t pixel = image.index(x - window.x0, y - window.y0);
        // Random numbers follow the pixel of the full image, so that a crop
        // renders exactly the pixels of the whole render.
        const auto pixelId = std::uint32_t(std::size_t(y) * std::size_t(width) + std::size_t(x));
        glm::dvec3 radiance(0.0);
        double coverage = 0;
        for (std::uint32_t sample = 0; sample < raysPerPixel; ++sample) {
          const glm::dvec2 offset = rules::f64::sample_offset(pixelId, sample, strata, reference.environmentSeed());
          const glm::dvec3 direction =
              rules::f64::camera_ray_direction(frame, x + offset.x, y + offset.y, width, height);
          ++primary;
          const auto hit = reference.cameraHit(Ray{frame.eye, direction}, pixelId, sample);
          if (hit && !bounceRays.empty()) ++bounceRays[0].hits;
          if (sample == 0 && hit) reference.writeAovs(image, pixel, *hit, direction);
          if (!rules::f64::is_shaded_sample(sample, strata)) continue;
          if (!hit) {
            radiance += reference.background(direction);
            continue;
          }
          coverage += 1;
          if (scene.objects[std::size_t(hit->object)].holdout) continue;  // black to the camera
          // The eye inside an absorbing solid sees the hit through it.
          const m::PathCarry start = m::camera_path_start(eyeSigma, frame.eye, hit->surface.position);
          if (bounces == 0) {
            radiance += start.throughput * reference.shade(*hit, direction, pixelId, sample, shadow);
            continue;
          }
          const ShadedVertex first = reference.shadeVertex(*hit, direction, pixelId, sample, reference.environmentSeed(),
                                                         bounceRays[0].shadowRays);
          radiance += tracePath(reference, first, start, {pixelId, sample, raysPerPixel, reference.environmentSeed()},
                                bounces, bounceRays, lobeLimits);
        }
        const double samples = double(rules::f64::shaded_sample_count(strata));
        image.beauty[pixel] = glm::vec4(glm::vec3(radiance / samples), float(coverage / samples));
      }
      const int done = ++finishedRows;
      if (progress) {
        std::lock_guard lock(progressMutex);
        progress(double(done) / window.height());
      }
    }
    if (!bounceRays.empty()) bounceRays[0].rays = primary;
    std::lock_guard lock(progressMutex);
    for (std::size_t b = 0; b < bounceRays.size(); ++b) {
      raysPerBounce[b].rays += bounceRays[b].rays;
      raysPerBounce[b].hits += bounceRays[b].hits;
      raysPerBounce[b].shadowRays += bounceRays[b].shadowRays;
      shadow += bounceRays[b].shadowRays;
    }
    primaryRays += primary;
    shadowRays += shadow;
  };
  std::vector<std::thread> threads;
  for (unsigned i = 0; i < resolveThreadCount(threadCount); ++i) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  if (statistics) *statistics = {primaryRays, shadowRays, environmentMilliseconds, std::move(raysPerBounce)};
  return image;
}

}  // namespace facet::cpu
