// SPDX-License-Identifier: MIT
// toml++'s implementation, compiled once into litkit from Debian's headers
// (libtomlplusplus-dev); every other file sees its declarations only
// (TOML_HEADER_ONLY=0, the top-level CMakeLists.txt says why). toml.hpp
// replaces one function of toml++ 3.3.0 (it says why).
#define TOML_IMPLEMENTATION
#include "scene/toml.hpp"
