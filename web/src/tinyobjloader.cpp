// tinyobjloader's implementation, compiled into the WebAssembly module: the
// native build links Debian's libtinyobjloader, which exists for the host
// only. Same header, same version.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
