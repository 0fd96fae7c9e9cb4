// librayvec_embree.so: the Embree 3 rival of `rayvec bench rays --vs-embree` behind the C interface
// of embree_module_abi.h — the only file that includes Embree.
// Scene: one RTC_GEOMETRY_TYPE_TRIANGLE with the mesh's shared vertices, RTC_BUILD_QUALITY_HIGH
// (Embree's SAH builder with spatial splits), a device with `threads` build threads whose ISA is
// capped at rayvec's (config max_isa), so `--isa avx2` compares against Embree's AVX2 code. Queries:
// rtcIntersect1 per ray, rtcIntersect16 per 4×4 tile, rtcOccluded1 per shadow ray, rtcOccluded16 per
// tile of shadow rays, each with a fresh RTCIntersectContext (coherent flag for the packets), from rayvec's
// own OpenMP threads.
#include <embree3/rtcore.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "bench/embree_module_abi.h"
#include "platform/stopwatch.h"

namespace rayvec {
namespace {

class EmbreeScene {
 public:
  EmbreeScene(const float* vertices, std::size_t vertex_count, const uint32_t* triangles,
              std::size_t triangle_count, int threads, const char* max_isa, double& build_seconds) {
    const std::string config = "threads=" + std::to_string(threads > 0 ? threads : 0) + ",max_isa=" + max_isa;
    device_ = rtcNewDevice(config.c_str());
    if (!device_) throw std::runtime_error("rtcNewDevice failed");
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
    // +1 float of slack: Embree may load 16 bytes at the last vertex
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), vertex_count + 1));
    std::memcpy(v, vertices, vertex_count * 3 * sizeof(float));
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangle_count));
    std::memcpy(idx, triangles, triangle_count * 3 * sizeof(unsigned));
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene_, geom);
    rtcReleaseGeometry(geom);
    const auto t0 = std::chrono::steady_clock::now();
    rtcCommitScene(scene_);
    build_seconds = seconds_since(t0);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
      release();
      throw std::runtime_error("scene build failed");
    }
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene() { release(); }

  void closest(const Ray* rays, Hit* hits, std::size_t n) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (std::size_t i = 0; i < n; ++i) {
      RTCRayHit rh;
      const Ray& r = rays[i];
      rh.ray = RTCRay{r.org.x, r.org.y, r.org.z, r.tmin,      r.dir.x, r.dir.y,
                      r.dir.z, 0.0f,    r.tmax,  0xffffffffu, 0,       0};
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(scene_, &ctx, &rh);
      hits[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID
                    ? Hit{}
                    : Hit{rh.ray.tfar, rh.hit.u, rh.hit.v, int32_t(rh.hit.primID)};
    }
  }

  // The first n of 16 lanes from rays[0..n), the others invalid (a copy of ray 0).
  static void fill_packet(const Ray* rays, std::size_t n, RTCRay16& p, int* valid) {
    for (std::size_t k = 0; k < 16; ++k) {
      const Ray& r = rays[k < n ? k : 0];
      valid[k] = k < n ? -1 : 0;
      p.org_x[k] = r.org.x;
      p.org_y[k] = r.org.y;
      p.org_z[k] = r.org.z;
      p.dir_x[k] = r.dir.x;
      p.dir_y[k] = r.dir.y;
      p.dir_z[k] = r.dir.z;
      p.tnear[k] = r.tmin;
      p.tfar[k] = r.tmax;
      p.time[k] = 0.0f;
      p.mask[k] = 0xffffffffu;
      p.id[k] = unsigned(k);
      p.flags[k] = 0;
    }
  }

  void closest_packet(const Ray* rays, Hit* hits, std::size_t n) const {
    alignas(64) RTCRayHit16 p;
    alignas(64) int valid[16];
    fill_packet(rays, n, p.ray, valid);
    for (std::size_t k = 0; k < 16; ++k) p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect16(valid, scene_, &ctx, &p);
    for (std::size_t k = 0; k < n; ++k)
      hits[k] = p.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID
                    ? Hit{}
                    : Hit{p.ray.tfar[k], p.hit.u[k], p.hit.v[k], int32_t(p.hit.primID[k])};
  }

  void occluded(const Ray* rays, uint8_t* out, std::size_t n) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (std::size_t i = 0; i < n; ++i) {
      const Ray& r = rays[i];
      RTCRay ray{r.org.x, r.org.y, r.org.z, r.tmin,      r.dir.x, r.dir.y,
                 r.dir.z, 0.0f,    r.tmax,  0xffffffffu, 0,       0};
      rtcOccluded1(scene_, &ctx, &ray);
      out[i] = ray.tfar < 0.0f ? 1 : 0;  // Embree sets tfar = -inf on a hit
    }
  }

  void occluded_packet(const Ray* rays, uint8_t* out, std::size_t n) const {
    alignas(64) RTCRay16 p;
    alignas(64) int valid[16];
    fill_packet(rays, n, p, valid);
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcOccluded16(valid, scene_, &ctx, &p);
    for (std::size_t k = 0; k < n; ++k) out[k] = p.tfar[k] < 0.0f ? 1 : 0;
  }

 private:
  void release() {
    if (scene_) rtcReleaseScene(scene_);
    if (device_) rtcReleaseDevice(device_);
    scene_ = nullptr;
    device_ = nullptr;
  }

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

const EmbreeScene& scene_of(void* handle) { return *static_cast<const EmbreeScene*>(handle); }

}  // namespace
}  // namespace rayvec

extern "C" {

__attribute__((visibility("default"))) int rayvec_embree_abi() { return kRayvecEmbreeAbi; }

__attribute__((visibility("default"))) void* rayvec_embree_build(
    const float* vertices, std::size_t vertex_count, const uint32_t* triangles, std::size_t triangle_count,
    int threads, const char* max_isa, double* build_seconds, char* error, std::size_t error_size) {
  try {
    return new rayvec::EmbreeScene(vertices, vertex_count, triangles, triangle_count, threads, max_isa,
                                   *build_seconds);
  } catch (const std::exception& e) {  // std::bad_alloc too
    std::snprintf(error, error_size, "Embree: %s", e.what());
    return nullptr;
  }
}

__attribute__((visibility("default"))) void rayvec_embree_closest(void* scene, const rayvec::Ray* rays,
                                                                  rayvec::Hit* hits, std::size_t n) {
  rayvec::scene_of(scene).closest(rays, hits, n);
}

__attribute__((visibility("default"))) void rayvec_embree_packet(void* scene, const rayvec::Ray* rays,
                                                                 rayvec::Hit* hits, std::size_t n) {
  rayvec::scene_of(scene).closest_packet(rays, hits, n);
}

__attribute__((visibility("default"))) void rayvec_embree_occluded(void* scene, const rayvec::Ray* rays,
                                                                   uint8_t* out, std::size_t n) {
  rayvec::scene_of(scene).occluded(rays, out, n);
}

__attribute__((visibility("default"))) void rayvec_embree_occluded_packet(void* scene,
                                                                          const rayvec::Ray* rays,
                                                                          uint8_t* out, std::size_t n) {
  rayvec::scene_of(scene).occluded_packet(rays, out, n);
}

__attribute__((visibility("default"))) void rayvec_embree_release(void* scene) {
  delete static_cast<rayvec::EmbreeScene*>(scene);
}
}
