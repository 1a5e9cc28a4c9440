// Covers src/cli/driver_setups.h and compare --driver / --reference parsing in src/cli/options.cpp:
// the set-up table, what a child render gets passed on, and the combinations refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "cli/driver_setups.h"
#include "cli/options.h"
#include "gl/capabilities.h"

namespace oasis {
namespace {

TEST(DriverSetups, TableSelectsDriversAndTiers) {
    const DriverSetup* zink = findDriverSetup("zink");
    ASSERT_NE(zink, nullptr);
    EXPECT_EQ(zink->rendererPrefix, "zink");
    bool runtimeDir = false, galliumZink = false;
    for (const auto& [name, value] : zink->environment) {
        runtimeDir |= name == "XDG_RUNTIME_DIR" && value == kRuntimeDirValue;
        galliumZink |= name == "GALLIUM_DRIVER" && value == "zink";
    }
    EXPECT_TRUE(runtimeDir && galliumZink);
    const DriverSetup* noSsbo = findDriverSetup("no-ssbo");
    ASSERT_NE(noSsbo, nullptr);
    EXPECT_TRUE(noSsbo->environment.empty());
    EXPECT_EQ(noSsbo->arguments, (std::vector<std::string>{"--force", "no-ssbo"}));
    ASSERT_NE(findDriverSetup("llvmpipe"), nullptr);
    EXPECT_TRUE(findDriverSetup("llvmpipe")->environment.empty());
    // The OpenGL ES tiers: llvmpipe's own environment, --api gles (and --force gles30) for the child.
    ASSERT_NE(findDriverSetup("gles"), nullptr);
    EXPECT_TRUE(findDriverSetup("gles")->environment.empty());
    EXPECT_EQ(findDriverSetup("gles")->arguments, (std::vector<std::string>{"--api", "gles"}));
    // ES 3.1 is Mesa's version override (its variable is cleared for every other set-up's child).
    ASSERT_NE(findDriverSetup("gles31"), nullptr);
    EXPECT_EQ(findDriverSetup("gles31")->environment,
              (std::vector<std::pair<std::string, std::string>>{{"MESA_GLES_VERSION_OVERRIDE", "3.1"}}));
    EXPECT_EQ(findDriverSetup("gles31")->arguments, (std::vector<std::string>{"--api", "gles"}));
    const std::vector<std::string>& cleared = driverSelectingVariables();
    EXPECT_NE(std::find(cleared.begin(), cleared.end(), "MESA_GLES_VERSION_OVERRIDE"), cleared.end());
    ASSERT_NE(findDriverSetup("gles30"), nullptr);
    EXPECT_EQ(findDriverSetup("gles30")->arguments, (std::vector<std::string>{"--api", "gles", "--force", "gles30"}));
    // The child's arguments parse as a render command line.
    for (const char* name : {"gles", "gles31", "gles30"}) {
        std::vector<std::string> args = {"render"};
        for (const std::string& argument : findDriverSetup(name)->arguments) args.push_back(argument);
        EXPECT_TRUE(parseCommandLine(args).ok) << name << ": " << parseCommandLine(args).error;
    }
    // native: this machine's default driver, whatever its renderer: nothing set, nothing passed.
    const DriverSetup* native = findDriverSetup("native");
    ASSERT_NE(native, nullptr);
    EXPECT_TRUE(native->environment.empty() && native->arguments.empty());
    EXPECT_EQ(native->rendererPrefix, "") << "no renderer required";
    EXPECT_TRUE(parseCommandLine({"compare", "--driver", "native", "--reference", "sent.png"}).ok);
    EXPECT_TRUE(parseCommandLine({"compare", "--driver", "native", "--driver", "llvmpipe"}).ok);
    // A set-up for every name --force accepts (gles30's with --api gles), whose child parses.
    std::string names = gl::forcedFallbackNames();
    for (size_t at = 0; at < names.size();) {
        size_t end = names.find(", ", at);
        std::string name = names.substr(at, end == std::string::npos ? std::string::npos : end - at);
        at = end == std::string::npos ? names.size() : end + 2;
        const DriverSetup* tier = findDriverSetup(name);
        ASSERT_NE(tier, nullptr) << "no set-up for --force " << name;
        std::vector<std::string> args = {"render"};
        args.insert(args.end(), tier->arguments.begin(), tier->arguments.end());
        EXPECT_NE(std::find(args.begin(), args.end(), name), args.end()) << name << " is not forced by its set-up";
        EXPECT_TRUE(parseCommandLine(args).ok) << name << ": " << parseCommandLine(args).error;
    }
    // Every named set-up is in the list the errors print, once.
    for (const DriverSetup& setup : driverSetups()) {
        std::string names = ", " + driverSetupNames() + ",";
        EXPECT_NE(names.find(", " + setup.name + ","), std::string::npos) << setup.name;
    }
}

TEST(DriverSetups, CompareParsesDriversAndPassesTheSceneOn) {
    ParseResult r = parseCommandLine({"compare", "--driver", "llvmpipe", "--size", "160x90", "--hour", "18",
                                      "--no-compute", "--driver", "zink", "--pipeline", "forward", "--out-dir", "d",
                                      "--json"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.drivers, (std::vector<std::string>{"llvmpipe", "zink"}));
    EXPECT_TRUE(r.options.comparesDrivers());
    EXPECT_TRUE(r.options.sizeGiven);
    EXPECT_EQ(r.options.sceneArguments,
              (std::vector<std::string>{"--size", "160x90", "--hour", "18", "--no-compute", "--pipeline", "forward"}));
    ParseResult reference = parseCommandLine({"compare", "--reference", "sent.png"});
    ASSERT_TRUE(reference.ok) << reference.error;
    EXPECT_EQ(reference.options.reference, "sent.png");
    EXPECT_FALSE(reference.options.sizeGiven);
    EXPECT_FALSE(parseCommandLine({"compare"}).options.comparesDrivers());
}

TEST(DriverSetups, RefusedCombinations) {
    auto error = [](std::vector<std::string> args) {
        ParseResult r = parseCommandLine(args);
        EXPECT_FALSE(r.ok) << args.size();
        return r.error;
    };
    EXPECT_NE(error({"compare", "--driver", "nope", "--driver", "zink"}).find("one of: native, llvmpipe, zink"), std::string::npos);
    EXPECT_NE(error({"compare", "--driver", "zink"}).find("needs a second --driver or --reference"), std::string::npos);
    EXPECT_NE(error({"compare", "--driver", "zink", "--driver", "zink", "--driver", "llvmpipe"}).find("three"),
              std::string::npos);
    EXPECT_NE(error({"compare", "--driver", "zink", "--driver", "llvmpipe", "--reference", "a.png"}).find("not both"),
              std::string::npos);
    EXPECT_NE(error({"compare", "--reference", "a.jpg"}).find("PNG"), std::string::npos);
    EXPECT_NE(error({"render", "--driver", "zink"}).find("belongs to `oasis compare`"), std::string::npos);
    EXPECT_NE(error({"compare", "--pipeline", "forward"}).find("--pipeline"), std::string::npos);
}

}  // namespace
}  // namespace oasis
