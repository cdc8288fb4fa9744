// web_libs.cpp — the implementations of header-only libraries for the browser build.
// The native build links Debian's compiled libstb and libtinygltf instead; this file is compiled
// only for the web (CMakeLists.txt), which is why the defines may live here.
//
// tinygltf includes stb_image.h and stb_image_write.h itself (whose implementation sections must
// be seen once), so it brings both: the lab's PNG code (core/image.cpp) uses them, and the lab
// installs its own file-system callbacks and an image loader that skips images (core/gltf.cpp).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
