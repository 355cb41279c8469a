// SPDX-License-Identifier: MIT
// tinyobjloader's implementation, compiled into litkit from Debian's header
// (libtinyobjloader-dev), as toml++'s is (the top-level CMakeLists.txt says
// why). The WebAssembly module compiles this same file.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
