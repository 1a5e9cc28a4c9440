// Command-line parsing: defaults, every scene option, and a message naming the option for each
// kind of bad input.
#include <gtest/gtest.h>

#include "cli/options.h"

namespace oasis {
namespace {

ParseResult parse(std::vector<std::string> arguments) { return parseCommandLine(arguments); }

TEST(Cli, DefaultsAndSubcommands) {
    ParseResult none = parse({});
    ASSERT_TRUE(none.ok);
    EXPECT_EQ(none.options.command, Command::Default);
    EXPECT_EQ(none.options.scene.width, 1280);
    EXPECT_EQ(none.options.scene.height, 720);
    EXPECT_EQ(none.options.scene.gbuffer, "standard");
    EXPECT_EQ(none.options.pipeline, PipelineKind::Deferred);
    EXPECT_EQ(none.options.view, "final");
    EXPECT_TRUE(none.options.scene.water.reflections);
    EXPECT_EQ(parse({"render"}).options.command, Command::Render);
    EXPECT_EQ(parse({"compare"}).options.command, Command::Compare);
    EXPECT_EQ(parse({"window"}).options.command, Command::Window);
    EXPECT_TRUE(parse({"compare", "--help"}).options.help);
}

TEST(Cli, SceneOptions) {
    ParseResult r = parse({"render", "--size", "320x200", "--time", "12.5", "--hour", "18", "--camera",
                           "1,2.5,-3,90,-10", "--gbuffer", "full", "--pipeline", "forward", "--view",
                           "stencil", "--out", "x.png", "--reflections", "off", "--ripples", "0",
                           "--absorption", "0.5", "--water-level", "-2", "--stop-before", "ToneMapPass"});
    ASSERT_TRUE(r.ok) << r.error;
    const Options& o = r.options;
    EXPECT_EQ(o.scene.width, 320);
    EXPECT_EQ(o.scene.height, 200);
    EXPECT_DOUBLE_EQ(o.scene.timeSeconds, 12.5);
    EXPECT_DOUBLE_EQ(*o.scene.hour, 18.0);
    ASSERT_TRUE(o.scene.camera);
    EXPECT_EQ(o.scene.camera->position, glm::dvec3(1, 2.5, -3));
    EXPECT_FLOAT_EQ(o.scene.camera->yawDegrees, 90.0f);
    EXPECT_FLOAT_EQ(o.scene.camera->pitchDegrees, -10.0f);
    EXPECT_EQ(o.scene.gbuffer, "full");
    EXPECT_EQ(o.pipeline, PipelineKind::Forward);
    EXPECT_EQ(o.view, "stencil");
    EXPECT_EQ(o.out, "x.png");
    EXPECT_FALSE(o.scene.water.reflections);
    EXPECT_FLOAT_EQ(o.scene.water.rippleStrength, 0.0f);
    EXPECT_FLOAT_EQ(o.scene.water.absorption, 0.5f);
    EXPECT_FLOAT_EQ(o.scene.water.level, -2.0f);
    EXPECT_EQ(o.stopBefore, "ToneMapPass");
    EXPECT_TRUE(parse({"compare", "--json", "--out-dir", "d", "--frames", "3"}).options.json);
}

TEST(Cli, BadInputNamesTheOption) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"--bogus"}, "--bogus"},
        {{"paint"}, "paint"},
        {{"render", "--size"}, "--size"},
        {{"render", "--size", "0x0"}, "--size"},
        {{"render", "--size", "abc"}, "--size"},
        {{"render", "--size", "12x"}, "--size"},
        {{"render", "--time", "soon"}, "--time"},
        {{"render", "--time", "nan"}, "--time"},
        {{"render", "--hour", "25"}, "--hour"},
        {{"render", "--camera", "1,2,3"}, "--camera"},
        {{"render", "--camera", "1,2,3,4,95"}, "--camera"},
        {{"render", "--gbuffer", "nope"}, "--gbuffer"},
        {{"render", "--view", "nope"}, "--view"},
        {{"render", "--pipeline", "nope"}, "--pipeline"},
        {{"render", "--reflections", "maybe"}, "--reflections"},
        {{"render", "--ripples", "-1"}, "--ripples"},
        {{"compare", "--pipeline", "forward"}, "--pipeline"},
        {{"compare", "--frames", "0"}, "--frames"},
    };
    for (const auto& [arguments, option] : cases) {
        ParseResult r = parse(arguments);
        EXPECT_FALSE(r.ok) << arguments.back();
        EXPECT_NE(r.error.find(option), std::string::npos) << "'" << r.error << "' should name " << option;
    }
}

TEST(Cli, ValueParsers) {
    int w = 0, h = 0;
    EXPECT_TRUE(parseSize("1x1", w, h));
    EXPECT_EQ(w, 1);
    EXPECT_FALSE(parseSize("-5x10", w, h));
    EXPECT_FALSE(parseSize("10*10", w, h));
    CameraPose pose;
    EXPECT_TRUE(parseCameraPose("1e5,0,-1e5,0,-89.9", pose));
    EXPECT_EQ(pose.position.x, 1e5);
    EXPECT_FALSE(parseCameraPose("1,2,3,4,5,6", pose));
    EXPECT_FALSE(parseCameraPose("1,,3,4,5", pose));
}

TEST(Cli, HelpTextListsTheTables) {
    EXPECT_NE(usage(Command::Render).find("reflection"), std::string::npos);  // from the debug view table
    EXPECT_NE(usage(Command::Render).find("full, standard"), std::string::npos);  // from the layout table
}

}  // namespace
}  // namespace oasis
