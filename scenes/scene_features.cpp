#include "scenes/scene_features.h"

namespace facet::scene {

SceneFeatures sceneFeatures(const Scene& scene) {
  SceneFeatures f;
  for (const Object& object : scene.objects) {
    const materials::Material& m = scene.materials[std::size_t(object.material)];
    f.perHitMaterials |= m.textures.has_value();
    f.emission |= m.emission != glm::dvec3(0.0);
    f.transmission |= materials::isTransmissive(m);
    f.anisotropy |= m.anisotropy > 0.0;
    f.clearcoat |= m.clearcoat > 0.0;
    f.sheen |= m.sheenColor != glm::dvec3(0.0);
    f.iridescence |= m.iridescence > 0.0;
    f.channels |= !object.cage.faceVertexTexcoords1.empty() || !object.cage.faceVertexColors.empty();
    f.culling |= cullsBackFaces(object, m);
    f.cutouts |= hasCutout(object);
    f.blends |= object.alphaMode == AlphaMode::Blend;
    f.shadowCatcher |= object.shadowCatcher;
    f.holdout |= object.holdout;
  }
  f.emission |= f.shadowCatcher;
  f.textures = f.perHitMaterials || !scene.textures.empty();
  f.paths = scene.render.bounces > 0;
  f.lobeLimits = f.paths && limitsLobes(scene.render);
  return f;
}

}  // namespace facet::scene
