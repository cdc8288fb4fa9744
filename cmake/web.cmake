# web.cmake — what the browser build (emcmake cmake, Debian's Emscripten 3.1.6) needs instead of
# find_package: Debian's header-only libraries through a folder of links (never -I/usr/include,
# which would bring glibc's headers), Dear ImGui compiled from Debian's source package, and the
# link options of the page. Included from CMakeLists.txt when EMSCRIPTEN is set.

# GLM, nlohmann-json, stb and tinygltf headers, and nothing else from /usr/include.
set(LAB_WEB_INCLUDE "${CMAKE_BINARY_DIR}/web-include")
file(MAKE_DIRECTORY "${LAB_WEB_INCLUDE}")
foreach(link glm nlohmann tiny_gltf.h)
  file(CREATE_LINK "/usr/include/${link}" "${LAB_WEB_INCLUDE}/${link}" SYMBOLIC)
endforeach()
foreach(header stb_image.h stb_image_write.h)
  file(CREATE_LINK "/usr/include/stb/${header}" "${LAB_WEB_INCLUDE}/${header}" SYMBOLIC)
endforeach()
add_library(lab_web_headers INTERFACE)
target_include_directories(lab_web_headers SYSTEM INTERFACE "${LAB_WEB_INCLUDE}")
# Exceptions carry nlohmann-json's parse errors to the preset validator; wasm exceptions are
# native in every browser with WebGL2.
target_compile_options(lab_web_headers INTERFACE -fwasm-exceptions)
target_link_options(lab_web_headers INTERFACE -fwasm-exceptions)

# Dear ImGui 1.86 from Debian's source package, cached in the build folder.
set(LAB_IMGUI_SOURCE_DIR "" CACHE PATH "Dear ImGui sources (fetched from Debian's source package when empty)")
if(NOT LAB_IMGUI_SOURCE_DIR)
  execute_process(
    COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/tools/fetch-imgui-source" "${CMAKE_BINARY_DIR}/_deps"
    OUTPUT_VARIABLE fetched OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed)
  if(failed OR NOT EXISTS "${fetched}/imgui.cpp")
    message(FATAL_ERROR "could not fetch the Dear ImGui sources with apt-get source (see above)")
  endif()
  set(LAB_IMGUI_SOURCE_DIR "${fetched}" CACHE PATH "Dear ImGui sources" FORCE)
endif()
set(imgui "${LAB_IMGUI_SOURCE_DIR}")
add_library(lab_imgui STATIC
  "${imgui}/imgui.cpp" "${imgui}/imgui_draw.cpp" "${imgui}/imgui_tables.cpp" "${imgui}/imgui_widgets.cpp"
  "${imgui}/misc/cpp/imgui_stdlib.cpp"
  "${imgui}/backends/imgui_impl_glfw.cpp" "${imgui}/backends/imgui_impl_opengl3.cpp")
target_include_directories(lab_imgui SYSTEM PUBLIC "${imgui}" "${imgui}/misc/cpp")
target_compile_definitions(lab_imgui PUBLIC IMGUI_IMPL_OPENGL_ES3 IMGUI_DISABLE_DEMO_WINDOWS)
target_compile_options(lab_imgui PUBLIC -fwasm-exceptions) # GLFW's header is in Emscripten's sysroot

# The UI font, cut down to the characters the UI can show (the glyph ranges ImGuiHost asks for,
# lab/platform/imgui_host.cpp: Latin-1, Greek, dashes and the ellipsis, arrows, minus, <= and >=)
# and without hinting, which ImGui's rasterizer does not use: 757 KB -> about 60 KB.
find_program(LAB_PYFTSUBSET pyftsubset REQUIRED) # Debian's fonttools
set(LAB_WEB_FONT "${CMAKE_BINARY_DIR}/fonts/DejaVuSans-ui.ttf")
set(LAB_FONT_SOURCE /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf)
add_custom_command(OUTPUT "${LAB_WEB_FONT}"
  COMMAND "${CMAKE_COMMAND}" -E make_directory "${CMAKE_BINARY_DIR}/fonts"
  COMMAND "${LAB_PYFTSUBSET}" "${LAB_FONT_SOURCE}" "--output-file=${LAB_WEB_FONT}"
          "--unicodes=U+0020-00FF,U+0370-03FF,U+2010-2027,U+2190-2193,U+2212,U+2264-2265,U+FFFD"
          --no-hinting --layout-features= --name-IDs=0,1,2,3,4,5,6 --drop-tables+=GSUB,GPOS,GDEF,kern,FFTM
  DEPENDS "${LAB_FONT_SOURCE}" VERBATIM)
add_custom_target(lab_web_font DEPENDS "${LAB_WEB_FONT}")

# The page: the program, the bundled presets and font, and web/'s shell, in one static folder.
function(lab_configure_web_target target)
  set(site "${CMAKE_BINARY_DIR}/site")
  set_target_properties(${target} PROPERTIES OUTPUT_NAME lab SUFFIX ".js" RUNTIME_OUTPUT_DIRECTORY "${site}")
  set(font "${LAB_WEB_FONT}")
  add_dependencies(${target} lab_web_font)
  target_link_options(${target} PRIVATE
    -sUSE_GLFW=3 -sMIN_WEBGL_VERSION=2 -sMAX_WEBGL_VERSION=2
    -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=web
    "-sEXPORTED_FUNCTIONS=[_main,_lab_open_file,_lab_open_link,_lab_widgets,_lab_frames,_lab_settled,_lab_touch,_lab_text,_lab_backspace]"
    "-sEXPORTED_RUNTIME_METHODS=[ccall,FS]"
    "--preload-file=${CMAKE_SOURCE_DIR}/presets@/presets"
    "--preload-file=${font}@/fonts/DejaVuSans-ui.ttf")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS "${font}")
  file(GLOB_RECURSE bundled CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/presets/*")
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS ${bundled})
  # The page is copied after each link: a changed page relinks, so the site never keeps an old one.
  set_property(TARGET ${target} APPEND PROPERTY LINK_DEPENDS "${CMAKE_SOURCE_DIR}/web/index.html")
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${CMAKE_SOURCE_DIR}/web/index.html" "${site}/index.html")
endfunction()
