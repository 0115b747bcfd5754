#include "benchmarks/incoherent/embree_triangles.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>
#include <thread>

#include "benchmarks/wall_clock.h"

namespace facet::benchmarks::incoherent {

struct EmbreeTriangles::Handles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
};

EmbreeTriangles::EmbreeTriangles(const std::vector<ceiling::Triangle>& tris, int threads)
    : handles_(std::make_unique<Handles>()), threads_(threads) {
  Handles& h = *handles_;
  h.device = rtcNewDevice(("threads=" + std::to_string(threads)).c_str());
  if (!h.device) throw std::runtime_error("rtcNewDevice failed");
  const double start = nowMs();
  h.scene = rtcNewScene(h.device);
  RTCGeometry geometry = rtcNewGeometry(h.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                               3 * sizeof(float), 3 * tris.size()));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), tris.size()));
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const glm::vec3* corners[3] = {&tris[i].a, &tris[i].b, &tris[i].c};
    for (int c = 0; c < 3; ++c) {
      for (int axis = 0; axis < 3; ++axis) vertices[9 * i + 3 * c + axis] = (*corners[c])[axis];
      indices[3 * i + c] = unsigned(3 * i + c);
    }
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(h.scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(h.scene);
  commitMs_ = nowMs() - start;
}

EmbreeTriangles::~EmbreeTriangles() {
  if (handles_->scene) rtcReleaseScene(handles_->scene);
  if (handles_->device) rtcReleaseDevice(handles_->device);
}

Traced EmbreeTriangles::trace(const std::vector<Ray>& rays) const {
  Traced out;
  out.t.assign(rays.size(), kMiss);
  // Blocks of consecutive rays taken by whichever thread is free, so both
  // stay busy whatever the rays cost.
  constexpr std::size_t kBlock = 256;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    for (std::size_t first; (first = next.fetch_add(kBlock)) < rays.size();) {
      for (std::size_t i = first, end = std::min(rays.size(), first + kBlock); i < end; ++i) {
        const Ray& r = rays[i];
        RTCRayHit rh{};
        rh.ray.org_x = r.originX, rh.ray.org_y = r.originY, rh.ray.org_z = r.originZ, rh.ray.tnear = r.tMin;
        rh.ray.dir_x = r.directionX, rh.ray.dir_y = r.directionY, rh.ray.dir_z = r.directionZ, rh.ray.tfar = r.tMax;
        rh.ray.mask = ~0u;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(handles_->scene, &context, &rh);
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) out.t[i] = rh.ray.tfar;
      }
    }
  };
  const double start = nowMs();
  std::vector<std::thread> workers;
  for (int t = 0; t < threads_; ++t) workers.emplace_back(work);
  for (std::thread& t : workers) t.join();
  out.ms = nowMs() - start;
  return out;
}

}  // namespace facet::benchmarks::incoherent
