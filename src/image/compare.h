// compare_images: the numbers `rayvec compare` prints, for golden-image regression tests.
#pragma once
#include <string>
#include <vector>

#include "image/image.h"

namespace rayvec {

struct ImageDifference {
  double rmse = 0;          // root mean square of every colour channel's difference
  double psnr = 0;          // 20·log10(1 / rmse) in dB (peak 1.0); +inf for identical images
  double max_error = 0;     // largest absolute difference of any colour channel of any pixel
  long over_threshold = 0;  // pixels whose largest channel difference exceeds the threshold
  long pixels = 0;
  std::vector<float> pixel_max;  // per pixel (row-major): the largest colour channel difference

  // Pixels whose largest channel difference exceeds `threshold`, and that as a percentage.
  long count_over(double threshold) const;
  double percent_over(double threshold) const;
};

// Compares the colour channels (the first three; a one-channel image is used as grey) of two
// images of equal size, as given (see to_srgb_encoded for putting a linear and an encoded image
// into one space first). A NaN in either image counts as an infinite difference. Throws InputError
// when the sizes differ.
ImageDifference compare_images(const Image& a, const Image& b, double pixel_threshold);

// The colour channels of a linear image as a PNG would store them: sRGB-encoded, clamped to [0, 1]
// (NaN as 0), without the 8-bit rounding; other channels unchanged.
Image to_srgb_encoded(const Image& linear);

enum class DiffMode { abs, scaled, falsecolor };

// A difference image of the colour channels, linear RGB (write_image encodes it for a PNG):
//   abs        |a - b| per channel;
//   scaled     |a - b| * scale per channel (scale <= 0: 1 / the largest difference, so the largest
//              difference is white);
//   falsecolor each pixel's largest channel difference over `threshold` -> a colour ramp: black
//              (equal), blue, cyan, green, yellow (at the threshold), red (2x the threshold or more).
Image difference_image(const Image& a, const Image& b, DiffMode mode, double scale, double threshold);

}  // namespace rayvec
