// OpenEXR pixels through the OpenEXR C++ library (exr_file.cpp is its only includer).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/image_io.h"

namespace rayvec {

// Reads the first part of a flat (not deep) EXR as float channels, linear as stored. The header is
// checked (image_budget.h) before any pixel is decoded, and pixels are read a strip of scanlines at
// a time, so a file whose header promises more than it holds fails after a strip, not after
// allocating the whole raster. Channel order: each layer's R G B A Z first, then the rest
// alphabetically; unlayered channels before layered ones (R G B Z id N.x N.y N.z), as
// OpenImageIO orders them. Throws InputError naming the file.
Image read_exr(const std::string& path);

// Encodes every channel of `image` as 32-bit float, ZIP-compressed scanlines, with `metadata` as
// string attributes.
std::vector<std::uint8_t> encode_exr(const Image& image, const ImageMetadata& metadata);

}  // namespace rayvec
