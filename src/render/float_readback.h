// A float RGBA target that a full-screen pass draws into so the CPU can read its results back:
// the surface positions lighting reads, a view's values, the probe's slots. Made on first use and
// remade when the size changes.
#pragma once
#include <vector>

#include "gl/objects.h"

namespace oasis {

class FloatReadback {
public:
    // Binds the target's framebuffer (made or remade for this size) and sets the viewport over it.
    void bindForDrawing(int width, int height);
    GLuint framebuffer() const { return framebuffer_.name(); }
    // What was drawn: RGBA floats, bottom row first.
    std::vector<float> read() const;

private:
    gl::Texture texture_;
    gl::Framebuffer framebuffer_;
    int width_ = 0, height_ = 0;
};

}  // namespace oasis
