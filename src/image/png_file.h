// PNG files through libpng (png_file.cpp is its only includer).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/image_io.h"

namespace rayvec {

// True when `bytes` start with the PNG signature.
bool has_png_signature(const unsigned char* bytes, std::size_t size);

// Reads a PNG's pixels as stored: 8- or 16-bit, palettes expanded to RGB, a tRNS colour key to alpha;
// channels Y, Y A, R G B or R G B A. The declared size is checked (image_budget.h) before any
// pixel is decoded. Throws InputError naming the file for anything unreadable.
ImageBytes read_png_bytes(const std::string& path);

// read_png_bytes as floats (image_of_bytes: 8-bit values v/255, 16-bit v/65535, still sRGB-encoded).
Image read_png(const std::string& path, bool* sixteen_bit = nullptr);

// Writes row y of an image being encoded: width·3 bytes of 8-bit interleaved RGB into `row`.
using PngRowSource = std::function<void(int y, std::uint8_t* row)>;

// Encodes 8-bit RGB rows as a PNG in memory, with the sRGB chunk and `metadata` as tEXt chunks. The
// rows are asked of `rows` top to bottom into one row's buffer: no whole-image copy of the bytes
// (a fresh buffer of that size costs more in page faults than the encoding of its bytes).
std::vector<std::uint8_t> encode_png_rgb8(int width, int height, const PngRowSource& rows,
                                          const ImageMetadata& metadata);

}  // namespace rayvec
