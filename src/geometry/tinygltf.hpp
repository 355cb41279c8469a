// SPDX-License-Identifier: MIT
// tinygltf's header as litkit compiles it everywhere (tinygltf.cpp holds
// its implementation, gltf.cpp uses it): without image decoding or writing,
// which the TinyGLTF class otherwise refers to, and without reading image
// files. litkit reads a glTF file's meshes only, never its images.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
