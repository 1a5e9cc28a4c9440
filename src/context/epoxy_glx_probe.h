// libepoxy's "is the current context GLX?" probe, answered "no" while oasis's only context is EGL,
// so that an EGL tracer (`apitrace trace --api egl`) can record a headless command with no special
// environment. Why and how it was checked: docs/captures.md ("apitrace").
#pragma once

namespace oasis {

// While alive, libepoxy sees no current GLX context without looking GLX up. libepoxy 1.5.10 asks
// `glXGetCurrentContext` from whatever `libGL.so.1` it opened before resolving glGetIntegerv and
// the other bootstrap functions; under apitrace's EGL tracer that library is the tracer, which has
// no GLX, and libepoxy aborts ("glXGetCurrentContext() not found") before its resolver-failure
// handler is consulted. HeadlessContext holds one: the process then has no GLX context by
// construction, so the answer is the true one, and libepoxy resolves every GL entry point through
// EGL (the tracer's, when traced). The destructor gives libepoxy its own lookup back (a window
// opened later in the same process is GLX).
class NoGlxContextForEpoxy {
public:
    NoGlxContextForEpoxy();
    ~NoGlxContextForEpoxy();
    NoGlxContextForEpoxy(const NoGlxContextForEpoxy&) = delete;
    NoGlxContextForEpoxy& operator=(const NoGlxContextForEpoxy&) = delete;

private:
    void* previous_ = nullptr;  // libepoxy's entry for glXGetCurrentContext before this
};

}  // namespace oasis
