# web.cmake — what the browser build (emcmake cmake, Debian's Emscripten 3.1.6) needs instead of
# find_package: Debian's header-only libraries through a folder of links (never -I/usr/include,
# which would bring glibc's headers), Dear ImGui compiled from Debian's source package, and the
# link options of the page, and the glTF decoders (meshoptimizer, Draco) and the QR code encoder
# (libqrencode) compiled from Debian's source packages. Included from CMakeLists.txt when EMSCRIPTEN
# is set.

# Link-time optimization for the whole page: every target below (the lab's, Dear ImGui, the glTF
# decoders, libqrencode) is compiled to LLVM bitcode and optimized once at the link, so code that
# only one side of a library boundary needs (unused virtuals, template copies) goes. About 17 KB less
# gzip-compressed lab.wasm at the same -Os (measured by a helper, issue 27: exercises, links and
# libqrencode had taken the page to 0.664 MB); the code generated is the same optimizer's at -Os.
add_compile_options(-flto)
add_link_options(-flto)
# No run-time type information in the page: the lab asks for none (no dynamic_cast, no typeid), and
# the names of every std::function's lambda type went into lab.wasm: 2.1 KB less gzip (issue 40).
# Exceptions still match their types: the compiler keeps the type information a catch needs.
add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-fno-rtti>)

# GLM, nlohmann-json, stb and tinygltf headers, and nothing else from /usr/include.
set(LAB_WEB_INCLUDE "${CMAKE_BINARY_DIR}/web-include")
file(MAKE_DIRECTORY "${LAB_WEB_INCLUDE}")
foreach(link glm nlohmann tiny_gltf.h)
  file(CREATE_LINK "/usr/include/${link}" "${LAB_WEB_INCLUDE}/${link}" SYMBOLIC)
endforeach()
foreach(header stb_image.h stb_image_write.h stb_truetype.h stb_rect_pack.h stb_easy_font.h)
  file(CREATE_LINK "/usr/include/stb/${header}" "${LAB_WEB_INCLUDE}/${header}" SYMBOLIC)
endforeach()
add_library(lab_web_headers INTERFACE)
target_include_directories(lab_web_headers SYSTEM INTERFACE "${LAB_WEB_INCLUDE}")
# Exceptions carry nlohmann-json's parse errors to the preset validator; wasm exceptions are
# native in every browser with WebGL2.
target_compile_options(lab_web_headers INTERFACE -fwasm-exceptions)
target_link_options(lab_web_headers INTERFACE -fwasm-exceptions)

# Sources that Debian ships only in source packages, fetched at the version of the installed -dev
# package (tools/fetch-debian-source) and cached in the build folder: lab_fetch_source(VAR SOURCE
# BINARY FILE) sets the cache path VAR unless it is set already, and checks FILE is in it.
function(lab_fetch_source var source binary file)
  set(${var} "" CACHE PATH "${source} sources (fetched from Debian's source package when empty)")
  if(NOT ${var})
    execute_process(
      COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/tools/fetch-debian-source" ${source} ${binary} "${CMAKE_BINARY_DIR}/_deps"
      OUTPUT_VARIABLE fetched OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed)
    if(failed OR NOT EXISTS "${fetched}/${file}")
      message(FATAL_ERROR "could not fetch the ${source} sources with apt-get source (see above)")
    endif()
    set(${var} "${fetched}" CACHE PATH "${source} sources" FORCE)
  endif()
endfunction()

