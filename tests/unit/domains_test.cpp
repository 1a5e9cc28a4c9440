// Covers src/cli/input_domains.h through the parser: every row's bounds (just inside accepted, just
// outside refused with a message that names the option and states the domain), the extreme numbers
// a fuzzer tries (-0, subnormals, 6.9e10, 1e308, nan, inf, hex, spaces), the yaw's wrap; and the
// depth below the parser: chunk ranges and noise cells stay defined for any double.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cli/input_domains.h"
#include "cli/options.h"
#include "render/shader_library.h"
#include "scene/camera.h"
#include "scene/noise.h"
#include "scene/terrain.h"
#include "scene/vegetation.h"

namespace oasis {
namespace {

// The command line that gives `text` to the domain's field (other camera fields inside theirs).
std::vector<std::string> argumentsFor(const InputDomain& domain, const std::string& text) {
    std::string name = domain.name;
    if (name.rfind("--camera ", 0) == 0) {
        static const std::vector<std::string> fields = {"X", "Y", "Z", "YAW", "PITCH"};
        std::vector<std::string> values = {"0", "50", "0", "0", "0"};
        for (size_t k = 0; k < fields.size(); ++k)
            if (name == "--camera " + fields[k]) values[k] = text;
        return {"render", "--camera", values[0] + "," + values[1] + "," + values[2] + "," + values[3] + "," + values[4]};
    }
    if (name == "--size W") return {"render", "--size", text + "x18"};
    if (name == "--size H") return {"render", "--size", "32x" + text};
    if (name == "--frames" || name == "--seed" || name == "--until-ci") return {"compare", name, text};
    if (name == "--driver-timeout") return {"compare", "--driver", "llvmpipe", "--driver", "zink", name, text};
    // The exposure scales the HDR views only (a rule refuses it on the final view: cli/option_rules.h).
    if (name == "--view-exposure") return {"render", "--view", "radiance", name, text};
    if (name == "--range LO") return {"render", "--view", "depth", "--range", text + ",1e9"};
    if (name == "--range HI") return {"render", "--view", "depth", "--range", "-1e9," + text};
    if (name == "--shard I") return {"check", "--shard", text + "/1000"};
    if (name == "--shard N") return {"check", "--shard", "1/" + text};
    if (name == "--case-timeout" || name == "--jobs" || name == "--retries") return {"check", name, text};
    if (name == "--at X") return {"probe", "--size", "32768x18", "--at", text + ",0"};
    if (name == "--at Y") return {"probe", "--size", "32x32768", "--at", "0," + text};
    return {"render", name, text};
}

std::string number(double value) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.17g", value);
    return text;
}

TEST(InputDomains, EveryNumericFlagHasARow) {
    for (const char* name : {"--time", "--hour", "--camera X", "--camera Y", "--camera Z", "--camera YAW",
                             "--camera PITCH", "--water-level", "--ripples", "--absorption", "--vegetation-density",
                             "--wind", "--lights", "--size W", "--size H", "--frames", "--driver-timeout"}) {
        EXPECT_NO_THROW(inputDomain(name)) << name;
    }
    EXPECT_THROW(inputDomain("--nope"), std::out_of_range);
    for (const InputDomain& domain : inputDomains()) {
        EXPECT_LT(domain.low, domain.high) << domain.name;
        EXPECT_GT(std::string(domain.reason).size(), 5u) << domain.name << " says why";
    }
}

TEST(InputDomains, BoundsAcceptedAndJustOutsideRefusedNamingTheDomain) {
    for (const InputDomain& domain : inputDomains()) {
        if (domain.kind == DomainKind::Angle) continue;
        bool integer = domain.kind == DomainKind::Integer;
        for (double inside : {domain.low, domain.high}) {
            // LO < HI: a range's low end at the top of its domain has no high end above it.
            if ((std::string(domain.name) == "--range LO" && inside == domain.high) ||
                (std::string(domain.name) == "--range HI" && inside == domain.low))
                continue;
            ParseResult r = parseCommandLine(argumentsFor(domain, integer ? std::to_string(int(inside)) : number(inside)));
            EXPECT_TRUE(r.ok) << domain.name << " " << inside << ": " << r.error;
        }
        double below = integer ? domain.low - 1.0 : std::nextafter(domain.low, -INFINITY);
        double above = integer ? domain.high + 1.0 : std::nextafter(domain.high, INFINITY);
        for (double outside : {below, above}) {
            if (integer && outside < 0.0) continue;  // a sign is refused as such (IntegersAreDigitsOnly)
            std::string text = integer ? std::to_string(int(outside)) : number(outside);
            std::vector<std::string> arguments = argumentsFor(domain, text);
            ParseResult r = parseCommandLine(arguments);
            EXPECT_FALSE(r.ok) << domain.name << " accepted " << text;
            // --size names the flag and quotes WxH; the others their row's name and the number.
            bool size = std::string(domain.name).rfind("--size", 0) == 0;
            EXPECT_NE(r.error.find(size ? "--size" : domain.name), std::string::npos) << r.error;
            EXPECT_NE(r.error.find(describeDomain(domain)), std::string::npos) << "states the domain: " << r.error;
            EXPECT_NE(r.error.find("'" + (size ? arguments.back() : text) + "'"), std::string::npos)
                << "quotes the value: " << r.error;
        }
    }
}

TEST(InputDomains, ExtremeNumbersAreRefusedWithTheDomain) {
    const std::vector<std::string> malformed = {"nan", "NaN", "inf", "-inf", "infinity", "1e400", "-1e400", "0x10",
                                                " 1", "1 ", "", "1e", "1.2.3", "--1", "1,5", "."};
    const std::vector<std::string> huge = {"6.9e10", "-6.9e10", "1e308", "-1e308"};
    for (const InputDomain& domain : inputDomains()) {
        std::vector<std::string> texts = malformed;
        if (domain.kind != DomainKind::Angle) texts.insert(texts.end(), huge.begin(), huge.end());  // an angle wraps
        for (const std::string& text : texts) {
            std::string error;
            double value = 0.0;
            EXPECT_FALSE(parseInDomain(text, domain, value, error)) << domain.name << " accepted '" << text << "'";
            EXPECT_NE(error.find(describeDomain(domain)), std::string::npos) << error;
        }
    }
}

TEST(InputDomains, NegativeZeroAndSubnormalsReadAsTheirValues) {
    for (const char* name : {"--time", "--camera X", "--camera YAW", "--camera PITCH", "--water-level", "--ripples"}) {
        const InputDomain& domain = inputDomain(name);
        double value = 1.0;
        std::string error;
        ASSERT_TRUE(parseInDomain("-0", domain, value, error)) << name << ": " << error;
        EXPECT_EQ(value, 0.0);
        EXPECT_FALSE(std::signbit(value)) << name << ": -0 reads as +0";
        for (const char* subnormal : {"4.9e-324", "-4.9e-324", "2.2e-310"}) {
            bool wanted = domain.low <= std::strtod(subnormal, nullptr);
            EXPECT_EQ(parseInDomain(subnormal, domain, value, error), wanted) << name << " " << subnormal << " " << error;
            if (wanted) EXPECT_TRUE(std::isfinite(value));
        }
    }
}

TEST(InputDomains, IntegersAreDigitsOnly) {
    for (const char* name : {"--lights", "--frames", "--size W"}) {
        const InputDomain& domain = inputDomain(name);
        int value = -1;
        std::string error;
        EXPECT_TRUE(parseIntInDomain("1", domain, value, error)) << error;
        EXPECT_EQ(value, 1);
        for (const char* text : {"+1", "-0", " 1", "1 ", "1.0", "1e2", "0x1", "", "4294967297", "99999999999"})
            EXPECT_FALSE(parseIntInDomain(text, domain, value, error)) << name << " accepted '" << text << "'";
    }
    for (const char* size : {" 64x36", "+32x+18", "64x 36", "32x18 ", "0x10", "32768x1", "32769x1", "1x32769"}) {
        int w = 0, h = 0;
        bool wanted = std::string(size) == "32768x1";
        EXPECT_EQ(parseSize(size, w, h), wanted) << "'" << size << "'";
    }
}

TEST(InputDomains, AngleWrapsInDoubleAndSaysSo) {
    const InputDomain& yaw = inputDomain("--camera YAW");
    struct Case {
        const char* text;
        double expected;
        bool wrapped;
    };
    for (const Case& c : {Case{"0", 0.0, false}, Case{"-180", -180.0, false}, Case{"180", -180.0, true},
                          Case{"179.5", 179.5, false}, Case{"540", -180.0, true}, Case{"-190", 170.0, true},
                          Case{"1e9", -80.0, true}, Case{"1e308", std::fmod(1e308 + 180.0, 360.0) - 180.0, true}}) {
        double value = 0.0;
        bool wrapped = false;
        std::string error;
        ASSERT_TRUE(parseInDomain(c.text, yaw, value, error, &wrapped)) << c.text << ": " << error;
        EXPECT_NEAR(value, c.expected, 1e-9) << c.text;
        EXPECT_GE(value, -180.0);
        EXPECT_LT(value, 180.0);
        EXPECT_EQ(wrapped, c.wrapped) << c.text;
    }
    ParseResult r = parseCommandLine({"render", "--camera", "435,4,140,1e9,-3"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_FLOAT_EQ(r.options.scene.camera->yawDegrees, -80.0f);
    ASSERT_EQ(r.notes.size(), 1u) << "the wrap is said once";
    EXPECT_NE(r.notes[0].find("--camera YAW 1e9 is -80 degrees"), std::string::npos) << r.notes[0];
    EXPECT_TRUE(parseCommandLine({"render", "--camera", "435,4,140,30,-3"}).notes.empty());
}

TEST(InputDomains, HelpPrintsTheTable) {
    std::string help = usage(Command::Render);
    for (const InputDomain& domain : inputDomains()) {
        EXPECT_NE(help.find(domain.name), std::string::npos) << domain.name;
        EXPECT_NE(help.find(describeDomain(domain)), std::string::npos) << domain.name;
    }
}

// docs/cli.md's table is this table: each row's name, unit and domain as the code states them.
TEST(InputDomains, DocsStateEveryDomain) {
    std::ifstream file(findShaderDirectory() + "/../docs/cli.md");
    ASSERT_TRUE(file) << "docs/cli.md beside the shaders";
    std::stringstream text;
    text << file.rdbuf();
    for (const InputDomain& domain : inputDomains()) {
        std::string name = domain.name;
        std::string row = "| `" + (name == "--size W" ? std::string("--size W`, `--size H") : name) + "` | " + domain.unit +
                          " | " + describeDomain(domain) + " |";
        if (name == "--size H") continue;  // shares --size W's row
        EXPECT_NE(text.str().find(row), std::string::npos) << "docs/cli.md lacks the row " << row;
    }
}

TEST(InputDomains, TheFlightStaysInsideThePositionDomainOverTheTimeDomain) {
    const InputDomain& time = inputDomain("--time");
    const InputDomain& x = inputDomain("--camera X");
    for (double t : {time.low, time.high}) {
        CameraPose pose = defaultCameraPath(TerrainShape{}, t);
        EXPECT_GE(pose.position.x, x.low) << t;
        EXPECT_LE(pose.position.x, x.high) << t;
        EXPECT_TRUE(std::isfinite(pose.position.y)) << t;
    }
}

// ---- Below the parser: whatever double reaches them, the loops end and nothing is undefined ----

TEST(DomainDepth, ChunkRangeRefusesWhatIntCannotIndex) {
    const double size = 32.0, distance = 600.0;
    ChunkRange range;
    ASSERT_TRUE(chunkRangeAround(glm::dvec3(100.0, 0.0, -100.0), distance, size, range));
    EXPECT_EQ(range.first, glm::ivec2(int(std::floor(-500.0 / 32.0)), int(std::floor(-700.0 / 32.0))));
    EXPECT_EQ(range.last, glm::ivec2(int(std::floor(700.0 / 32.0)), int(std::floor(500.0 / 32.0))));
    // 2^36 (the hang: the last index reached INT_MAX), beyond int, beyond everything.
    for (double far : {68719476110.0, 6.9e10, 1e300, -1e300, double(INFINITY), std::nan("")}) {
        EXPECT_FALSE(chunkRangeAround(glm::dvec3(far, 0.0, 0.0), distance, size, range)) << far;
        EXPECT_FALSE(chunkRangeAround(glm::dvec3(0.0, 0.0, far), distance, size, range)) << far;
    }
    EXPECT_FALSE(chunkRangeAround(glm::dvec3(0.0), 1e9, size, range)) << "a range too wide to walk";
    EXPECT_FALSE(chunkRangeAround(glm::dvec3(0.0), distance, 0.0, range)) << "zero-size chunks";
}

TEST(DomainDepth, VegetationUpdateEndsForAnyCamera) {
    auto start = std::chrono::steady_clock::now();
    for (double far : {68719476110.0, 68719476104.0, 1e300, std::nan("")}) {
        VegetationField field;
        field.update(TerrainShape{}, 0.0f, VegetationSettings{}, 4, glm::dvec3(far, 50.0, 0.0));
        EXPECT_EQ(field.stats().chunksInRange, 0u) << far;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 10.0) << "a time limit against the hang, not a speed test";
}

TEST(DomainDepth, NoiseStaysFiniteForAnyPoint) {
    for (double far : {1e300, -1e300, 6.9e10, 2147483647.5 * 650.0, 1.7e308, double(INFINITY), std::nan("")}) {
        glm::vec3 n = fractalNoise(glm::dvec2(far, far), kMaxNoiseOctaves);
        EXPECT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) << far;
        glm::vec4 origin = skewedOrigin(glm::dvec2(far, -far * 0.5));
        EXPECT_LE(std::fabs(origin.z), 2147483648.0f) << far;
        EXPECT_LE(std::fabs(origin.w), 2147483648.0f) << far;
        CameraPose flight = defaultCameraPath(TerrainShape{}, far);
        EXPECT_TRUE(std::isfinite(flight.position.y) || !std::isfinite(far)) << far;
    }
}

}  // namespace
}  // namespace oasis
