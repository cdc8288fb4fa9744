# package.cmake — `cmake --install` and the Debian package (CPack), for the native `lab`.
#
#   bin/lab                                   the program (shaders are embedded in it at build time)
#   share/lighting-lab/presets/               the shipped presets, with presets/models/
#   share/doc/lighting-lab/README.md          the README
#
# The program finds the shipped presets by one rule (lab/cli/main.cpp): <its folder>/LAB_INSTALLED_PRESETS
# (../share/lighting-lab/presets), else the source tree's presets/ it was built from (a build tree).
#
# `tools/dev package` builds lighting-lab_<version>_amd64.deb with CPack: `cpack --config
# build/CPackConfig.cmake -B build`. Its Depends are dpkg-shlibdeps's (the libraries `lab` links)
# plus Mesa's EGL and its software rasterizer, which `lab check`/`render` need on a machine
# without a GPU or a display (a CI runner). tests/package/run_package_test.sh installs it and checks.
include(GNUInstallDirs)

set(LAB_INSTALL_PRESETS_DIR "${CMAKE_INSTALL_DATADIR}/lighting-lab/presets")
set(LAB_INSTALL_DOC_DIR "${CMAKE_INSTALL_DATADIR}/doc/lighting-lab")

# The installed presets relative to the installed program, for the program's preset rule.
file(RELATIVE_PATH LAB_INSTALLED_PRESETS "/prefix/${CMAKE_INSTALL_BINDIR}" "/prefix/${LAB_INSTALL_PRESETS_DIR}")
target_compile_definitions(lab PRIVATE LAB_INSTALLED_PRESETS="${LAB_INSTALLED_PRESETS}")

install(TARGETS lab RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(DIRECTORY presets/ DESTINATION "${LAB_INSTALL_PRESETS_DIR}")
install(FILES README.md DESTINATION "${LAB_INSTALL_DOC_DIR}")

# --- CPack: the .deb --------------------------------------------------------------------
set(LAB_PACKAGE_MAINTAINER "Lighting Lab maintainers <maintainers@users.noreply.h-seed-9a979b1d.example>"
    CACHE STRING "The Debian package's Maintainer field")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME lighting-lab)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_VENDOR "Lighting Lab")
set(CPACK_PACKAGE_CONTACT "${LAB_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "interactive lab for teaching local illumination (Phong, Blinn-Phong, Cook-Torrance)")
set(CPACK_STRIP_FILES ON) # the build is RelWithDebInfo; the package carries no debug information
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # lighting-lab_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION education)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${LAB_PACKAGE_MAINTAINER}")
# The long description (CPack puts the summary above it and indents each line).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "The Phong reflection model, Blinn-Phong and Torrance-Sparrow/Cook-Torrance,
with flat, Gouraud and Phong shading, in a desktop window with live plots of
the reflection lobes, and on the command line without a display or a GPU:
lab render (presets to PNG), lab plot (lobe data as CSV) and lab check
(renders compared with golden images, for a course's CI). The shipped presets
are in /usr/share/lighting-lab/presets.")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON) # dpkg-shlibdeps (dpkg-dev): libglfw3, libegl1, libgles2, libdraco7, ...
# Not linked, but loaded at run time: Mesa's EGL (libEGL.so.1 is only the dispatcher) and its
# software rasterizer (swrast_dri.so, llvmpipe), so that `lab check` runs on a headless machine.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl-mesa0, libgl1-mesa-dri")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fonts-dejavu-core") # the window's UI font (ImGui's own otherwise)
include(CPack)
