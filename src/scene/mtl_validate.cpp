#include "scene/mtl_validate.h"

#include <algorithm>
#include <cstdio>

#include "io/input_error.h"

namespace rayvec {
namespace {

std::string number(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", double(v));
  return text;
}

class Checker {
 public:
  Checker(MtlMaterial& m, const std::string& path, std::vector<std::string>& warnings)
      : m_(m), path_(path), warnings_(warnings) {}

  void warn(std::size_t line, const std::string& what) {
    std::string place = path_;
    if (line) place += ":" + std::to_string(line);
    warnings_.push_back(place + ": material '" + m_.material.name + "': " + what);
  }

  void scalar(float& v, std::size_t line, const char* key, float lo, float hi) {
    if (v >= lo && v <= hi) return;
    const float clamped = std::clamp(v, lo, hi);
    warn(line, std::string("`") + key + " " + number(v) + "` is outside " + number(lo) + ".." + number(hi) +
                   "; using " + number(clamped));
    v = clamped;
  }

  void colour(Vec3f& c, std::size_t line, const char* key, float hi) {
    if (c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x <= hi && c.y <= hi && c.z <= hi) return;
    const Vec3f clamped{std::clamp(c.x, 0.0f, hi), std::clamp(c.y, 0.0f, hi), std::clamp(c.z, 0.0f, hi)};
    warn(line, std::string("`") + key + " " + number(c.x) + " " + number(c.y) + " " + number(c.z) +
                   "` has a component outside 0.." + number(hi) + "; using " + number(clamped.x) + " " +
                   number(clamped.y) + " " + number(clamped.z));
    c = clamped;
  }

 private:
  MtlMaterial& m_;
  const std::string& path_;
  std::vector<std::string>& warnings_;
};

}  // namespace

void validate_mtl_material(MtlMaterial& m, const std::string& path, std::vector<std::string>& warnings) {
  Checker check(m, path, warnings);
  Material& mat = m.material;
  if (!m.illum_text.empty()) {
    check.warn(m.lines.illum, "`illum " + m.illum_text + "` is not an integer; using illum 2 (Blinn–Phong)");
    mat.illum = 2;
  } else if (mat.illum < 0 || mat.illum > 10) {
    check.warn(m.lines.illum, "`illum " + std::to_string(mat.illum) +
                                  "` is not an MTL illumination model (0..10); using illum 2 (Blinn–Phong)");
    mat.illum = 2;
  }
  check.colour(mat.Ka, m.lines.Ka, "Ka", 1.0f);
  check.colour(mat.Kd, m.lines.Kd, "Kd", 1.0f);
  check.colour(mat.Ks, m.lines.Ks, "Ks", 1.0f);
  check.colour(mat.Tf, m.lines.Tf, "Tf", 1.0f);
  check.colour(mat.Ke, m.lines.Ke, "Ke", kMaxEmission);
  check.scalar(mat.Ns, m.lines.Ns, "Ns", 0.0f, kMaxShininess);
  check.scalar(mat.d, m.lines.d, "d", 0.0f, 1.0f);
  // Ni matters to the Fresnel and refraction models only (illum 5, 6, 7).
  if (mat.illum >= 5 && mat.illum <= 7)
    check.scalar(mat.Ni, m.lines.Ni, "Ni", kMinIor, kMaxIor);
  else if (!(mat.Ni >= kMinIor && mat.Ni <= kMaxIor))
    mat.Ni = 1.0f;
}

}  // namespace rayvec
