// The driver set-up table (cli/driver_setups.h); docs/compatibility.md describes the set-ups.
#include "cli/driver_setups.h"

namespace oasis {

const std::vector<DriverSetup>& driverSetups() {
    static const std::vector<DriverSetup> setups = [] {
        const std::string noSsbo = "-GL_ARB_shader_storage_buffer_object -GL_ARB_compute_shader";
        std::vector<DriverSetup> table = {
            // Whatever driver this machine gives by default (AMD, Intel, NVIDIA, Mesa...): nothing set,
            // no renderer required; the Mesa-selecting variables are cleared as for every set-up.
            {"native", "this machine's default driver, whatever its name (nothing set, no renderer check)", {}, {}, "",
             "an OpenGL driver with EGL"},
            {"llvmpipe", "Mesa llvmpipe, GL 4.5 core (the default)", {}, {}, "llvmpipe", "Mesa's llvmpipe (libgl1-mesa-dri)"},
            {"zink", "zink over lavapipe, GL 4.6 core",
             {{"LIBGL_ALWAYS_SOFTWARE", "1"}, {"GALLIUM_DRIVER", "zink"}, {"XDG_RUNTIME_DIR", kRuntimeDirValue}},
             {}, "zink", "zink and lavapipe (mesa-vulkan-drivers)"},
            {"softpipe", "Mesa softpipe, GL 3.3 core with extensions (~30x slower: use small sizes)",
             {{"GALLIUM_DRIVER", "softpipe"}}, {}, "softpipe", "Mesa's softpipe (libgl1-mesa-dri)"},
            // The shader cache would report earlier compiles (with SSBOs) as successes: off.
            {"no-ssbo-compute", "llvmpipe without SSBOs and compute shaders (GL 4.2)",
             {{"MESA_EXTENSION_OVERRIDE", noSsbo}, {"MESA_SHADER_CACHE_DISABLE", "true"}}, {}, "llvmpipe",
             "Mesa's llvmpipe (libgl1-mesa-dri)"},
            {"softpipe-bare", "softpipe without SSBOs, compute shaders and stencil texturing (bare 3.3)",
             {{"GALLIUM_DRIVER", "softpipe"}, {"MESA_EXTENSION_OVERRIDE", noSsbo + " -GL_ARB_stencil_texturing"},
              {"MESA_SHADER_CACHE_DISABLE", "true"}},
             {}, "softpipe", "Mesa's softpipe (libgl1-mesa-dri)"},
            {"bare-gl33", "llvmpipe, --force gl33,no-ssbo,no-compute,no-stencil-texturing",
             {}, {"--force", "gl33,no-ssbo,no-compute,no-stencil-texturing"}, "llvmpipe",
             "Mesa's llvmpipe (libgl1-mesa-dri)"},
            // The OpenGL ES tiers (--api gles): llvmpipe's ES 3.2, the same made ES 3.1 by Mesa (GLSL
            // ES 3.10: `precise` only by EXT_/OES_gpu_shader5, both listed), and limited to ES 3.0.
            {"gles", "llvmpipe, OpenGL ES 3.2 (--api gles)", {}, {"--api", "gles"}, "llvmpipe",
             "Mesa's llvmpipe with OpenGL ES (libgles2 / libegl-mesa0)"},
            {"gles31", "llvmpipe, OpenGL ES 3.1 (MESA_GLES_VERSION_OVERRIDE=3.1, --api gles)",
             {{"MESA_GLES_VERSION_OVERRIDE", "3.1"}}, {"--api", "gles"}, "llvmpipe",
             "Mesa's llvmpipe with OpenGL ES (libgles2 / libegl-mesa0)"},
            {"gles30", "llvmpipe, OpenGL ES 3.2 treated as ES 3.0 (--api gles --force gles30)", {},
             {"--api", "gles", "--force", "gles30"}, "llvmpipe", "Mesa's llvmpipe with OpenGL ES (libgles2 / libegl-mesa0)"},
        };
        // Each forced fallback alone on llvmpipe (--force NAME): bit-identical to llvmpipe by design
        // (gles30 is the ES row above: it needs --api gles). driver_setups_test holds this list to
        // every name --force accepts.
        for (const char* name : {"gl33", "no-ssbo", "no-compute", "no-stencil-texturing", "no-dsa", "no-clip-control",
                                 "no-depth-clamp", "no-read-only-depth"})
            table.push_back({name, std::string("llvmpipe, --force ") + name, {}, {"--force", name}, "llvmpipe",
                             "Mesa's llvmpipe (libgl1-mesa-dri)"});
        return table;
    }();
    return setups;
}

const DriverSetup* findDriverSetup(const std::string& name) {
    for (const DriverSetup& setup : driverSetups())
        if (setup.name == name) return &setup;
    return nullptr;
}

std::string driverSetupNames() {
    std::string names;
    for (const DriverSetup& setup : driverSetups()) names += (names.empty() ? "" : ", ") + setup.name;
    return names;
}

const std::vector<std::string>& driverSelectingVariables() {
    static const std::vector<std::string> variables = {"GALLIUM_DRIVER", "LIBGL_ALWAYS_SOFTWARE",
                                                       "MESA_EXTENSION_OVERRIDE", "MESA_GL_VERSION_OVERRIDE",
                                                       "MESA_GLES_VERSION_OVERRIDE", "MESA_GLSL_VERSION_OVERRIDE",
                                                       "MESA_LOADER_DRIVER_OVERRIDE"};
    return variables;
}

}  // namespace oasis
