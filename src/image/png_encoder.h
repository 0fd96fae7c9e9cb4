// PNG encoding: 8-bit RGB rows into a PNG file's bytes, the image data deflated in bands of rows on
// every thread (zlib; png_encoder.cpp is its only includer). Reading stays with libpng (png_file.h).
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/image_io.h"

namespace rayvec {

// Writes row y of an image being encoded: width·3 bytes of 8-bit interleaved RGB into `row`. Called
// from several threads at once, each time for another y.
using PngRowSource = std::function<void(int y, std::uint8_t* row)>;

// Rows a band of an image `width` pixels wide holds: enough that a band's own deflate dictionary,
// started empty, costs a few percent of size at most (at least 256 KiB of row bytes).
int png_band_rows(int width);

// Encodes 8-bit RGB rows as a PNG in memory: no row filter, zlib level 1, the sRGB, gAMA and cHRM
// chunks, then `metadata` as tEXt chunks (keys of 1 to 79 printable Latin-1 characters; a text ends
// at its first NUL). The image is cut into bands of png_band_rows rows, each deflated on its own
// on the calling OpenMP team's threads and ended by a sync flush, so the bands join into one zlib
// stream (their Adler-32 sums combined): the bytes do not depend on the thread count. Each thread
// asks `rows` for one row at a time into one row's buffer: no whole-image copy of the bytes. Throws
// RuntimeError when a key is not a PNG keyword or memory runs out.
std::vector<std::uint8_t> encode_png_rgb8(int width, int height, const PngRowSource& rows,
                                          const ImageMetadata& metadata);

}  // namespace rayvec
