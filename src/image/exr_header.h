// What the binary checks of an EXR file before the module librayvec_exr.so (exr_module_abi.h) is asked
// to parse it: the magic number, and an attribute walk in plain stdio (exr_header.cpp).
#pragma once
#include <cstddef>
#include <string>

namespace rayvec {

// True when `bytes` start with the OpenEXR magic number.
bool has_exr_magic(const unsigned char* bytes, std::size_t size);

// Walks the attribute list of every header (name, type, int32 size, value) and throws InputError
// naming the file when a value claims more bytes than the file holds or a size OpenEXR's C++ reader
// would not consume, or when a header gives one attribute twice. That reader allocates an attribute of
// unknown type at its declared size before reading it, reads a typed one by its own layout whatever
// the size field says (and then parses the rest of the header out of step), and allocates a preview
// at width x height x 4: one corrupt field in a small file would cost gigabytes. OpenEXRCore skips
// such values unread and so does not catch it. Of a repeated attribute OpenEXRCore keeps the first and
// the C++ reader the last, so the two would disagree on the data window the pixels are written to.
// A tiled header's tile, decoded, must fit the input limit (check_declared_tile_size): the C++ reader
// allocates a buffer of one tile's pixels when it opens the file.
// A file that cannot be opened or is shorter than its version field passes (the module reports it).
void check_exr_attributes(const std::string& path);

}  // namespace rayvec
