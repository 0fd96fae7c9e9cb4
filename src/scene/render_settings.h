// RenderSettings: how a scene is rendered. A scene file's "render" block fills the first four
// (scene_json.cpp), `rayvec render` overrides them from its command line and adds the extra output
// channels; render() and the Whitted integrator read them.
#pragma once
#include <string>

namespace rayvec {

struct RenderSettings {
  // Extra EXR channels, from each pixel's first sample: Z (camera-space depth along the view axis,
  // +inf for background), N.x N.y N.z (world shading normal facing the camera, 0 for background),
  // id (triangle id) and object_id (-1 for background). Command line only (--aov).
  // cost.nodes, cost.triangles (BVH nodes whose boxes were tested and triangles tested by all rays
  // of the pixel, every sample, counted by the scalar single-ray traversal) and bounces (the depth of
  // the pixel's deepest reflection/refraction ray, every sample; 0 for background) — the two
  // teaching AOVs.
  struct Aovs {
    bool depth = false, normal = false, id = false, cost = false, bounces = false;
  };
  // Which kinds of secondary rays the integrator may spawn (each still only where a material asks
  // for it). Without shadows every light reaches every point that faces it. Command line only
  // (--effects).
  struct Effects {
    bool shadows = true, reflection = true, refraction = true;
  };

  int max_depth = 8;               // a primary ray is depth 0; reflection/refraction children up to this
  float min_contribution = 0.01f;  // Hall & Greenberg (1983): smallest child weight (max RGB) traced
  int spp = 1;                     // samples per pixel: 1 = the pixel centre; more = stratified
  std::string intersector;         // "" = the command line's default
  Aovs aov;
  Effects effects;
};

}  // namespace rayvec