# Dear ImGui 1.86 from Debian's source package.
lab_fetch_source(LAB_IMGUI_SOURCE_DIR imgui libimgui-dev imgui.cpp)
set(imgui "${LAB_IMGUI_SOURCE_DIR}")
# Its imgui_draw.cpp with one line changed: ImFontAtlas::Build adds ImGui's built-in font
# (ProggyClean, 10.8 KB of gzip) when no font was added — a test at run time, so the font stays in
# lab.wasm although the page always adds its own (lab/platform/web_window.cpp checks it is in
# lab.data before the lab starts, and ImGuiHost has no fallback there). The line becomes an
# assertion; the configure stops if ImGui's text is not what is replaced.
file(READ "${imgui}/imgui_draw.cpp" imgui_draw)
set(imgui_default_font "    if (ConfigData.Size == 0)\n        AddFontDefault();\n")
string(FIND "${imgui_draw}" "${imgui_default_font}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${imgui}/imgui_draw.cpp: ImFontAtlas::Build's AddFontDefault() call is not as cmake/web.cmake expects")
endif()
string(REPLACE "${imgui_default_font}" "    IM_ASSERT(ConfigData.Size > 0 && \"the page adds its own font\");\n" imgui_draw "${imgui_draw}")
file(WRITE "${CMAKE_BINARY_DIR}/imgui/imgui_draw.cpp.new" "${imgui_draw}")
configure_file("${CMAKE_BINARY_DIR}/imgui/imgui_draw.cpp.new" "${CMAKE_BINARY_DIR}/imgui/imgui_draw.cpp" COPYONLY)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${imgui}/imgui_draw.cpp")
add_library(lab_imgui STATIC
  "${imgui}/imgui.cpp" "${CMAKE_BINARY_DIR}/imgui/imgui_draw.cpp" "${imgui}/imgui_tables.cpp" "${imgui}/imgui_widgets.cpp"
  "${imgui}/misc/cpp/imgui_stdlib.cpp"
  "${imgui}/backends/imgui_impl_glfw.cpp" "${imgui}/backends/imgui_impl_opengl3.cpp")
target_include_directories(lab_imgui SYSTEM PUBLIC "${imgui}" "${imgui}/misc/cpp")
target_compile_definitions(lab_imgui PUBLIC IMGUI_IMPL_OPENGL_ES3 IMGUI_DISABLE_DEMO_WINDOWS)
# One stb_truetype in the page: the font atlas uses the one lab/core/plots/text_raster.cpp compiles for
# the figures' and sweeps' labels (Debian's stb_truetype.h 1.26 and the stb_rect_pack.h it packs
# glyphs with, exported there when LAB_STB_TRUETYPE_EXTERN is set) instead of ImGui's own copies:
# 4 KB less gzip-compressed. Both must come from the same headers: stb_truetype lays out its packing
# context by whether stb_rect_pack.h came first.
target_include_directories(lab_imgui SYSTEM PRIVATE "${LAB_WEB_INCLUDE}")
target_compile_definitions(lab_imgui PRIVATE
  IMGUI_STB_TRUETYPE_FILENAME="stb_truetype.h" IMGUI_DISABLE_STB_TRUETYPE_IMPLEMENTATION
  IMGUI_STB_RECT_PACK_FILENAME="stb_rect_pack.h" IMGUI_DISABLE_STB_RECT_PACK_IMPLEMENTATION)
target_compile_definitions(lab_web_headers INTERFACE LAB_STB_TRUETYPE_EXTERN)
# tinygltf without its default image decoder, in every file that includes it (its class names the
# default loader): the lab skips glTF images, and the page never decodes a PNG (9 KB of gzip).
target_compile_definitions(lab_web_headers INTERFACE TINYGLTF_NO_STB_IMAGE)
# Nor its default image writer: the lab never writes glTF.
target_compile_definitions(lab_web_headers INTERFACE TINYGLTF_NO_STB_IMAGE_WRITE)
target_compile_options(lab_imgui PUBLIC -fwasm-exceptions) # GLFW's header is in Emscripten's sysroot

