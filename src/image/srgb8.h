// srgb8: a linear value as the 8-bit sRGB byte a PNG stores, by table lookup. The byte equals
// lround(clamp(srgb_encode(v), 0, 1) · 255) — the reference, which calls pow() — for every float:
// the table holds, for each byte k = 1..255, the smallest float the reference maps to k or above,
// found by bisection over float bit patterns with the reference itself, so the lookup can differ
// from it only where the reference is not monotonic (tests/image/srgb8_test.cpp checks it is not).
// NaN and values ≤ 0 give 0, values ≥ 1 give 255.
#pragma once
#include <cstddef>
#include <cstdint>

namespace rayvec {

std::uint8_t srgb8(float linear);

// srgb8 of `count` pixels of `channels` floats each, three bytes a pixel: the first three
// channels, a missing one as 0.
void srgb8_pixels(const float* linear, int channels, std::size_t count, std::uint8_t* rgb);

// The reference: lround(clamp(srgb_encode(v), 0, 1) · 255), NaN as 0.
std::uint8_t srgb8_reference(float linear);

// The other way, for textures of 8-bit files (texture.h): a table whose entry k is
// srgb_decode(k · (1/255)), 256 floats, so a code decodes to the very float the formula gives.
const float* srgb8_decode_table();

}  // namespace rayvec
