#include "image/compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "image/image_io.h"
#include "io/input_error.h"

namespace rayvec {
namespace {

float colour(const Image& image, int x, int y, int c) {
  return image.at(x, y, image.nchannels() >= 3 ? c : 0);
}

double channel_diff(const Image& a, const Image& b, int x, int y, int c) {
  const double diff = std::fabs(double(colour(a, x, y, c)) - double(colour(b, x, y, c)));
  return std::isnan(diff) ? std::numeric_limits<double>::infinity() : diff;
}

void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw InputError("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                     " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
}

// The false-colour ramp in display (sRGB-encoded) values, t in [0, 1].
std::array<float, 3> ramp(double t) {
  static const float kStops[6][3] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}};
  t = std::clamp(std::isnan(t) ? 1.0 : t, 0.0, 1.0) * 5.0;
  const int i = std::min(4, int(t));
  const float f = float(t - i);
  std::array<float, 3> rgb{};
  for (int c = 0; c < 3; ++c) rgb[c] = kStops[i][c] + f * (kStops[i + 1][c] - kStops[i][c]);
  return rgb;
}

}  // namespace

long ImageDifference::count_over(double threshold) const {
  return long(std::count_if(pixel_max.begin(), pixel_max.end(), [&](float d) { return !(d <= threshold); }));
}

double ImageDifference::percent_over(double threshold) const {
  return pixels ? 100.0 * double(count_over(threshold)) / double(pixels) : 0.0;
}

ImageDifference compare_images(const Image& a, const Image& b, double pixel_threshold) {
  check_sizes(a, b);
  ImageDifference d;
  d.pixels = long(a.width) * a.height;
  d.pixel_max.resize(std::size_t(d.pixels));
  double sum_sq = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      double pixel_max = 0;
      for (int c = 0; c < 3; ++c) {
        const double diff = channel_diff(a, b, x, y, c);
        sum_sq += diff * diff;
        pixel_max = std::max(pixel_max, diff);
      }
      d.pixel_max[std::size_t(y) * a.width + x] = float(pixel_max);
      d.max_error = std::max(d.max_error, pixel_max);
    }
  d.over_threshold = d.count_over(pixel_threshold);
  d.rmse = d.pixels ? std::sqrt(sum_sq / (3.0 * double(d.pixels))) : 0.0;
  d.psnr = d.rmse > 0 ? 20.0 * std::log10(1.0 / d.rmse) : std::numeric_limits<double>::infinity();
  return d;
}

Image to_srgb_encoded(const Image& linear) {
  Image out = linear;
  const int n = out.nchannels(), colours = std::min(3, n);
  for (std::size_t p = 0; p < std::size_t(out.width) * out.height; ++p)
    for (int c = 0; c < colours; ++c) {
      float& v = out.pixels[p * n + c];
      v = std::isnan(v) ? 0.0f : std::clamp(srgb_encode(v), 0.0f, 1.0f);
    }
  return out;
}

Image difference_image(const Image& a, const Image& b, DiffMode mode, double scale, double threshold) {
  check_sizes(a, b);
  Image out(a.width, a.height, {"R", "G", "B"});
  if (mode == DiffMode::scaled && !(scale > 0)) {
    double largest = 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x)
        for (int c = 0; c < 3; ++c) {
          const double d = channel_diff(a, b, x, y, c);
          if (std::isfinite(d)) largest = std::max(largest, d);
        }
    scale = largest > 0 ? 1.0 / largest : 1.0;
  }
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (mode == DiffMode::falsecolor) {
        double m = 0;
        for (int c = 0; c < 3; ++c) m = std::max(m, channel_diff(a, b, x, y, c));
        // 0 black; just above 0 blue; the threshold yellow; twice the threshold and more red.
        const double r = threshold > 0 ? m / threshold : (m > 0 ? 2.0 : 0.0);
        const auto rgb = ramp(m <= 0 ? 0.0 : r <= 1 ? 0.2 + 0.6 * r : 0.8 + 0.2 * (r - 1.0));
        for (int c = 0; c < 3; ++c) out.at(x, y, c) = srgb_decode(rgb[c]);
        continue;
      }
      for (int c = 0; c < 3; ++c) {
        const double d = channel_diff(a, b, x, y, c) * (mode == DiffMode::scaled ? scale : 1.0);
        out.at(x, y, c) = std::isfinite(d) ? float(d) : 1.0f;
      }
    }
  return out;
}

}  // namespace rayvec
