// Two independent counts of live GL objects, for the leak tests (resources_test.cpp) and the soak
// (tests/soak): the wrappers' own counters, and the names the driver says are live.
#pragma once
#include <algorithm>
#include <array>
#include <ostream>

#include "gl/objects.h"

namespace oasis::gputest {

// Names the driver says are live objects of each kind; independent of the wrappers' counters, so
// it also sees objects made outside them (ImGui's label renderer, raw glGen* calls).
struct GlNameProbe {
    int textures = 0, buffers = 0, framebuffers = 0, vertexArrays = 0, programs = 0, shaders = 0;
    bool operator==(const GlNameProbe& o) const {
        return textures == o.textures && buffers == o.buffers && framebuffers == o.framebuffers &&
               vertexArrays == o.vertexArrays && programs == o.programs && shaders == o.shaders;
    }
    bool operator!=(const GlNameProbe& o) const { return !(*this == o); }
    int total() const { return textures + buffers + framebuffers + vertexArrays + programs + shaders; }
};

// The names to probe: 1 up to 4096 past the next name the driver would hand out. Mesa hands out
// texture names above every name used before (a long run passes 4096), and where a driver reuses
// freed names the live ones stay packed near the bottom, so the margin covers them either way.
inline GLuint probedNameLimit() {
    GLuint texture = 0, buffer = 0, framebuffer = 0, vertexArray = 0;
    glGenTextures(1, &texture);
    glGenBuffers(1, &buffer);
    glGenFramebuffers(1, &framebuffer);
    glGenVertexArrays(1, &vertexArray);
    GLuint program = glCreateProgram();  // programs and shaders share one namespace
    GLuint highest = std::max({texture, buffer, framebuffer, vertexArray, program});
    glDeleteTextures(1, &texture);
    glDeleteBuffers(1, &buffer);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteVertexArrays(1, &vertexArray);
    glDeleteProgram(program);
    return highest + 4096;
}

inline GlNameProbe probeNames() {
    GlNameProbe probe;
    const GLuint limit = probedNameLimit();
    for (GLuint name = 1; name <= limit; ++name) {
        probe.textures += glIsTexture(name) ? 1 : 0;
        probe.buffers += glIsBuffer(name) ? 1 : 0;
        probe.framebuffers += glIsFramebuffer(name) ? 1 : 0;
        probe.vertexArrays += glIsVertexArray(name) ? 1 : 0;
        probe.programs += glIsProgram(name) ? 1 : 0;
        probe.shaders += glIsShader(name) ? 1 : 0;
    }
    return probe;
}

inline std::ostream& operator<<(std::ostream& out, const GlNameProbe& p) {
    return out << "{textures " << p.textures << ", buffers " << p.buffers << ", framebuffers " << p.framebuffers
               << ", vertex arrays " << p.vertexArrays << ", programs " << p.programs << ", shaders " << p.shaders << "}";
}

// The wrappers' live objects (gl/objects.h), by kind and in all.
struct LiveCounts {
    std::array<int, size_t(gl::ObjectKind::Count)> byKind{};
    int total = 0;
    bool operator==(const LiveCounts& o) const { return byKind == o.byKind && total == o.total; }
    bool operator!=(const LiveCounts& o) const { return !(*this == o); }
};

inline LiveCounts liveCounts() {
    LiveCounts counts;
    for (int k = 0; k < int(gl::ObjectKind::Count); ++k) counts.byKind[k] = gl::liveObjectCount(gl::ObjectKind(k));
    counts.total = gl::liveObjectCount();
    return counts;
}

inline std::ostream& operator<<(std::ostream& out, const LiveCounts& c) {
    out << "{total " << c.total << ":";
    for (int n : c.byKind) out << " " << n;
    return out << "}";
}

}  // namespace oasis::gputest
