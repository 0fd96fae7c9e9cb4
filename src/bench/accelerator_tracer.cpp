// RayTracer over rayvec's Accelerator (see ray_tracer.h).
#include "accel/accelerator.h"
#include "bench/ray_tracer.h"

namespace rayvec {
namespace {

class AcceleratorTracer final : public RayTracer {
 public:
  explicit AcceleratorTracer(const Accelerator& accel) : accel_(accel) {}
  std::string name() const override { return "rayvec"; }
  void closest(const Ray* rays, Hit* hits, std::size_t n) const override {
    for (std::size_t i = 0; i < n; ++i) hits[i] = accel_.closest(rays[i]);
  }
  void closest_packet(const Ray* rays, Hit* hits, std::size_t n) const override {
    accel_.closest_stream(rays, hits, n);
  }
  void occluded(const Ray* rays, uint8_t* out, std::size_t n) const override {
    for (std::size_t i = 0; i < n; ++i) out[i] = accel_.occluded(rays[i]) ? 1 : 0;
  }
  void occluded_packet(const Ray* rays, uint8_t* out, std::size_t n) const override {
    accel_.occluded_stream(rays, out, n);
  }

 private:
  const Accelerator& accel_;
};

}  // namespace

std::unique_ptr<RayTracer> make_accelerator_tracer(const Accelerator& accel) {
  return std::make_unique<AcceleratorTracer>(accel);
}

}  // namespace rayvec
