# forbidden_calls.cmake — a library does not call what its room must not: no undefined symbol of
# its objects matches FORBIDDEN. The rule is enforced here, at the link level, because Debian's
# libimgui.a carries the OpenGL3 backend beside ImGui: linking ImGui makes GL reachable, and only
# the objects tell who calls it. Two uses (tests/CMakeLists.txt):
#   * GL, EGL, GLFW or ImGui's OpenGL/GLFW backend, in the rooms that never touch GL (the default);
#   * Dear ImGui, in lab/app (what it needs of ImGui's IO comes through ui::ScreenEvents).
#
#   cmake -DNM=<nm> -DLIBRARIES="<a.a>|<b.a>" [-DFORBIDDEN=<regex> -DWHAT=<words>] -P forbidden_calls.cmake
if(NOT FORBIDDEN)
  set(FORBIDDEN "gl[A-Z][A-Za-z0-9_]*|egl[A-Z][A-Za-z0-9_]*|glfw[A-Z][A-Za-z0-9_]*|_Z[A-Za-z0-9_]*ImGui_Impl(OpenGL|Glfw)[A-Za-z0-9_]*")
  set(WHAT "OpenGL or a window system")
endif()
string(REPLACE "|" ";" LIBRARIES "${LIBRARIES}")
foreach(library IN LISTS LIBRARIES)
  execute_process(COMMAND "${NM}" --undefined-only --format=posix "${library}"
                  OUTPUT_VARIABLE symbols RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "${NM} could not read ${library}")
  endif()
  string(REGEX MATCHALL "(^|\n)(${FORBIDDEN}) " calls "${symbols}")
  if(calls)
    string(REGEX REPLACE "[\n ]" "" calls "${calls}")
    list(REMOVE_DUPLICATES calls)
    list(JOIN calls ", " calls)
    get_filename_component(name "${library}" NAME)
    message(FATAL_ERROR "${name} calls ${WHAT}, which its room must not: ${calls}")
  endif()
  message(STATUS "${library}: no call to ${WHAT}")
endforeach()
