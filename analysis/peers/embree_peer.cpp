#include "analysis/peers/embree_peer.h"

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <thread>

#include "engine/camera/camera.h"

namespace facet::peers {

namespace {

double nowMs() {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// A buffer of `count` items of `valuesPerItem` T each, owned by the geometry.
template <typename T>
T* newBuffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, std::size_t count, int valuesPerItem = 1) {
  return static_cast<T*>(rtcSetNewGeometryBuffer(geometry, type, 0, format, valuesPerItem * sizeof(T), count));
}

// OpenSubdiv treats sharpness >= 10 as infinitely sharp; Embree takes +inf.
float embreeSharpness(float sharpness) {
  return sharpness >= 10.0f ? std::numeric_limits<float>::infinity() : sharpness;
}

// What the casting loops share: the scene, the camera's rays and the depth image.
struct ImageCast {
  RTCScene scene;
  rules::f64::CameraFrame frame;
  int width;
  int height;
  float* depth;

  // The unit ray direction through pixel (x, y)'s centre, in Embree's float.
  glm::vec3 direction(int x, int y) const {
    return glm::vec3(rules::f64::camera_ray_direction(frame, x + 0.5, y + 0.5, double(width), double(height)));
  }
  float* pixel(int x, int y) const { return depth + std::size_t(y) * std::size_t(width) + std::size_t(x); }
};

// Rows [row0, row1), one rtcIntersect1 per pixel.
void castPixelRows(const ImageCast& c, RTCIntersectContext& context, int row0, int row1) {
  for (int y = row0; y < row1; ++y)
    for (int x = 0; x < c.width; ++x) {
      const glm::vec3 d = c.direction(x, y);
      RTCRayHit rh{};
      rh.ray.org_x = float(c.frame.eye.x);
      rh.ray.org_y = float(c.frame.eye.y);
      rh.ray.org_z = float(c.frame.eye.z);
      rh.ray.dir_x = d.x;
      rh.ray.dir_y = d.y;
      rh.ray.dir_z = d.z;
      rh.ray.tfar = std::numeric_limits<float>::infinity();
      rh.ray.mask = 0xFFFFFFFFu;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(c.scene, &context, &rh);
      if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) *c.pixel(x, y) = rh.ray.tfar;
    }
}

// Rows [row0, row1) (row0 even), one rtcIntersect8 per 4×2 pixel tile; the
// lanes past the image's right edge or row1 are masked off.
constexpr int kTileWidth = 4;
constexpr int kTileHeight = 2;
static_assert(kTileWidth * kTileHeight == 8, "one RTCRayHit8 per tile");

void castTileRows(const ImageCast& c, RTCIntersectContext& context, int row0, int row1) {
  for (int y0 = row0; y0 < row1; y0 += kTileHeight)
    for (int x0 = 0; x0 < c.width; x0 += kTileWidth) {
      alignas(32) int valid[8];
      alignas(32) RTCRayHit8 rh{};
      for (int lane = 0; lane < 8; ++lane) {
        const int x = x0 + lane % kTileWidth, y = y0 + lane / kTileWidth;
        valid[lane] = x < c.width && y < row1 ? -1 : 0;
        rh.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
        if (!valid[lane]) continue;
        const glm::vec3 d = c.direction(x, y);
        rh.ray.org_x[lane] = float(c.frame.eye.x);
        rh.ray.org_y[lane] = float(c.frame.eye.y);
        rh.ray.org_z[lane] = float(c.frame.eye.z);
        rh.ray.dir_x[lane] = d.x;
        rh.ray.dir_y[lane] = d.y;
        rh.ray.dir_z[lane] = d.z;
        rh.ray.tfar[lane] = std::numeric_limits<float>::infinity();
        rh.ray.mask[lane] = 0xFFFFFFFFu;
      }
      rtcIntersect8(valid, c.scene, &context, &rh);
      for (int lane = 0; lane < 8; ++lane)
        if (valid[lane] && rh.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID)
          *c.pixel(x0 + lane % kTileWidth, y0 + lane / kTileWidth) = rh.ray.tfar[lane];
    }
}

// Fills `depth` (+inf on a miss) by `castRows` on `threads` threads and
// returns the time in ms. Rows are handed out in blocks (whole tiles high) so
// that every thread stays busy whatever part of the image the surface covers.
template <typename CastRows>
double castInRowBlocks(RTCScene scene, int threads, const scene::Camera& camera, int width, int height,
                       std::vector<float>& depth, CastRows castRows) {
  depth.assign(std::size_t(width) * std::size_t(height), std::numeric_limits<float>::infinity());
  const ImageCast image{scene, camera::cameraFrame(camera, width, height), width, height, depth.data()};
  std::atomic<int> nextRow{0};
  constexpr int kRowsPerBlock = 8;
  static_assert(kRowsPerBlock % kTileHeight == 0, "blocks of whole tiles");
  auto work = [&] {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (;;) {
      const int row0 = nextRow.fetch_add(kRowsPerBlock);
      if (row0 >= height) break;
      castRows(image, context, row0, std::min(height, row0 + kRowsPerBlock));
    }
  };
  const double start = nowMs();
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) workers.emplace_back(work);
  for (std::thread& t : workers) t.join();
  return nowMs() - start;
}

}  // namespace

