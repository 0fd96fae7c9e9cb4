// make_embree_tracer: the Embree rival of `bench rays --vs-embree`, traced through
// librayvec_embree.so, which is loaded on first use (embree_module_abi.h says why it is a module).
// Without Embree at build time there is no module, and the rival is unavailable.
#include <mutex>
#include <string>

#include "bench/embree_module_abi.h"
#include "bench/ray_tracer.h"
#include "geometry/triangle_mesh.h"
#include "io/input_error.h"
#include "platform/plugin.h"

namespace rayvec {
namespace {

#ifdef RAYVEC_HAVE_EMBREE

struct Module {
  RayvecEmbreeBuildFn build = nullptr;
  RayvecEmbreeClosestFn closest = nullptr;
  RayvecEmbreePacketFn packet = nullptr;
  RayvecEmbreeOccludedFn occluded = nullptr;
  RayvecEmbreeOccludedPacketFn occluded_packet = nullptr;
  RayvecEmbreeReleaseFn release = nullptr;
  std::string error;  // why it could not be loaded
};

Module load() {
  Module m;
  const Plugin p = open_plugin("RAYVEC_EMBREE_MODULE", kEmbreeModuleName, /*global=*/false);
  if (!p.handle) {
    m.error = plugin_problem(p, kEmbreeModuleName, "RAYVEC_EMBREE_MODULE");
    return m;
  }
  const auto abi = reinterpret_cast<RayvecEmbreeAbiFn>(plugin_symbol(p, "rayvec_embree_abi"));
  m.build = reinterpret_cast<RayvecEmbreeBuildFn>(plugin_symbol(p, "rayvec_embree_build"));
  m.closest = reinterpret_cast<RayvecEmbreeClosestFn>(plugin_symbol(p, "rayvec_embree_closest"));
  m.packet = reinterpret_cast<RayvecEmbreePacketFn>(plugin_symbol(p, "rayvec_embree_packet"));
  m.occluded = reinterpret_cast<RayvecEmbreeOccludedFn>(plugin_symbol(p, "rayvec_embree_occluded"));
  m.occluded_packet =
      reinterpret_cast<RayvecEmbreeOccludedPacketFn>(plugin_symbol(p, "rayvec_embree_occluded_packet"));
  m.release = reinterpret_cast<RayvecEmbreeReleaseFn>(plugin_symbol(p, "rayvec_embree_release"));
  if (!abi || abi() != kRayvecEmbreeAbi || !m.build || !m.closest || !m.packet || !m.occluded ||
      !m.occluded_packet || !m.release) {
    m.error = p.path + " is not a rayvec " + RAYVEC_VERSION + " Embree module (rebuild rayvec)";
    m.build = nullptr;
  }
  return m;
}

const Module& module() {
  static std::once_flag once;
  static Module* loaded = nullptr;
  std::call_once(once, [] { loaded = new Module(load()); });
  return *loaded;
}

class EmbreeTracer final : public RayTracer {
 public:
  EmbreeTracer(const Module& m, void* scene) : m_(m), scene_(scene) {}
  EmbreeTracer(const EmbreeTracer&) = delete;
  EmbreeTracer& operator=(const EmbreeTracer&) = delete;
  ~EmbreeTracer() override { m_.release(scene_); }
  std::string name() const override { return "embree"; }
  void closest(const Ray* rays, Hit* hits, std::size_t n) const override {
    m_.closest(scene_, rays, hits, n);
  }
  void closest_packet(const Ray* rays, Hit* hits, std::size_t n) const override {
    m_.packet(scene_, rays, hits, n);
  }
  void occluded(const Ray* rays, uint8_t* out, std::size_t n) const override {
    m_.occluded(scene_, rays, out, n);
  }
  void occluded_packet(const Ray* rays, uint8_t* out, std::size_t n) const override {
    m_.occluded_packet(scene_, rays, out, n);
  }

 private:
  const Module& m_;
  void* scene_;
};

#endif

}  // namespace

std::string embree_unavailable_reason() {
#ifdef RAYVEC_HAVE_EMBREE
  return module().build ? std::string() : module().error;
#else
  return "this rayvec was built without Embree 3 (install libembree-dev and re-run CMake)";
#endif
}

bool embree_available() { return embree_unavailable_reason().empty(); }

bool embree_built() {
#ifdef RAYVEC_HAVE_EMBREE
  return true;
#else
  return false;
#endif
}

std::unique_ptr<RayTracer> make_embree_tracer(const TriangleMesh& mesh, int threads, const char* max_isa,
                                              double& build_seconds) {
  build_seconds = 0;
#ifdef RAYVEC_HAVE_EMBREE
  const Module& m = module();
  if (!m.build) throw RuntimeError("Embree: " + m.error);
  static_assert(sizeof(Vec3f) == 3 * sizeof(float) && sizeof(mesh.triangles[0]) == 3 * sizeof(uint32_t));
  char error[512] = "";
  void* scene = m.build(reinterpret_cast<const float*>(mesh.positions.data()), mesh.positions.size(),
                        reinterpret_cast<const uint32_t*>(mesh.triangles.data()), mesh.size(), threads,
                        max_isa, &build_seconds, error, sizeof error);
  if (!scene) throw RuntimeError(error);
  return std::make_unique<EmbreeTracer>(m, scene);
#else
  (void)mesh, (void)threads, (void)max_isa;
  return nullptr;
#endif
}

}  // namespace rayvec
