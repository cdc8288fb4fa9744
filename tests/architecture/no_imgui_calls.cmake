# no_imgui_calls.cmake — a library that must not draw UI does not: no undefined symbol of its
# objects names a Dear ImGui function (lab/app: what it needs of ImGui's IO comes through the UI
# room's ScreenEvents or the platform).
#
#   cmake -DNM=<nm> -DLIBRARY=<a.a> -P no_imgui_calls.cmake
execute_process(COMMAND "${NM}" --undefined-only --format=posix "${LIBRARY}" OUTPUT_VARIABLE symbols RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "${NM} could not read ${LIBRARY}")
endif()
string(REGEX MATCHALL "(^|\n)_Z[A-Za-z0-9_]*ImGui[A-Za-z0-9_]* " calls "${symbols}")
if(calls)
  string(REGEX REPLACE "[\n ]" "" calls "${calls}")
  list(REMOVE_DUPLICATES calls)
  list(JOIN calls ", " calls)
  get_filename_component(name "${LIBRARY}" NAME)
  message(FATAL_ERROR "${name} calls Dear ImGui, which its room must not: ${calls}")
endif()
message(STATUS "${LIBRARY}: no Dear ImGui call")