struct EmbreeSubdivision::Handles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  RTCGeometry geometry = nullptr;

  ~Handles() {
    if (geometry) rtcReleaseGeometry(geometry);
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

EmbreeSubdivision::EmbreeSubdivision(const scene::ControlCage& cage, int threads)
    : handles_(std::make_unique<Handles>()), threads_(threads) {
  Handles& h = *handles_;
  h.device = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
  if (!h.device) throw std::runtime_error("rtcNewDevice failed");
  h.scene = rtcNewScene(h.device);
  rtcSetSceneBuildQuality(h.scene, RTC_BUILD_QUALITY_MEDIUM);
  h.geometry = rtcNewGeometry(h.device, RTC_GEOMETRY_TYPE_SUBDIVISION);
  RTCGeometry g = h.geometry;

  auto* faces = newBuffer<unsigned>(g, RTC_BUFFER_TYPE_FACE, RTC_FORMAT_UINT, cage.faceVertexCounts.size());
  std::copy(cage.faceVertexCounts.begin(), cage.faceVertexCounts.end(), faces);
  auto* indices = newBuffer<unsigned>(g, RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT, cage.faceVertexIndices.size());
  std::copy(cage.faceVertexIndices.begin(), cage.faceVertexIndices.end(), indices);
  // Embree reads vertices 16 bytes apart.
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               4 * sizeof(float), cage.positions.size()));
  for (std::size_t i = 0; i < cage.positions.size(); ++i) {
    vertices[4 * i + 0] = float(cage.positions[i].x);
    vertices[4 * i + 1] = float(cage.positions[i].y);
    vertices[4 * i + 2] = float(cage.positions[i].z);
    vertices[4 * i + 3] = 0.0f;
  }
  if (!cage.creases.empty()) {
    auto* pairs = newBuffer<unsigned>(g, RTC_BUFFER_TYPE_EDGE_CREASE_INDEX, RTC_FORMAT_UINT2, cage.creases.size(), 2);
    auto* weights = newBuffer<float>(g, RTC_BUFFER_TYPE_EDGE_CREASE_WEIGHT, RTC_FORMAT_FLOAT, cage.creases.size());
    for (std::size_t i = 0; i < cage.creases.size(); ++i) {
      pairs[2 * i] = unsigned(cage.creases[i].v0);
      pairs[2 * i + 1] = unsigned(cage.creases[i].v1);
      weights[i] = embreeSharpness(cage.creases[i].sharpness);
    }
  }
  if (!cage.corners.empty()) {
    auto* ids = newBuffer<unsigned>(g, RTC_BUFFER_TYPE_VERTEX_CREASE_INDEX, RTC_FORMAT_UINT, cage.corners.size());
    auto* weights = newBuffer<float>(g, RTC_BUFFER_TYPE_VERTEX_CREASE_WEIGHT, RTC_FORMAT_FLOAT, cage.corners.size());
    for (std::size_t i = 0; i < cage.corners.size(); ++i) {
      ids[i] = unsigned(cage.corners[i].vertex);
      weights[i] = embreeSharpness(cage.corners[i].sharpness);
    }
  }
  if (!cage.holes.empty()) {
    auto* holes = newBuffer<unsigned>(g, RTC_BUFFER_TYPE_HOLE, RTC_FORMAT_UINT, cage.holes.size());
    std::copy(cage.holes.begin(), cage.holes.end(), holes);
  }
  switch (cage.options.boundary) {
    case scene::BoundaryInterpolation::None:
      rtcSetGeometrySubdivisionMode(g, 0, RTC_SUBDIVISION_MODE_NO_BOUNDARY);
      break;
    case scene::BoundaryInterpolation::EdgeOnly:
      rtcSetGeometrySubdivisionMode(g, 0, RTC_SUBDIVISION_MODE_SMOOTH_BOUNDARY);
      break;
    case scene::BoundaryInterpolation::EdgeAndCorner:
      rtcSetGeometrySubdivisionMode(g, 0, RTC_SUBDIVISION_MODE_PIN_CORNERS);
      break;
  }
  if (cage.options.creasing != scene::CreasingMethod::Uniform)
    notes_ = "Chaikin creasing not available in Embree (uniform used)";
  rtcAttachGeometryByID(h.scene, g, 0);
}

EmbreeSubdivision::~EmbreeSubdivision() = default;

double EmbreeSubdivision::setTessellationRate(int rate) {
  const double start = nowMs();
  rtcSetGeometryTessellationRate(handles_->geometry, float(rate));
  rtcCommitGeometry(handles_->geometry);
  rtcCommitScene(handles_->scene);
  return nowMs() - start;
}

double EmbreeSubdivision::castPrimary(const scene::Camera& camera, int width, int height,
                                      std::vector<float>& depth) const {
  return castInRowBlocks(handles_->scene, threads_, camera, width, height, depth, castPixelRows);
}

double EmbreeSubdivision::castPrimary8(const scene::Camera& camera, int width, int height,
                                       std::vector<float>& depth) const {
  return castInRowBlocks(handles_->scene, threads_, camera, width, height, depth, castTileRows);
}

}  // namespace facet::peers
