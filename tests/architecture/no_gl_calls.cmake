# no_gl_calls.cmake — a library that must never call OpenGL (or a window system) does not: no
# undefined symbol of its objects names a GL, EGL or GLFW function or ImGui's OpenGL/GLFW backend.
# The rule is enforced here, at the link level, because Debian's libimgui.a carries the OpenGL3
# backend beside ImGui: linking ImGui makes GL reachable, and only the objects tell who calls it.
#
#   cmake -DNM=<nm> -DLIBRARIES="<a.a>|<b.a>" -P no_gl_calls.cmake
string(REPLACE "|" ";" LIBRARIES "${LIBRARIES}")
foreach(library IN LISTS LIBRARIES)
  execute_process(COMMAND "${NM}" --undefined-only --format=posix "${library}"
                  OUTPUT_VARIABLE symbols RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${NM} could not read ${library}")
  endif()
  string(REGEX MATCHALL "(^|\n)(gl[A-Z][A-Za-z0-9_]*|egl[A-Z][A-Za-z0-9_]*|glfw[A-Z][A-Za-z0-9_]*|_Z[A-Za-z0-9_]*ImGui_Impl(OpenGL|Glfw)[A-Za-z0-9_]*) "
         calls "${symbols}")
  if(calls)
    string(REGEX REPLACE "[\n ]" "" calls "${calls}")
    list(REMOVE_DUPLICATES calls)
    list(JOIN calls ", " calls)
    get_filename_component(name "${library}" NAME)
    message(FATAL_ERROR "${name} calls OpenGL or a window system, which its room must not: ${calls}")
  endif()
  message(STATUS "${library}: no GL, EGL, GLFW or ImGui backend call")
endforeach()
