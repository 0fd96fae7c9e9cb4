// Checks an image file's declared size before any pixel is decoded, so that a tiny file claiming a
// huge raster (a decompression bomb, or a corrupt header) fails at once with a message naming the
// file, instead of allocating gigabytes and being killed or failing late without the file's name.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace rayvec {

// Bytes `width`×`height` pixels of `channels` float channels take once decoded.
std::size_t decoded_image_bytes(std::int64_t width, std::int64_t height, int channels);

// Throws InputError `path: declares a WxH image ...` when a side is not positive or the decoded
// floats would exceed the input limit (RAYVEC_MAX_INPUT_MB, see io/text_file.h); the message gives
// the size, the need, the limit and how to raise it.
void check_declared_image_size(const std::string& path, std::int64_t width, std::int64_t height,
                               int channels);

// Throws InputError `path: declares tiles of WxH pixels ...` when a tile of `channels` float
// channels, decoded, would exceed the input limit: a tiled EXR reader allocates a whole tile's buffer
// whatever the data window is.
void check_declared_tile_size(const std::string& path, std::int64_t width, std::int64_t height, int channels);

// Throws InputError `path: is a WxH texture ...` when the image, counted as three float channels
// (the unit of the input limit, whatever the texture then keeps: 8-bit codes or floats), grows past
// the limit (a grey or two-channel file passes check_declared_image_size with fewer).
void check_texture_size(const std::string& path, std::int64_t width, std::int64_t height);

// Throws InputError when `raw_bytes` of pixel data cannot have been compressed with DEFLATE into a
// file of `file_bytes` (DEFLATE shrinks at most 1032:1): the header lies or the file is truncated.
// PNG only: EXR has codecs with other bounds and is instead read a strip at a time.
void check_deflate_ratio(const std::string& path, std::int64_t width, std::int64_t height,
                         std::size_t raw_bytes, std::size_t file_bytes);

}  // namespace rayvec
