// compare_images: the numbers `rayvec compare` prints, for golden-image regression tests.
#pragma once
#include "image/image.h"

namespace rayvec {

struct ImageDifference {
  double rmse = 0;          // root mean square of every colour channel's difference
  double psnr = 0;          // 20·log10(1 / rmse) in dB (peak 1.0); +inf for identical images
  double max_error = 0;     // largest absolute difference of any colour channel of any pixel
  long over_threshold = 0;  // pixels whose largest channel difference exceeds the threshold
  long pixels = 0;
};

// Compares the colour channels (the first three; a one-channel image is used as grey) of two
// images of equal size, as stored (PNG values are compared sRGB-encoded in [0, 1], EXR values
// linear). A NaN in either image counts as an infinite difference. Throws InputError when the
// sizes differ.
ImageDifference compare_images(const Image& a, const Image& b, double pixel_threshold);

}  // namespace rayvec
