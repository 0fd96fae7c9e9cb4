#include "render/ray_tree_format.h"

#include <cmath>
#include <cstdio>

#include "io/json_string.h"

namespace rayvec {
namespace {

// Text: 4 significant digits are what a reader compares; JSON: %.9g round-trips a float.
std::string num(float v, const char* fmt = "%.4g") {
  if (!std::isfinite(v)) return v > 0 ? "inf" : (v < 0 ? "-inf" : "nan");
  char b[32];
  std::snprintf(b, sizeof b, fmt, double(v));
  return b;
}
std::string vec(Vec3f v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }
std::string jnum(float v) { return std::isfinite(v) ? num(v, "%.9g") : "null"; }
std::string jvec(Vec3f v) { return "[" + jnum(v.x) + ", " + jnum(v.y) + ", " + jnum(v.z) + "]"; }

const char* reason_text(SkipReason r) {
  switch (r) {
    case SkipReason::max_depth: return "max depth reached";
    case SkipReason::contribution_cutoff: return "contribution below the cutoff";
    case SkipReason::total_internal_reflection: return "total internal reflection";
    case SkipReason::effect_off: return "switched off (--effects)";
  }
  return "?";
}

std::string hit_text(const RayNode& n, const Scene& scene) {
  const std::string what = "triangle " + std::to_string(n.hit.tri) + " of object " +
                           std::to_string(n.object) + ", material \"" + scene.materials[n.material].name +
                           "\", t = " + num(n.hit.t);
  return what;
}

void text_node(const RayNode& n, const Scene& scene, int indent, std::string& out) {
  const std::string pad(std::size_t(indent), ' '), in = pad + "  ";
  const std::string cost =
      "BVH: " + std::to_string(n.cost.nodes) + " nodes, " + std::to_string(n.cost.triangles) + " triangles";
  if (n.kind == RayKind::shadow) {
    out += pad + "shadow ray to light " + std::to_string(n.light) + ": ";
    out += n.blocked ? "blocked by " + hit_text(n, scene) : "reaches the light, adds " + vec(n.lit);
    out += "  [" + cost + "]\n";
    out += in + "origin " + vec(n.ray.org) + "  direction " + vec(n.ray.dir) + "\n";
    return;
  }
  out += pad + ray_kind_name(n.kind) + " ray, depth " + std::to_string(n.depth) + ", weight " + num(n.weight);
  if (n.kind != RayKind::camera) out += ", factor " + vec(n.factor);
  out += "\n" + in + "origin " + vec(n.ray.org) + "  direction " + vec(n.ray.dir) + "\n";
  if (n.hit.hit())
    out += in + "hits " + hit_text(n, scene) + "  [" + cost + "]\n";
  else
    out += in + "misses everything: background " + vec(n.local) + "  [" + cost + "]\n";
  if (n.hit.hit()) out += in + "local light " + vec(n.local) + "\n";
  for (const RayNode& c : n.children) text_node(c, scene, indent + 2, out);
  for (const SkippedRay& s : n.skipped)
    out += in + ray_kind_name(s.kind) + " ray not traced: " + reason_text(s.reason) + " (weight " +
           num(s.weight) + ")\n";
  std::string why;
  for (const std::string& r : n.stop_reasons(scene)) why += (why.empty() ? "" : ", ") + r;
  out += in + "stops: " + why + "; returns " + vec(n.radiance) + ", adds " + vec(n.contribution()) +
         " to the pixel\n";
}

void json_node(const RayNode& n, const Scene& scene, int indent, std::string& out) {
  const std::string pad(std::size_t(indent), ' '), in = pad + "  ";
  out += "{\n" + in + "\"kind\": \"" + ray_kind_name(n.kind) + "\",\n";
  out += in + "\"depth\": " + std::to_string(n.depth) + ", \"weight\": " + jnum(n.weight) +
         ", \"factor\": " + jvec(n.factor) + ", \"throughput\": " + jvec(n.throughput) + ",\n";
  out += in + "\"origin\": " + jvec(n.ray.org) + ", \"direction\": " + jvec(n.ray.dir) +
         ", \"tmax\": " + jnum(n.ray.tmax) + ",\n";
  if (n.hit.hit())
    out += in + "\"hit\": {\"triangle\": " + std::to_string(n.hit.tri) +
           ", \"object\": " + std::to_string(n.object) + ", \"material\": " + std::to_string(n.material) +
           ", \"material_name\": " + json_string(scene.materials[n.material].name) +
           ", \"t\": " + jnum(n.hit.t) + "},\n";
  else
    out += in + "\"hit\": null,\n";
  out += in + "\"cost\": {\"nodes\": " + std::to_string(n.cost.nodes) +
         ", \"triangles\": " + std::to_string(n.cost.triangles) + "},\n";
  if (n.kind == RayKind::shadow) {
    out += in + "\"light\": " + std::to_string(n.light) + ", \"blocked\": " + (n.blocked ? "true" : "false") +
           ", \"lit\": " + jvec(n.lit) + ",\n";
  } else {
    out += in + "\"local\": " + jvec(n.local) + ", \"radiance\": " + jvec(n.radiance) +
           ", \"contribution\": " + jvec(n.contribution()) + ",\n";
  }
  std::string why;
  for (const std::string& r : n.stop_reasons(scene)) why += (why.empty() ? "\"" : ", \"") + r + "\"";
  out += in + "\"stop\": [" + why + "],\n";
  out += in + "\"skipped\": [";
  for (std::size_t i = 0; i < n.skipped.size(); ++i)
    out += std::string(i ? ", " : "") + "{\"kind\": \"" + ray_kind_name(n.skipped[i].kind) +
           "\", \"reason\": \"" + skip_reason_name(n.skipped[i].reason) +
           "\", \"weight\": " + jnum(n.skipped[i].weight) + "}";
  out += "],\n" + in + "\"children\": [";
  for (std::size_t i = 0; i < n.children.size(); ++i) {
    out += i ? ", " : "";
    json_node(n.children[i], scene, indent + 2, out);
  }
  out += "]\n" + pad + "}";
}

std::string effects_text(const RenderSettings::Effects& e) {
  std::string s;
  if (e.shadows) s += "shadows";
  if (e.reflection) s += std::string(s.empty() ? "" : ",") + "reflection";
  if (e.refraction) s += std::string(s.empty() ? "" : ",") + "refraction";
  return s.empty() ? "none" : s;
}

}  // namespace

std::string ray_tree_text(const PixelTrace& t, const Scene& scene) {
  std::string out = "pixel (" + std::to_string(t.x) + ", " + std::to_string(t.y) + "), sample " +
                    std::to_string(t.sample) + " of " + std::to_string(t.spp) + " at image position (" +
                    num(t.px) + ", " + num(t.py) + "); max_depth " + std::to_string(t.max_depth) +
                    ", min_contribution " + num(t.min_contribution) + ", effects " + effects_text(t.effects) +
                    "\n";
  text_node(t.root, scene, 0, out);
  out += "sample radiance " + vec(t.sample_radiance) + "; pixel value (mean of " + std::to_string(t.spp) +
         " sample" + (t.spp == 1 ? "" : "s") + ") " + vec(t.pixel) + "\n";
  return out;
}

std::string ray_tree_json(const PixelTrace& t, const Scene& scene) {
  std::string out = "{\n  \"pixel\": [" + std::to_string(t.x) + ", " + std::to_string(t.y) +
                    "], \"sample\": " + std::to_string(t.sample) + ", \"spp\": " + std::to_string(t.spp) +
                    ", \"position\": [" + jnum(t.px) + ", " + jnum(t.py) + "],\n";
  out += "  \"max_depth\": " + std::to_string(t.max_depth) +
         ", \"min_contribution\": " + jnum(t.min_contribution) + ", \"effects\": \"" +
         effects_text(t.effects) + "\",\n";
  out += "  \"sample_radiance\": " + jvec(t.sample_radiance) + ", \"pixel_value\": " + jvec(t.pixel) + ",\n";
  out += "  \"ray\": ";
  json_node(t.root, scene, 2, out);
  out += "\n}\n";
  return out;
}

}  // namespace rayvec
