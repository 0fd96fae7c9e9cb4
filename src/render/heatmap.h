// Heatmaps: one channel of an image in false colour with a legend strip below it — a bar running
// from the smallest to the largest value and those two numbers written under its ends — for the
// cost and bounces AOVs (`rayvec render --aov cost,bounces --heatmap`). The colour map is
// cubehelix (Green 2011), computed from its definition: brightness rises monotonically from black
// to white while the hue turns, so the map reads correctly in grey too.
#pragma once
#include <string>

#include "image/image.h"
#include "math/vec3.h"

namespace rayvec {

// Cubehelix at fraction f in [0, 1] (clamped) with Green's default parameters (start 0.5,
// rotations −1.5, hue 1, gamma 1), as display (sRGB-encoded) values in [0, 1].
Vec3f cubehelix(float f);

struct Heatmap {
  Image image;           // linear RGB (write_image encodes it as sRGB for a PNG)
  float lo = 0, hi = 0;  // the channel's range over the finite pixels, as the legend shows it
  static constexpr int kLegendHeight = 30;  // rows added under the picture
};

// `channel` of `source` (an index into source.channels) mapped from [lo, hi] onto cubehelix, the
// legend strip appended below; the picture keeps source's size and orientation. With `log_scale`
// the colour follows log(1 + v − lo) (the legend then reads "log" between its ends): costs span
// orders of magnitude, and a linear map would show only the most costly pixels.
Heatmap make_heatmap(const Image& source, int channel, bool log_scale = false);

// The legend's numbers: integers as integers, others with 4 significant digits.
std::string legend_number(float v);

}  // namespace rayvec
