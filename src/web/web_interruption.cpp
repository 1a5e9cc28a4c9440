// io/interruption.h for the page: a browser tab sends no signals and runs no child processes,
// so nothing is ever removed on an interruption; registering a file is a no-op.
#include "io/interruption.h"

namespace oasis {

void installInterruptionCleanup() {}
RemovedOnInterrupt::RemovedOnInterrupt(const std::string&, Kind) {}
RemovedOnInterrupt& RemovedOnInterrupt::operator=(RemovedOnInterrupt&& other) noexcept {
    slot_ = other.slot_;
    other.slot_ = -1;
    return *this;
}
void RemovedOnInterrupt::release() { slot_ = -1; }
InterruptionHeld::InterruptionHeld() {}
InterruptionHeld::~InterruptionHeld() {}
int heldSignal() { return 0; }
void endForHeldSignal() {}

}  // namespace oasis
