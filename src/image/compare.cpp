#include "image/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "io/input_error.h"

namespace rayvec {
namespace {

float colour(const Image& image, int x, int y, int c) {
  return image.at(x, y, image.nchannels() >= 3 ? c : 0);
}

}  // namespace

ImageDifference compare_images(const Image& a, const Image& b, double pixel_threshold) {
  if (a.width != b.width || a.height != b.height)
    throw InputError("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                     " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
  ImageDifference d;
  d.pixels = long(a.width) * a.height;
  double sum_sq = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      double pixel_max = 0;
      for (int c = 0; c < 3; ++c) {
        double diff = std::fabs(double(colour(a, x, y, c)) - double(colour(b, x, y, c)));
        if (std::isnan(diff)) diff = std::numeric_limits<double>::infinity();
        sum_sq += diff * diff;
        pixel_max = std::max(pixel_max, diff);
      }
      d.max_error = std::max(d.max_error, pixel_max);
      if (pixel_max > pixel_threshold) ++d.over_threshold;
    }
  d.rmse = d.pixels ? std::sqrt(sum_sq / (3.0 * double(d.pixels))) : 0.0;
  d.psnr = d.rmse > 0 ? 20.0 * std::log10(1.0 / d.rmse) : std::numeric_limits<double>::infinity();
  return d;
}

}  // namespace rayvec