# The glTF loader's decoders (lab/core/gltf*), as the native build has them from libmeshoptimizer-dev
# and libdraco-dev: compiled from the same Debian source packages, decoders only. Each is a static
# library with its headers: meshoptimizer with a PUBLIC definition (LAB_HAVE_MESHOPT) that lab_gltf
# gets through meshoptimizer::meshoptimizer (below); Draco goes only into the page's Draco module,
# fetched when a model needs it (lab/core/gltf/draco_decoder.h), through draco::draco. Compiled with -fwasm-exceptions like the rest, so a std::bad_alloc
# from a decoder's allocation (sizes come from the file) unwinds to the loader.
# meshoptimizer 0.18 (EXT_meshopt_compression): the vertex and index codecs and the filters
# (+6 KB of gzip in lab.wasm).
lab_fetch_source(LAB_MESHOPT_SOURCE_DIR meshoptimizer libmeshoptimizer-dev src/meshoptimizer.h)
set(meshopt "${LAB_MESHOPT_SOURCE_DIR}/src")
add_library(lab_meshopt STATIC "${meshopt}/vertexcodec.cpp" "${meshopt}/indexcodec.cpp" "${meshopt}/vertexfilter.cpp")
target_include_directories(lab_meshopt SYSTEM PUBLIC "${meshopt}")
target_compile_definitions(lab_meshopt PUBLIC LAB_HAVE_MESHOPT=1)
target_compile_options(lab_meshopt PRIVATE -fwasm-exceptions)

# Draco 1.5.5 (KHR_draco_mesh_compression): Decoder::DecodeMeshFromBuffer with the features of the
# bitstream glTF names (2.2, as Draco's own DRACO_GLTF_BITSTREAM option: meshes, sequential and
# edgebreaker connectivity, standard and valence, normal encoding), in its own draco_features.h;
# Debian's also has point clouds, pre-2.2 bitstreams, and the transcoder, which needs Eigen. Only
# the sources that decoding a mesh links: about 80 s of CPU to compile; 45.7 KB of gzip as draco.wasm
# (it was 36 KB of the page's first load inside lab.wasm).
lab_fetch_source(LAB_DRACO_SOURCE_DIR draco libdraco-dev src/draco/compression/decode.cc)
set(draco "${LAB_DRACO_SOURCE_DIR}/src/draco")
set(LAB_DRACO_CONFIG "${CMAKE_BINARY_DIR}/draco-config")
file(CONFIGURE OUTPUT "${LAB_DRACO_CONFIG}/draco/draco_features.h" CONTENT [[
// The features of Draco's glTF bitstream, as its CMake option DRACO_GLTF_BITSTREAM has them.
#ifndef DRACO_FEATURES_H_
#define DRACO_FEATURES_H_
#define DRACO_MESH_COMPRESSION_SUPPORTED
#define DRACO_NORMAL_ENCODING_SUPPORTED
#define DRACO_STANDARD_EDGEBREAKER_SUPPORTED
#endif
]])
add_library(lab_draco STATIC
  "${draco}/attributes/attribute_octahedron_transform.cc"
  "${draco}/attributes/attribute_quantization_transform.cc"
  "${draco}/attributes/attribute_transform.cc"
  "${draco}/attributes/geometry_attribute.cc"
  "${draco}/attributes/point_attribute.cc"
  "${draco}/compression/attributes/attributes_decoder.cc"
  "${draco}/compression/attributes/sequential_attribute_decoder.cc"
  "${draco}/compression/attributes/sequential_attribute_decoders_controller.cc"
  "${draco}/compression/attributes/sequential_integer_attribute_decoder.cc"
  "${draco}/compression/attributes/sequential_normal_attribute_decoder.cc"
  "${draco}/compression/attributes/sequential_quantization_attribute_decoder.cc"
  "${draco}/compression/bit_coders/rans_bit_decoder.cc"
  "${draco}/compression/decode.cc"
  "${draco}/compression/entropy/symbol_decoding.cc"
  "${draco}/compression/mesh/mesh_decoder.cc"
  "${draco}/compression/mesh/mesh_edgebreaker_decoder.cc"
  "${draco}/compression/mesh/mesh_edgebreaker_decoder_impl.cc"
  "${draco}/compression/mesh/mesh_sequential_decoder.cc"
  "${draco}/compression/point_cloud/point_cloud_decoder.cc"
  "${draco}/core/bit_utils.cc"
  "${draco}/core/data_buffer.cc"
  "${draco}/core/decoder_buffer.cc"
  "${draco}/core/draco_types.cc"
  "${draco}/core/options.cc"
  "${draco}/core/quantization_utils.cc"
  "${draco}/mesh/corner_table.cc"
  "${draco}/mesh/mesh.cc"
  "${draco}/mesh/mesh_attribute_corner_table.cc"
  "${draco}/metadata/geometry_metadata.cc"
  "${draco}/metadata/metadata.cc"
  "${draco}/metadata/metadata_decoder.cc"
  "${draco}/point_cloud/point_cloud.cc")
