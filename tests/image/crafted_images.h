// Tiny image files made byte by byte for tests: PNG and EXR headers that declare any size.
#pragma once
#include <cstdint>
#include <string>

namespace rayvec::test {

// PNG's CRC-32 (ISO 3309) of a chunk's type and data.
std::uint32_t png_crc32(const std::string& bytes);

// A PNG of `width`×`height` 8-bit RGB whose IDAT holds only a few bytes (a decompression bomb's
// header, or a truncated file): valid signature, IHDR and CRCs, so only the size is wrong.
std::string png_claiming(std::uint32_t width, std::uint32_t height);

// `exr` (the bytes of a valid scanline EXR) with its dataWindow changed to 0,0 .. width-1,height-1.
std::string exr_claiming(std::string exr, std::int32_t width, std::int32_t height);

}  // namespace rayvec::test
