// NoGlxContextForEpoxy: replaces libepoxy's public glXGetCurrentContext pointer (kept apart from
// gl_context.cpp: <epoxy/glx.h> brings in Xlib's macros).
#include "context/epoxy_glx_probe.h"

#include <epoxy/glx.h>

namespace oasis {
namespace {

// libepoxy calls through its exported pointer `epoxy_glXGetCurrentContext` (glXGetCurrentContext
// is a macro for it), from the application and from its own dispatch code alike; until first use it
// points at a stub that resolves the real function. Pointing it here answers without a lookup.
GLXContext noGlxContext() { return nullptr; }

}  // namespace

NoGlxContextForEpoxy::NoGlxContextForEpoxy() {
    previous_ = reinterpret_cast<void*>(epoxy_glXGetCurrentContext);
    epoxy_glXGetCurrentContext = noGlxContext;
}

NoGlxContextForEpoxy::~NoGlxContextForEpoxy() {
    epoxy_glXGetCurrentContext = reinterpret_cast<decltype(epoxy_glXGetCurrentContext)>(previous_);
}

}  // namespace oasis
