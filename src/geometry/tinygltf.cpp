// SPDX-License-Identifier: MIT
// tinygltf's implementation, compiled into litkit from Debian's header
// (libtinygltf-dev, with nlohmann-json3-dev's JSON parser) rather than
// linked from its shared library, as tinyobjloader's is (the top-level
// CMakeLists.txt says why).
#define TINYGLTF_IMPLEMENTATION
#include "geometry/tinygltf.hpp"
