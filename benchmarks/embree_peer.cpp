#include "benchmarks/embree_peer.h"

#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <thread>

#include "engine/camera.hpp"

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
  depth.assign(std::size_t(width) * std::size_t(height), std::numeric_limits<float>::infinity());
  const camera::CameraFrame frame = camera::cameraFrame(camera, width, height);
  RTCScene scene = handles_->scene;
  // Rows are handed out in blocks so that both threads stay busy whatever
  // part of the image the surface covers.
  std::atomic<int> nextRow{0};
  constexpr int kRowsPerBlock = 8;
  auto work = [&] {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (;;) {
      const int row0 = nextRow.fetch_add(kRowsPerBlock);
      if (row0 >= height) break;
      for (int y = row0; y < std::min(height, row0 + kRowsPerBlock); ++y)
        for (int x = 0; x < width; ++x) {
          const glm::dvec3 d = camera::camera_ray_direction(frame, x + 0.5, y + 0.5, double(width), double(height));
          RTCRayHit rh{};
          rh.ray.org_x = float(camera.eye.x);
          rh.ray.org_y = float(camera.eye.y);
          rh.ray.org_z = float(camera.eye.z);
          rh.ray.dir_x = float(d.x);
          rh.ray.dir_y = float(d.y);
          rh.ray.dir_z = float(d.z);
          rh.ray.tfar = std::numeric_limits<float>::infinity();
          rh.ray.mask = 0xFFFFFFFFu;
          rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
          rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
          rtcIntersect1(scene, &context, &rh);
          if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) depth[std::size_t(y) * std::size_t(width) + x] = rh.ray.tfar;
        }
    }
  };
  const double start = nowMs();
  std::vector<std::thread> workers;
  for (int t = 0; t < threads_; ++t) workers.emplace_back(work);
  for (std::thread& t : workers) t.join();
  return nowMs() - start;
}

}  // namespace facet::peers
