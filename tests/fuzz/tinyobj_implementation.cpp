// tinyobjloader's implementation compiled with the fuzz instrumentation (the normal build links
// Debian's shared libtinyobjloader instead; same header, same version 2.0.0rc10, float real_t).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
