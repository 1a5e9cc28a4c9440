/* Driver bug, minimal: a depth-only draw with GL_DEPTH_CLAMP and a slope-scaled polygon offset (as
 * oasis's ShadowPass draws a cascade's casters into a GL_DEPTH_COMPONENT32F map) of a quad that
 * reaches nearer than the near plane. GL offsets each fragment's interpolated depth, then clamps it
 * to the depth range; softpipe (Mesa 22.3.6) writes depths that fit the vertices' depths offset and
 * clamped to [0, 1] *before* interpolation: the unclamped part of the quad lies too far (up to 0.32
 * of the depth range here), its slope changed. Without the offset, or with no vertex outside
 * [0, 1], softpipe is right. oasis's workaround (depth-clamp-off) is its fallback for
 * drivers without depth clamp: the cascade's box reaches towards the sun up to the highest caster,
 * so no caster crosses its front and nothing is clamped. Runs both ways; argv[1] "bug" (the driver
 * is known to have it) or "fixed", then optionally the GL_RENDERER prefix expected (exit 77,
 * skipped, when another driver answers): exit 0 when the clamped result is as expected and the
 * contained one right. docs/drivers.md. */
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* A quad over the whole 16x1 viewport whose clip z goes from z.x at the left to z.y at the right (w = 1). */
static const char* kVertex = "#version 330\nuniform vec2 z;\nvoid main() { vec2 p = vec2(gl_VertexID & 1, gl_VertexID >> 1);\n"
    "  gl_Position = vec4(p * 2.0 - 1.0, mix(z.x, z.y, p.x), 1.0); }\n";
static const char* kFragment = "#version 330\nvoid main() {}\n";  /* depth only, as a shadow caster */
enum { kWidth = 16 };
static const float kFactor = 2.0f, kUnits = 2.0f;  /* passes/shadow_pass.cpp's glPolygonOffset */

static void stage(GLuint program, GLenum type, const char* source) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, NULL);
    glCompileShader(shader);
    glAttachShader(program, shader);
}

/* Draws the quad from clip z `near` to `far` and compares each texel with GL's rule: the window
 * depth interpolated, plus the offset factor * slope (+ units * r, under 1e-6 for a float map),
 * clamped to [0, 1]. */
static int drawnRight(GLuint program, int clamp, int offset, float near, float far, const char* what) {
    const float farthest = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &farthest);
    if (clamp) glEnable(GL_DEPTH_CLAMP); else glDisable(GL_DEPTH_CLAMP);
    if (offset) glEnable(GL_POLYGON_OFFSET_FILL); else glDisable(GL_POLYGON_OFFSET_FILL);
    glUniform2f(glGetUniformLocation(program, "z"), near, far);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    float depth[kWidth], worst = 0.0f;
    glReadPixels(0, 0, kWidth, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    float slope = 0.5f * (far - near) / kWidth;  /* window depth per pixel */
    printf("%s:\n  written ", what);
    for (int x = 0; x < kWidth; ++x) {
        float want = 0.5f + 0.5f * (near + (far - near) * (x + 0.5f) / kWidth) + (offset ? kFactor * slope : 0.0f);
        want = want < 0.0f ? 0.0f : want > 1.0f ? 1.0f : want;
        worst = fmaxf(worst, fabsf(depth[x] - want));
        printf(" %.3f", depth[x]);
    }
    int right = worst < 1.0f / 256.0f;
    printf("\n  largest difference from GL's %.3f: %s\n", worst, right ? "right" : "wrong");
    return right;
}

int main(int argc, char** argv) {
    int expectBug = argc > 1 && strcmp(argv[1], "bug") == 0;
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
    eglInitialize(display, NULL, NULL);
    eglBindAPI(EGL_OPENGL_API);
    EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                           EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, NULL, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) return 77;
    const char* renderer = (const char*)glGetString(GL_RENDERER);
    printf("%s; %s\n", renderer, (const char*)glGetString(GL_VERSION));
    if (argc > 2 && strncmp(renderer, argv[2], strlen(argv[2])) != 0) return 77;  /* not the driver asked for */
    GLuint program = glCreateProgram(), texture, framebuffer, vao;
    stage(program, GL_VERTEX_SHADER, kVertex);
    stage(program, GL_FRAGMENT_SHADER, kFragment);
    glLinkProgram(program);
    glUseProgram(program);
    glGenTextures(1, &texture);  /* a shadow map's format (render/shadow_maps.cpp) */
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, kWidth, 1, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glViewport(0, 0, kWidth, 1);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glPolygonOffset(kFactor, kUnits);
    /* A caster from 1.0 nearer than the front (clip z -3, window depth -1) to inside the box (0.5). */
    int clamped = drawnRight(program, 1, 1, -3.0f, 0.5f, "depth clamp and polygon offset, the quad crossing the near plane");
    drawnRight(program, 1, 0, -3.0f, 0.5f, "depth clamp, no offset (not asserted)");
    /* The workaround: the box's front moved to the caster (z' = 0.45 z + 0.4: -0.95 .. 0.625), no clamp. */
    int contained = drawnRight(program, 0, 1, -0.95f, 0.625f, "no depth clamp, polygon offset, the box reaching the caster");
    int ok = contained && clamped == !expectBug;
    printf("%s: expected the clamped depths %s and the contained ones right\n", ok ? "PASS" : "FAIL",
           expectBug ? "wrong" : "right");
    return ok ? 0 : 1;
}
