#include "api/image_planes.h"

#include <string>

#include "facet/error.h"

namespace facet::v0 {
namespace {

template <int N, class Plane>
Aov aov(const Plane& plane) {
  Aov out;
  out.channels = N;
  out.values.resize(plane.size() * N);
  for (std::size_t i = 0; i < plane.size(); ++i)
    for (int c = 0; c < N; ++c) out.values[i * N + std::size_t(c)] = plane[i][c];
  return out;
}

}  // namespace

Image publicImage(const facet::Image& image) {
  Image out;
  out.width = image.width;
  out.height = image.height;
  out.aovs["beauty"] = aov<4>(image.beauty);
  out.aovs["depth"] = Aov{1, image.depth};
  out.aovs["position"] = aov<3>(image.position);
  out.aovs["geometric_normal"] = aov<3>(image.geometricNormal);
  out.aovs["shading_normal"] = aov<3>(image.shadingNormal);
  out.aovs["uv"] = aov<2>(image.uv);
  out.aovs["texcoord"] = aov<2>(image.texcoord);
  out.ids["patch_id"] = image.patchId;
  out.ids["face_id"] = image.faceId;
  return out;
}

namespace {

template <int N, class Plane>
void fromAov(const Image& image, const std::string& name, Plane& plane) {
  const auto found = image.aovs.find(name);
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  if (found == image.aovs.end()) throw Error(ErrorKind::BadInput, "image: no AOV named '" + name + "'");
  const Aov& a = found->second;
  if (a.channels != N || a.values.size() != pixels * N)
    throw Error(ErrorKind::BadInput, "image: AOV '" + name + "': must hold " + std::to_string(image.width) + " x " +
                                         std::to_string(image.height) + " x " + std::to_string(N) + " values, has " +
                                         std::to_string(a.values.size()) + " in " + std::to_string(a.channels) +
                                         " channels");
  plane.resize(pixels);
  for (std::size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < N; ++c) {
      if constexpr (N == 1)
        plane[i] = a.values[i];
      else
        plane[i][c] = a.values[i * N + std::size_t(c)];
    }
}

void fromIds(const Image& image, const std::string& name, std::vector<std::uint32_t>& plane) {
  const auto found = image.ids.find(name);
  if (found == image.ids.end() || found->second.size() != std::size_t(image.width) * std::size_t(image.height))
    throw Error(ErrorKind::BadInput, "image: ids '" + name + "': must have one id per pixel");
  plane = found->second;
}

}  // namespace

facet::Image engineImage(const Image& image) {
  if (image.width < 1 || image.height < 1 || image.width > 16384 || image.height > 16384)
    throw Error(ErrorKind::BadInput, "image: width and height must be in [1, 16384]");
  facet::Image out;
  out.width = image.width;
  out.height = image.height;
  fromAov<4>(image, "beauty", out.beauty);
  fromAov<1>(image, "depth", out.depth);
  fromAov<3>(image, "position", out.position);
  fromAov<3>(image, "geometric_normal", out.geometricNormal);
  fromAov<3>(image, "shading_normal", out.shadingNormal);
  fromAov<2>(image, "uv", out.uv);
  fromAov<2>(image, "texcoord", out.texcoord);
  fromIds(image, "patch_id", out.patchId);
  fromIds(image, "face_id", out.faceId);
  return out;
}

}  // namespace facet::v0
