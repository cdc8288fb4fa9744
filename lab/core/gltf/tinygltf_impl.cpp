// tinygltf_impl.cpp — tinygltf's implementation, compiled into the native lab from Debian's
// header (libtinygltf-dev), instead of linking Debian's libtinygltf.so.
//
// Why: Debian's libdraco (KHR_draco_mesh_compression, core/gltf/compression.cpp) carries its own
// copy of tinygltf, built with another class layout. With two definitions of tinygltf's symbols
// on the link line, the first one wins, and CMake does not keep the order: the lab crashed in
// ~TinyGLTF. Compiled here, the symbols come from lab_gltf itself, ahead of any library, and
// only draco's codec objects are taken from its static archive. The browser build compiles this
// file too (its stb implementations are core/io/stb_impl.cpp; the native build links libstb).
//
// tinygltf's image functions call stb, whose implementation the native build links from Debian's
// libstb (the lab itself never decodes images through tinygltf: core/gltf/reader.cpp skips them).
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