target_include_directories(lab_draco SYSTEM PUBLIC "${LAB_DRACO_CONFIG}" "${LAB_DRACO_SOURCE_DIR}/src")
target_compile_options(lab_draco PRIVATE -fwasm-exceptions)

# libqrencode 4.1.1 (QR codes of the share links, lab/core/share): Debian's libqrencode-dev is built
# for the host, not for WebAssembly, so the page compiles the library's own C files from the source
# package (not qrenc.c, the command-line tool, which wants libpng). Its build would write these
# definitions into config.h; here they are given directly, without HAVE_CONFIG_H:
# STATIC_IN_RELEASE=static as in its release builds, the version, and strdup from Emscripten's libc.
# No HAVE_LIBPTHREAD: the page has one thread, so rsecc.c's lazily built tables need no mutex (and
# -pthread would need SharedArrayBuffer). A static library whose include folder gives qrencode.h,
# linked as PkgConfig::QRENCODE below. It only reaches lab.wasm once the app calls encodeQr.
enable_language(C)
lab_fetch_source(LAB_QRENCODE_SOURCE_DIR qrencode libqrencode-dev qrencode.c)
set(qrencode "${LAB_QRENCODE_SOURCE_DIR}")
add_library(lab_qrencode STATIC
  "${qrencode}/qrencode.c" "${qrencode}/qrinput.c" "${qrencode}/bitstream.c" "${qrencode}/qrspec.c"
  "${qrencode}/rsecc.c" "${qrencode}/split.c" "${qrencode}/mask.c" "${qrencode}/mqrspec.c" "${qrencode}/mmask.c")
# Its users see qrencode.h alone, not the library's internal headers (split.h, mask.h, ...).
file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/qrencode-include")
file(CREATE_LINK "${qrencode}/qrencode.h" "${CMAKE_BINARY_DIR}/qrencode-include/qrencode.h" SYMBOLIC)
target_include_directories(lab_qrencode SYSTEM PUBLIC "${CMAKE_BINARY_DIR}/qrencode-include")
target_compile_definitions(lab_qrencode PRIVATE
  STATIC_IN_RELEASE=static MAJOR_VERSION=4 MINOR_VERSION=1 MICRO_VERSION=1 VERSION="4.1.1" HAVE_STRDUP=1)

# The native build's target names for what stands in for them here, so that each room of lab/
# links the same names on both builds.
foreach(name glm::glm nlohmann_json::nlohmann_json PkgConfig::STB)
  add_library(${name} INTERFACE IMPORTED)
  target_link_libraries(${name} INTERFACE lab_web_headers)
endforeach()
add_library(draco::draco INTERFACE IMPORTED)
target_link_libraries(draco::draco INTERFACE lab_draco)
add_library(meshoptimizer::meshoptimizer INTERFACE IMPORTED)
target_link_libraries(meshoptimizer::meshoptimizer INTERFACE lab_meshopt)
add_library(PkgConfig::QRENCODE INTERFACE IMPORTED)
target_link_libraries(PkgConfig::QRENCODE INTERFACE lab_qrencode)

