#pragma once
// Direct GL calls. render/ links no GL library: the editor links libOpenGL (GLVND) and the
// headless tools link OSMesa; both export every GL 4.5 entry point (see docs/architecture.md).
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
