// Image files. Written:
//   .exr — linear float, every channel of the Image (R G B and any AOVs), plus metadata.
//   .png — the first three channels, sRGB-encoded (IEC 61966-2-1), 8 bits, clamped to [0, 1].
// Read: PNG (libpng) and JPEG (libjpeg) directly and EXR through OpenEXR in a module loaded on first
// use (exr_file.h), told by their first bytes; any other format OpenImageIO knows (and CMYK JPEGs)
// through another such module (oiio_module.h). Every reader checks the declared size before
// decoding (image_budget.h).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "image/texture.h"

namespace rayvec {

// Free-form key/value pairs stored in the file header (EXR attributes, PNG text chunks),
// e.g. {"rayvec:scene", "scenes/whitted.json"}.
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

// True for the extensions write_image accepts (".exr", ".png", any case).
bool is_writable_image_path(const std::string& path);

// Writes `image` atomically: the encoded file is assembled in memory and goes through AtomicFile
// (temporary in the same directory, renamed on success), so a failure never leaves a partial file.
// Throws InputError (exit 2) for an extension other than .exr/.png, RuntimeError when writing fails.
void write_image(const std::string& path, const Image& image, const ImageMetadata& metadata = {});

// Loads what write_image will need for `path` (the EXR module for .exr), so that a command whose
// output comes after long work fails before it: throws RuntimeError naming a module that is missing.
void require_image_writer(const std::string& path);

// Reads any format OpenImageIO knows, every channel as float as stored (8-bit PNG values become
// v/255, still sRGB-encoded; EXR values are linear). Throws InputError naming the file for a
// missing, unreadable or oversized one. `encoded`, when given, is set for integer pixel formats
// (PNG, 8/16-bit files: sRGB-encoded values) and cleared for float ones (EXR, HDR: linear).
Image read_image(const std::string& path);
Image read_image(const std::string& path, bool* encoded);

// Reads a texture as linear RGB (texture.h): 8- and 16-bit files are taken as sRGB-encoded, float
// files (EXR, HDR) as linear; grey images are widened to RGB and alpha is dropped. Three floats a
// texel count against the input limit (image_budget.h), whatever the file stores.
Texture read_texture(const std::string& path);

// sRGB transfer functions (IEC 61966-2-1).
float srgb_encode(float linear);
float srgb_decode(float encoded);

}  // namespace rayvec