# The UI font, cut down to the characters the UI can show (the glyph ranges ImGuiHost asks for,
# lab/platform/imgui_host.cpp: Latin-1, the Greek letters, dashes and the ellipsis, arrows, minus, <= and >=)
# and without hinting, which ImGui's rasterizer does not use: 757 KB -> about 60 KB.
find_program(LAB_PYFTSUBSET pyftsubset REQUIRED) # Debian's fonttools
set(LAB_WEB_FONT "${CMAKE_BINARY_DIR}/fonts/DejaVuSans-ui.ttf")
set(LAB_FONT_SOURCE /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf)
add_custom_command(OUTPUT "${LAB_WEB_FONT}"
  COMMAND "${CMAKE_COMMAND}" -E make_directory "${CMAKE_BINARY_DIR}/fonts"
  COMMAND "${LAB_PYFTSUBSET}" "${LAB_FONT_SOURCE}" "--output-file=${LAB_WEB_FONT}"
          "--unicodes=U+0020-00FF,U+0391-03A9,U+03B1-03C9,U+2010-2027,U+2190-2193,U+2212,U+2264-2265,U+FFFD"
          --no-hinting --layout-features= --name-IDs=0,1,2,3,4,5,6 --drop-tables+=GSUB,GPOS,GDEF,kern,FFTM,MATH
  DEPENDS "${LAB_FONT_SOURCE}" VERBATIM)
add_custom_target(lab_web_font DEPENDS "${LAB_WEB_FONT}")

