// web_libs.cpp — the implementations of header-only libraries for the browser build.
// The native build links Debian's compiled libstb and libtinygltf instead; this file is compiled
// only for the web (CMakeLists.txt), which is why the defines may live here.
//
// tinygltf includes stb_image_write.h itself (whose implementation section must be seen once):
// the lab's PNG writer (core/image.cpp) uses it. Its image decoder is left out of the page
// (TINYGLTF_NO_STB_IMAGE, set for every file by cmake/web.cmake: the lab installs an image loader
// that skips images, core/gltf.cpp), so stb_image's PNG decoder, compiled here for
// core/image.cpp's readPng, is linked only where something reads a PNG: never in the page.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
