// gl.h — the one header that knows which GL the lab is built against.
//
// Every target renders with the OpenGL ES 3.0 API and GLSL ES 3.00: headless EGL on Mesa,
// the desktop window, and WebGL2 in the browser (which is ES 3.0). Nothing else includes a GL
// header directly.
#pragma once

#include <GLES3/gl3.h>