# A module the page fetches when something needs it (core/io/fetched_module.h): NAME.js and NAME.wasm
# in the site, a module factory FACTORY with one function FUNCTION and the heap functions the page
# copies through; no file system, no main. The Draco decoder (lab/platform/web_draco_module.cpp:
# draco, LabDraco, when a model needs it) and the QR encoder (web_qr_module.cpp: qr, LabQr, when the
# QR code window asks for a code; 7 KB of gzip out of the first load).
function(lab_configure_fetched_module target name factory function)
  set_target_properties(${target} PROPERTIES OUTPUT_NAME ${name} SUFFIX ".js" RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/site")
  target_link_options(${target} PRIVATE -Oz
    -sMODULARIZE=1 -sEXPORT_NAME=${factory} -sENVIRONMENT=web -sALLOW_MEMORY_GROWTH=1 -sMALLOC=emmalloc
    -sFILESYSTEM=0 --no-entry "-sEXPORTED_FUNCTIONS=[_${function},_malloc,_free]")
endfunction()

# The page: the program, the bundled presets and font, and web/'s shell, in one static folder.
function(lab_configure_web_target target)
  set(site "${CMAKE_BINARY_DIR}/site")
  set_target_properties(${target} PROPERTIES OUTPUT_NAME lab SUFFIX ".js" RUNTIME_OUTPUT_DIRECTORY "${site}")
  set(font "${LAB_WEB_FONT}")
  add_dependencies(${target} lab_web_font)
  target_link_options(${target} PRIVATE
    # The whole page's code generated for size at the link (LTO: the compile's -Os only makes bitcode):
    # 19 KB less gzip than -Os (issue 40; a drag frame's script time measured alike, see the README).
    -Oz
    -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
    -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=web
    # Smaller for the same frame: emmalloc instead of dlmalloc (3 KB of gzip), no WebGL extension
    # enabled or renamed behind the lab's back (it uses none). Main-thread script time a frame
    # while dragging a slider, median of 4 runs each way: 0.95 ms before, 0.97 ms after.
    -sMALLOC=emmalloc -sGL_EXTENSIONS_IN_PREFIXED_FORMAT=0 -sGL_SUPPORT_AUTOMATIC_ENABLE_EXTENSIONS=0
    "-sEXPORTED_FUNCTIONS=[_main,_lab_open_file,_lab_open_link,_lab_widgets,_lab_frames,_lab_settled,_lab_touch,_lab_text,_lab_backspace,_lab_page_field,_lab_page_command,_lab_page_focus,_lab_draco_loaded,_lab_qr_loaded,_lab_site_file_fetched,_malloc,_free]"
    "-sEXPORTED_RUNTIME_METHODS=[ccall,FS]"
    # lab.js reads only the Module properties index.html sets (and the file packager's preRun), and
    # decodes text with the TextDecoder every WebGL2 browser has: 0.4 KB less gzip (issue 40).
    "-sINCOMING_MODULE_JS_API=[canvas,print,printErr,onAbort,preRun]" -sTEXTDECODER=2
    # The bundled models stay out of lab.data (compact_presets.py leaves out presets/models): the
    # site's models/ folder, fetched the first time a preset names one (lab/core/io/site_files.h; the
    # trefoil is 16.4 KB of gzip).
    # The presets, exercises and decks as compact JSON (tools/compact_presets.py: 0.45 KB less gzip).
    "--preload-file=${CMAKE_BINARY_DIR}/presets-compact@/presets"
    "--preload-file=${font}@/fonts/DejaVuSans-ui.ttf")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS "${font}")
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  file(GLOB_RECURSE bundled CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/presets/*")
  set(compact_stamp "${CMAKE_BINARY_DIR}/presets-compact.stamp")
  # The files' names, written only when they change: a preset deleted or renamed packs anew too.
  set(compact_list "${CMAKE_BINARY_DIR}/presets-compact.list")
  string(REPLACE ";" "\n" bundled_lines "${bundled}")
  file(CONFIGURE OUTPUT "${compact_list}" CONTENT "${bundled_lines}\n" @ONLY)
  add_custom_command(OUTPUT "${compact_stamp}"
    COMMAND Python3::Interpreter "${CMAKE_SOURCE_DIR}/tools/compact_presets.py" "${CMAKE_SOURCE_DIR}/presets"
            "${CMAKE_BINARY_DIR}/presets-compact"
    COMMAND "${CMAKE_COMMAND}" -E touch "${compact_stamp}"
    DEPENDS ${bundled} "${compact_list}" "${CMAKE_SOURCE_DIR}/tools/compact_presets.py" VERBATIM)
  add_custom_target(lab_presets_compact DEPENDS "${compact_stamp}")
  add_dependencies(${target} lab_presets_compact)
  # (and the bundled models, which the link's last step copies into the site)
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS "${compact_stamp}" ${bundled})
  # The page is written after each link, without its comments (tools/minify_page.py): a changed
  # page relinks, so the site never keeps an old one.
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS "${CMAKE_SOURCE_DIR}/web/index.html"
                                                             "${CMAKE_SOURCE_DIR}/tools/minify_page.py"
                                                             "${CMAKE_SOURCE_DIR}/web/access.js")
  # lab.js with its names shortened and its code compacted by Debian's terser (Emscripten's own
  # minifier only takes the spaces out; its Closure step is an npm package): 6 KB less gzip. Only
  # `Module` is kept, the one name of lab.js that index.html and access.js use (they name nothing
  # else of it, and lab.js evaluates no script: lab/platform/web_main.cpp).
  find_program(LAB_TERSER terser REQUIRED) # Debian's terser
  # And lab.wasm through Binaryen's size passes once more, until they find nothing (--converge): the
  # link's own run comes before Emscripten drops the exports and imports nothing uses; 3.5 KB less
  # gzip. The features are the page's: wasm exceptions, nothing else past the MVP.
  find_program(LAB_WASM_OPT wasm-opt REQUIRED) # Debian's binaryen, which Emscripten uses
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND "${LAB_WASM_OPT}" --mvp-features --enable-exception-handling -Oz --converge "${site}/lab.wasm" -o "${site}/lab.min.wasm"
    COMMAND "${CMAKE_COMMAND}" -E rename "${site}/lab.min.wasm" "${site}/lab.wasm"
    COMMAND "${LAB_TERSER}" "${site}/lab.js" --compress --mangle "toplevel,reserved=[Module]" --output "${site}/lab.min.js"
    COMMAND "${CMAKE_COMMAND}" -E rename "${site}/lab.min.js" "${site}/lab.js"
    COMMAND Python3::Interpreter "${CMAKE_SOURCE_DIR}/tools/minify_page.py" "${CMAKE_SOURCE_DIR}/web/index.html" "${site}/index.html" "${LAB_TERSER}"
    COMMAND "${CMAKE_COMMAND}" -E rm -rf "${site}/models"
    COMMAND "${CMAKE_COMMAND}" -E copy_directory "${CMAKE_SOURCE_DIR}/presets/models" "${site}/models")
endfunction()
