// PNG files read through libpng (png_file.cpp is its only includer); written by png_encoder.h.
#pragma once
#include <cstdint>
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

}  // namespace rayvec
