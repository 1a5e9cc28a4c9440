/* Driver bug, minimal: in a compute shader, a local array written at an index that differs per
 * invocation (a[i] = x) lands every write of four neighbouring invocations in the element the first
 * of them names; softpipe (Mesa 22.3.6) runs four invocations together and uses the first one's
 * index. Writing through a loop over constant indices (for (k) if (k == i) a[k] = x) mends it:
 * oasis's workaround array-write-by-loop. Invocation i (of 8) writes i + 1 into a[i % 4] of a
 * zeroed array and reports a[0] + 10 a[1] + 100 a[2] + 1000 a[3]: 1 20 300 4000 5 60 700 8000 is
 * right, 1 2 3 4 5 6 7 8 the bug (every write in a[0]). Runs both ways; argv[1] "bug"
 * (the driver is known to have it) or "fixed", then optionally the GL_RENDERER prefix expected (exit 77,
 * skipped, when another driver answers): exit 0 when the direct write is as expected and
 * the loop right. docs/drivers.md. */
#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <stdio.h>
#include <string.h>

static const char* kCompute[2] = {
    "#version 330\n#extension GL_ARB_compute_shader : require\n"
    "#extension GL_ARB_shader_storage_buffer_object : require\nlayout(local_size_x = 8) in;\n"
    "layout(std430) buffer Out { uint seen[]; };\n"
    "void main() {\n  uint i = gl_LocalInvocationID.x; uint a[4] = uint[4](0u, 0u, 0u, 0u);\n",
    "  seen[i] = a[0] + 10u * a[1] + 100u * a[2] + 1000u * a[3];\n}\n"};
static const char* kDirect = "  a[i % 4u] = i + 1u;\n";
static const char* kLoop = "  for (uint k = 0u; k < 4u; ++k) if (k == i % 4u) a[k] = i + 1u;\n";

/* The eight numbers, as the shader with `write` computed them: 1 20 300 4000 5 60 700 8000? */
static int numbers(const char* write, const char* label) {
    const char* sources[3] = {kCompute[0], write, kCompute[1]};
    GLuint shader = glCreateShader(GL_COMPUTE_SHADER), program = glCreateProgram();
    glShaderSource(shader, 3, sources, NULL);
    glCompileShader(shader);
    glAttachShader(program, shader);
    glLinkProgram(program);
    glUseProgram(program);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    GLuint seen[8];
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(seen), seen);
    const GLuint want[8] = {1, 20, 300, 4000, 5, 60, 700, 8000};
    int right = 1;
    printf("%s:", label);
    for (int i = 0; i < 8; ++i) {
        right = right && seen[i] == want[i];
        printf(" %u", seen[i]);
    }
    printf(" (%s)\n", right ? "right" : "wrong");
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
    GLuint buffer;
    glGenBuffers(1, &buffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer);
    glBufferData(GL_SHADER_STORAGE_BUFFER, 8 * sizeof(GLuint), NULL, GL_DYNAMIC_READ);
    int direct = numbers(kDirect, "a[i % 4u] = i + 1u           ");
    int loop = numbers(kLoop, "for (k) if (k == i % 4u) a[k]");
    int ok = loop && direct == !expectBug;
    printf("%s: expected the direct write %s and the loop right\n", ok ? "PASS" : "FAIL", expectBug ? "wrong" : "right");
    return ok ? 0 : 1;
}
