#include "render/heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>

#include "image/image_io.h"

namespace rayvec {
namespace {

// A 3×5 pixel font for the legend's numbers: five rows of three bits, top row first, leftmost
// pixel the high bit.
struct Glyph {
  char c;
  uint8_t rows[5];
};
constexpr Glyph kGlyphs[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'.', {0, 0, 0, 0, 2}}, {'-', {0, 0, 7, 0, 0}},
    {'+', {0, 2, 7, 2, 0}}, {'e', {0, 7, 7, 4, 7}}, {'l', {6, 2, 2, 2, 7}}, {'o', {0, 7, 5, 5, 7}},
    {'g', {7, 5, 7, 1, 7}},
};
constexpr int kScale = 2;                   // font pixels per glyph pixel
constexpr int kAdvance = 4 * kScale;        // glyph width plus a column of space
constexpr int kMargin = 4, kBarHeight = 8;  // legend layout, in rows and columns

const Glyph* glyph(char c) {
  for (const Glyph& g : kGlyphs)
    if (g.c == c) return &g;
  return nullptr;
}

void put(Image& img, int x, int y, Vec3f linear) {
  if (x < 0 || y < 0 || x >= img.width || y >= img.height) return;
  img.at(x, y, 0) = linear.x;
  img.at(x, y, 1) = linear.y;
  img.at(x, y, 2) = linear.z;
}

void draw_text(Image& img, int x0, int y0, const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const Glyph* g = glyph(text[i]);
    if (!g) continue;
    for (int r = 0; r < 5 * kScale; ++r)
      for (int c = 0; c < 3 * kScale; ++c)
        if (g->rows[r / kScale] >> (2 - c / kScale) & 1)
          put(img, x0 + int(i) * kAdvance + c, y0 + r, {1, 1, 1});
  }
}

Vec3f linear_colour(float f) {
  const Vec3f d = cubehelix(f);
  return {srgb_decode(d.x), srgb_decode(d.y), srgb_decode(d.z)};
}

}  // namespace

Vec3f cubehelix(float f) {
  constexpr float start = 0.5f, rotations = -1.5f, hue = 1.0f;
  const float l = std::clamp(f, 0.0f, 1.0f);
  const float phi = 2.0f * std::numbers::pi_v<float> * (start / 3.0f + rotations * l);
  const float a = hue * l * (1.0f - l) / 2.0f;  // amplitude of the deviation from grey
  const float c = std::cos(phi), s = std::sin(phi);
  auto unit = [](float v) { return std::clamp(v, 0.0f, 1.0f); };
  return {unit(l + a * (-0.14861f * c + 1.78277f * s)), unit(l + a * (-0.29227f * c - 0.90649f * s)),
          unit(l + a * (1.97294f * c))};
}

std::string legend_number(float v) {
  char b[32];
  if (std::fabs(v) < 1e7f && v == std::floor(v))
    std::snprintf(b, sizeof b, "%.0f", double(v));
  else
    std::snprintf(b, sizeof b, "%.4g", double(v));
  return b;
}

Heatmap make_heatmap(const Image& source, int channel, bool log_scale) {
  Heatmap h;
  bool any = false;
  for (int y = 0; y < source.height; ++y)
    for (int x = 0; x < source.width; ++x) {
      const float v = source.at(x, y, channel);
      if (!std::isfinite(v)) continue;
      h.lo = any ? std::min(h.lo, v) : v;
      h.hi = any ? std::max(h.hi, v) : v;
      any = true;
    }
  // position along the bar: linear in v, or in log(1 + v − lo) so that a few costly pixels do not
  // flatten the rest
  auto scale = [&](float v) { return log_scale ? std::log1p(std::max(0.0f, v - h.lo)) : v - h.lo; };
  const float range = h.hi > h.lo ? scale(h.hi) : 1.0f;
  h.image = Image(source.width, source.height + Heatmap::kLegendHeight, {"R", "G", "B"});
  for (int y = 0; y < source.height; ++y)
    for (int x = 0; x < source.width; ++x) {
      const float v = source.at(x, y, channel);
      put(h.image, x, y, std::isfinite(v) ? linear_colour(scale(v) / range) : Vec3f{});
    }
  // legend: a dark strip, the bar from lo (left) to hi (right), the two numbers under its ends
  const int y0 = source.height;
  for (int y = y0; y < h.image.height; ++y)
    for (int x = 0; x < h.image.width; ++x) put(h.image, x, y, {0.01f, 0.01f, 0.01f});
  const int bar_w = std::max(1, source.width - 2 * kMargin);
  for (int y = y0 + kMargin; y < y0 + kMargin + kBarHeight; ++y)
    for (int x = 0; x < bar_w; ++x)
      put(h.image, kMargin + x, y, linear_colour(float(x) / float(std::max(1, bar_w - 1))));
  const int text_y = y0 + 2 * kMargin + kBarHeight;
  const std::string lo = legend_number(h.lo), hi = legend_number(h.hi);
  draw_text(h.image, kMargin, text_y, lo);
  draw_text(h.image, source.width - kMargin - int(hi.size()) * kAdvance + kScale, text_y, hi);
  if (log_scale) draw_text(h.image, source.width / 2 - 3 * kAdvance / 2, text_y, "log");
  return h;
}

}  // namespace rayvec
