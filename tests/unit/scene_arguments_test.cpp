// Covers src/cli/scene_arguments.h: every scene option written back and parsed again gives the same
// options (the table and the parser agree), defaults are left out, numbers are written exactly and
// command lines are quoted as a shell reads them.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "cli/options.h"
#include "cli/scene_arguments.h"

namespace oasis {
namespace {

// A value other than the default for every row of the table: a new row needs one here.
const std::map<std::string, std::string> kExamples = {
    {"--size", "160x90"},          {"--time", "12.5"},          {"--hour", "18.2"},
    {"--camera", "420,14.25,170,60,-10"}, {"--gbuffer", "standard"}, {"--depth", "reversed-z"},
    {"--reflections", "off"},      {"--reflection-bounds", "off"}, {"--reflection-resolution", "half"},
    {"--reflection-plant-cull", "on"}, {"--water-level", "-1.5"}, {"--ripples", "0"},
    {"--absorption", "0.2"},       {"--vegetation", "off"},     {"--vegetation-density", "2.5"},
    {"--wind", "0.3"},             {"--billboards", "whole"},   {"--tone-map", "separate"},
    {"--depth-read", "copy"},      {"--shadows", "off"},        {"--shadow-quality", "high"},
    {"--lights", "64"},            {"--api", "gles"},           {"--force", "no-ssbo,no-dsa"},
    {"--no-compute", ""},          {"--lights-path", "ubo"},    {"--light-method", "tiled"},
    {"--workarounds", "none"},     {"--workarounds-file", "/dev/null"},  // an empty file: no rules
};

SceneOptions parsed(const std::vector<std::string>& arguments) {
    std::vector<std::string> line = {"render"};
    line.insert(line.end(), arguments.begin(), arguments.end());
    ParseResult result = parseCommandLine(line);
    EXPECT_TRUE(result.ok) << result.error;
    return result.options.scene;
}

std::vector<std::string> written(const SceneOptions& scene) {
    std::vector<std::string> all = sceneArguments(scene, SceneArgumentKind::Picture);
    std::vector<std::string> driver = sceneArguments(scene, SceneArgumentKind::Driver);
    all.insert(all.end(), driver.begin(), driver.end());
    return all;
}

TEST(SceneArguments, DefaultsWriteOnlyTheSize) {
    SceneOptions defaults;
    EXPECT_EQ(sceneArguments(defaults, SceneArgumentKind::Picture), (std::vector<std::string>{"--size", "1280x720"}));
    EXPECT_TRUE(sceneArguments(defaults, SceneArgumentKind::Driver).empty());
    // Given at their defaults, options are still left out: the line is canonical.
    EXPECT_EQ(written(parsed({"--ripples", "1", "--shadows", "on", "--time", "0", "--gbuffer", "compact"})),
              (std::vector<std::string>{"--size", "1280x720"}));
}

TEST(SceneArguments, EveryRowHasAnExampleAndRoundTrips) {
    for (const SceneArgument& row : sceneArgumentTable()) {
        auto example = kExamples.find(row.flag);
        ASSERT_NE(example, kExamples.end()) << row.flag << " has no example in this test";
        std::vector<std::string> given = {row.flag};
        if (!row.bare) given.push_back(example->second);
        SceneOptions scene = parsed(given);
        std::vector<std::string> line = written(scene);
        // The option given is written (a non-default value), and parsing the line gives the same line.
        bool present = false;
        for (const std::string& argument : line) present = present || argument == row.flag;
        EXPECT_TRUE(present) << row.flag << ": " << joinArguments(line);
        EXPECT_EQ(written(parsed(line)), line) << row.flag;
    }
}

TEST(SceneArguments, AllAtOnceInTheTablesOrder) {
    // What the picture shows first, then how the driver drew it; each in the rows' order.
    std::vector<std::string> given;
    for (SceneArgumentKind kind : {SceneArgumentKind::Picture, SceneArgumentKind::Driver})
        for (const SceneArgument& row : sceneArgumentTable()) {
            if (row.kind != kind) continue;
            given.push_back(row.flag);
            if (!row.bare) given.push_back(kExamples.at(row.flag));
        }
    SceneOptions scene = parsed(given);
    std::vector<std::string> line = written(scene);
    EXPECT_EQ(line, given);
    EXPECT_EQ(joinArguments(sceneArguments(scene, SceneArgumentKind::Driver)),
              "--no-compute --lights-path ubo --light-method tiled --force no-ssbo,no-dsa --workarounds none "
              "--workarounds-file /dev/null --api gles");
    SceneOptions again = parsed(line);
    EXPECT_EQ(again.camera->position.y, 14.25);
    EXPECT_EQ(again.camera->pitchDegrees, -10.0f);
    EXPECT_EQ(again.water.absorption, 0.2f);
    EXPECT_EQ(*again.hour, 18.2);
}

TEST(SceneArguments, KindsSplitPictureFromDriver) {
    for (const char* flag : {"--size", "--hour", "--camera", "--gbuffer", "--lights", "--shadows"})
        EXPECT_EQ(findSceneArgument(flag)->kind, SceneArgumentKind::Picture) << flag;
    for (const char* flag : {"--api", "--force", "--no-compute", "--lights-path", "--light-method", "--workarounds",
                             "--workarounds-file"})
        EXPECT_EQ(findSceneArgument(flag)->kind, SceneArgumentKind::Driver) << flag;
    for (const char* flag : {"--view", "--out", "--pipeline", "--legend", "--gl-debug", "--reference"})
        EXPECT_EQ(findSceneArgument(flag), nullptr) << flag;
}

TEST(SceneArguments, NumbersAreWrittenExactlyAndShort) {
    EXPECT_EQ(exactNumber(0.0), "0");
    EXPECT_EQ(exactNumber(-0.0), "0");
    EXPECT_EQ(exactNumber(18.0), "18");
    EXPECT_EQ(exactNumber(0.1), "0.1");
    EXPECT_EQ(exactNumber(0.09f, true), "0.09");  // not 0.0900000036
    EXPECT_EQ(std::stod(exactNumber(double(0.09f))), double(0.09f));
    EXPECT_EQ(exactNumber(420.0), "420");  // not 4.2e+02
    EXPECT_EQ(exactNumber(-1234567.25), "-1234567.25");
    EXPECT_EQ(exactNumber(1e-7), "0.0000001");
    EXPECT_EQ(exactNumber(1e-30), "1e-30");  // beyond 17 decimals: exponent form
    EXPECT_EQ(exactNumber(1e300), "1e+300");
    EXPECT_EQ(std::stod(exactNumber(1.0 / 3.0)), 1.0 / 3.0);
    EXPECT_EQ(std::stof(exactNumber(1.0f / 3.0f, true)), 1.0f / 3.0f);
}

TEST(SceneArguments, LinesSplitAndJoinAndQuote) {
    EXPECT_EQ(splitArguments("--size 160x90  --hour 18 "), (std::vector<std::string>{"--size", "160x90", "--hour", "18"}));
    EXPECT_TRUE(splitArguments("").empty());
    EXPECT_EQ(joinArguments({"--size", "160x90"}), "--size 160x90");
    EXPECT_EQ(shellCommandLine({"oasis", "render", "--out", "my frame.png", "--camera", "1,2,3,4,-5"}),
              "oasis render --out 'my frame.png' --camera 1,2,3,4,-5");
    EXPECT_EQ(shellCommandLine({"it's", ""}), "'it'\\''s' ''");
    ParseResult result = parseCommandLine({"render", "--out", "a b.png"});
    EXPECT_EQ(result.options.commandLine, "oasis render --out 'a b.png'");
}

}  // namespace
}  // namespace oasis
