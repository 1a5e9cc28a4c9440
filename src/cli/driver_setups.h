// The driver set-ups of this machine that `oasis compare --driver` can render a frame on: each a
// name, the environment variables that select the driver, extra oasis arguments (the forced
// tiers) and the renderer string the context must report. GL-free: the parser checks names here.
// The OpenGL ES tiers are rows too (gles, gles30: --api gles in the child's arguments), and
// `native`: this machine's default driver, whatever its renderer string.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace oasis {

struct DriverSetup {
    std::string name;
    std::string description;
    // Set in the child's environment; the value kRuntimeDirValue is replaced by a 0700 directory
    // oasis makes for the run (zink warns without one).
    std::vector<std::pair<std::string, std::string>> environment;
    std::vector<std::string> arguments;  // added to the child's `oasis render` command line
    std::string rendererPrefix;          // GL_RENDERER must start with this, or the driver is missing ("": any)
    std::string needs;                   // what the set-up needs on this machine, said when it is missing
};

constexpr const char* kRuntimeDirValue = "<runtime dir>";

const std::vector<DriverSetup>& driverSetups();
const DriverSetup* findDriverSetup(const std::string& name);
std::string driverSetupNames();  // "native, llvmpipe, zink, ..."

// Variables that select or limit a Mesa driver: cleared in every set-up's child first, so that the
// table alone says what each set-up is (a caller running under GALLIUM_DRIVER=zink still gets
// llvmpipe for `--driver llvmpipe`).
const std::vector<std::string>& driverSelectingVariables();

}  // namespace oasis
