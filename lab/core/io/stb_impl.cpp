// stb_impl.cpp — stb_image's and stb_image_write's implementations, for the browser build only
// (the native build links Debian's libstb, which has them compiled; lab/core/io/CMakeLists.txt).
//
// PNG only: core/io/image.cpp's readPng is linked only where something reads a PNG, never in the
// page; encodePng's writer is. tinygltf's image decoder is left out of the page altogether
// (TINYGLTF_NO_STB_IMAGE, cmake/web.cmake), and its writer functions use this stb_image_write.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#include <stb_image_write.h>
