// PresentPass: puts the Display target on the window's framebuffer with a full-screen draw that
// samples it (never a blit or a copy, whose behaviour differs between drivers).
#pragma once
#include "passes/pass.h"

namespace oasis {

class PresentPass {
public:
    std::string name() const { return "PresentPass"; }
    void run(PassContext& context, int windowWidth, int windowHeight);
};

}  // namespace oasis
