// JPEG files through libjpeg-turbo (jpeg_file.cpp is its only includer): the texture format of most
// OBJ files in the wild, read without loading OpenImageIO's module and its ~260 shared libraries.
#pragma once
#include <cstddef>
#include <optional>
#include <string>

#include "image/image.h"

namespace rayvec {

// True when `bytes` start with a JPEG start-of-image marker (FF D8 FF).
bool has_jpeg_signature(const unsigned char* bytes, std::size_t size);

// Reads a greyscale (one channel) or colour (three) JPEG's 8-bit codes with libjpeg's default
// decoding (accurate integer IDCT, smooth chroma upsampling), as OpenImageIO decodes it, so the
// pixels are the ones its module gives. Returns nullopt for the colour models it leaves to
// OpenImageIO (CMYK, YCCK, other component counts). The declared size is checked (image_budget.h)
// before any pixel is decoded. Throws InputError naming the file for anything unreadable, a file
// that ends before its image data does, or more than kMaxJpegScans scans.
std::optional<ImageBytes> read_jpeg_bytes(const std::string& path);

// read_jpeg_bytes as floats v/255 (still sRGB-encoded), channels Y or R G B.
std::optional<Image> read_jpeg(const std::string& path);

// Most scans a progressive JPEG may have: a few dozen in real files; thousands of tiny scans make
// a small file cost minutes of decoding (libjpeg-turbo's own limit for hostile input is the same).
inline constexpr int kMaxJpegScans = 500;

}  // namespace rayvec
