/* Driver bug, minimal: a compute dispatch reads a texture a draw has just written, with that draw's
 * framebuffer still bound. GL orders the two (no barrier is needed: glMemoryBarrier only orders
 * shader stores), yet softpipe (Mesa 22.3.6) reads the texels as they were before the draw. A
 * glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT) before the dispatch mends it: oasis's workaround
 * flush-before-compute-read. Runs both ways; argv[1] "bug" (the driver is known to have it) or
 * "fixed", then optionally the GL_RENDERER prefix expected (exit 77, skipped, when another driver
 * answers): exit 0 when the result without the barrier is as expected and the one with it right.
 * Also prints (not asserted) whether a glClear alone is seen by a compute read, without and with the
 * barrier. docs/drivers.md. */
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <stdio.h>
#include <string.h>

static const char* kVertex = "#version 330\nvoid main() { gl_Position = vec4(vec2(gl_VertexID & 1, gl_VertexID >> 1) * 4.0 - 1.0, 0.0, 1.0); }\n";
static const char* kFragment = "#version 330\nout vec4 colour; void main() { colour = vec4(0.75); }\n";
static const char* kCompute = "#version 330\n#extension GL_ARB_compute_shader : require\n"
    "#extension GL_ARB_shader_storage_buffer_object : require\nlayout(local_size_x = 8, local_size_y = 8) in;\n"
    "uniform sampler2D drawn; layout(std430) buffer Out { float seen[]; };\n"
    "void main() { ivec2 p = ivec2(gl_GlobalInvocationID.xy); seen[p.y * 8 + p.x] = texelFetch(drawn, p, 0).r; }\n";

static GLuint stage(GLuint program, GLenum type, const char* source) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, NULL);
    glCompileShader(shader);
    glAttachShader(program, shader);
    return shader;
}

/* The 64 texels as the compute shader saw them: all `want`? */
static int computeSees(GLuint compute, GLuint buffer, float want) {
    float seen[64];
    glUseProgram(compute);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(seen), seen);
    int right = 1;
    for (int i = 0; i < 64; ++i) right = right && seen[i] > want - 0.01f && seen[i] < want + 0.01f;
    printf("  texel 0 read %.3f, %.3f expected\n", seen[0], want);
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
    GLuint draw = glCreateProgram(), compute = glCreateProgram(), texture, framebuffer, buffer, vao;
    stage(draw, GL_VERTEX_SHADER, kVertex);
    stage(draw, GL_FRAGMENT_SHADER, kFragment);
    stage(compute, GL_COMPUTE_SHADER, kCompute);
    glLinkProgram(draw);
    glLinkProgram(compute);
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  /* complete without mipmaps */
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);  /* stays bound: the bug needs it */
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glGenBuffers(1, &buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, 64 * sizeof(float), NULL, GL_DYNAMIC_READ);
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glViewport(0, 0, 8, 8);
    int pass[2];
    for (int barrier = 0; barrier < 2; ++barrier) {
        glClearColor(0.25f, 0.25f, 0.25f, 0.25f);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();  /* the clear is done and visible: only the draw below is in question */
        glUseProgram(draw);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if (barrier) glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        pass[barrier] = computeSees(compute, buffer, 0.75f);
        printf("draw then dispatch, %s barrier: compute reads the %s\n", barrier ? "with a" : "no",
               pass[barrier] ? "drawn texels (right)" : "texels from before the draw (wrong)");
    }
    for (int barrier = 0; barrier < 2; ++barrier) {  /* the same question of a clear alone */
        glClearColor(0.5f - 0.25f * barrier, 0.5f, 0.5f, 0.5f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (barrier) glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
        int right = computeSees(compute, buffer, 0.5f - 0.25f * barrier);
        printf("clear then dispatch, %s barrier: compute reads the %s (not asserted)\n", barrier ? "with a" : "no",
               right ? "cleared texels (right)" : "texels from before the clear (wrong)");
    }
    int ok = pass[1] && pass[0] == !expectBug;
    printf("%s: expected %s without the barrier and right with it\n", ok ? "PASS" : "FAIL", expectBug ? "wrong" : "right");
    return ok ? 0 : 1;
}
