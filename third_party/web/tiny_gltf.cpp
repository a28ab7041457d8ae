// What Debian's libtinygltf provides to the desktop build (README.Debian: one unit defines the
// implementation), for the browser build. stb's implementation is in stb.cpp.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
