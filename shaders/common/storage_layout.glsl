// The layout of a storage block: std430, and on OpenGL ES (OASIS_STORAGE_BINDINGS, set by the ES
// dialect) its binding too, as ES cannot bind a block by name from the API (desktop GL does:
// render/shader_library.cpp's bindLightBlocks, so GLSL 3.30 with the extension works there).
#ifndef OASIS_STORAGE_LAYOUT_GLSL
#define OASIS_STORAGE_LAYOUT_GLSL
#include "common/shared_constants.glsl"

#if defined(OASIS_STORAGE_BINDINGS)
#define OASIS_STORAGE_LAYOUT(binding_) layout(std430, binding = binding_)
#else
#define OASIS_STORAGE_LAYOUT(binding_) layout(std430)
#endif

#endif
