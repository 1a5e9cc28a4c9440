// Covers src/cli/options.h: parseSize, parseCameraPose, parseCommandLine (subcommands, defaults, every option, errors naming the option).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/options.h"
#include "commands/session.h"
#include "debug/debug_views.h"
#include "render/gbuffer_layout.h"

namespace oasis {
namespace {

ParseResult parse(std::vector<std::string> arguments) { return parseCommandLine(arguments); }

TEST(Cli, DefaultsAndSubcommands) {
    ParseResult none = parse({});
    ASSERT_TRUE(none.ok);
    EXPECT_EQ(none.options.command, Command::Default);
    EXPECT_EQ(none.options.scene.width, 1280);
    EXPECT_EQ(none.options.scene.height, 720);
    EXPECT_EQ(none.options.scene.gbuffer, defaultGBufferLayout().name);
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

TEST(Cli, NoComputeIsASceneOptionOfEverySubcommand) {
    EXPECT_FALSE(parse({}).options.scene.noCompute);
    for (const char* command : {"render", "compare", "window"}) {
        ParseResult result = parse({command, "--no-compute"});
        ASSERT_TRUE(result.ok) << command << ": " << result.error;
        EXPECT_TRUE(result.options.scene.noCompute) << command;
    }
    EXPECT_TRUE(parse({"--no-compute"}).options.scene.noCompute);
    EXPECT_NE(usage(Command::Render).find("--no-compute"), std::string::npos);
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

TEST(Cli, VegetationOptions) {
    Options defaults = parse({}).options;
    EXPECT_TRUE(defaults.scene.vegetation.enabled);
    EXPECT_EQ(defaults.scene.vegetation.density, 1.0f);
    Options o = parse({"render", "--vegetation", "off", "--vegetation-density", "2.5", "--wind", "0"}).options;
    EXPECT_FALSE(o.scene.vegetation.enabled);
    EXPECT_EQ(o.scene.vegetation.density, 2.5f);
    EXPECT_EQ(o.scene.vegetation.windStrength, 0.0f);
    SceneSettings scene = sceneSettingsFrom(o.scene);
    EXPECT_FALSE(scene.vegetation.enabled);
    EXPECT_EQ(scene.vegetation.density, 2.5f);
    EXPECT_NE(usage(Command::Render).find("--vegetation-density"), std::string::npos);
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


// ---- Value parsers in detail, every option under every subcommand, and each error's message ----

using Args = std::vector<std::string>;

// Fails the test unless parsing fails with a message that names `mention`.
void expectError(const Args& args, const std::string& mention) {
    std::string joined;
    for (const std::string& a : args) joined += a + " ";
    ParseResult r = parse(args);
    EXPECT_FALSE(r.ok) << "accepted: " << joined;
    EXPECT_FALSE(r.error.empty()) << joined;
    EXPECT_NE(r.error.find(mention), std::string::npos)
        << "error for '" << joined << "' does not mention '" << mention << "': " << r.error;
}

TEST(ParseSize, Accepts) {
    int w = 0, h = 0;
    ASSERT_TRUE(parseSize("1280x720", w, h));
    EXPECT_EQ(w, 1280);
    EXPECT_EQ(h, 720);
    ASSERT_TRUE(parseSize("1x1", w, h));
    EXPECT_EQ(w, 1);
    EXPECT_EQ(h, 1);
    ASSERT_TRUE(parseSize("3840x2160", w, h));
    EXPECT_EQ(w, 3840);
    EXPECT_EQ(h, 2160);
    ASSERT_TRUE(parseSize("7x5000", w, h));
    EXPECT_EQ(w, 7);
    EXPECT_EQ(h, 5000);
}

TEST(ParseSize, Rejects) {
    for (const char* text : {"", "x", "0x0", "0x720", "1280x0", "-1x720", "1280x-5", "abc", "1280", "1280x",
                             "x720", "12.5x10", "1280X720", "1280*720", "1280x720x3", "axb", "99999999999x10"}) {
        int w = 0, h = 0;
        EXPECT_FALSE(parseSize(text, w, h)) << "'" << text << "' -> " << w << "x" << h;
    }
}

TEST(ParseCameraPose, Accepts) {
    CameraPose pose;
    ASSERT_TRUE(parseCameraPose("1,2,3,45,-10", pose));
    EXPECT_EQ(pose.position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(pose.yawDegrees, 45.0f);
    EXPECT_EQ(pose.pitchDegrees, -10.0f);
    ASSERT_TRUE(parseCameraPose("-1.5e2,0.25,123456.5,370,90", pose));
    EXPECT_EQ(pose.position, glm::dvec3(-150.0, 0.25, 123456.5));
    EXPECT_EQ(pose.yawDegrees, 10.0f);  // wrapped into [-180, 180)
    EXPECT_EQ(pose.pitchDegrees, 90.0f);  // |pitch| <= 90 accepted
    ASSERT_TRUE(parseCameraPose("0,0,0,0,-90", pose));
    EXPECT_EQ(pose.pitchDegrees, -90.0f);
}

TEST(ParseCameraPose, RejectsAndLeavesPoseUnchanged) {
    for (const char* text : {"", "1,2,3,4", "1,2,3,4,5,6", "1,2,3,4,91", "1,2,3,4,-90.5", "a,2,3,4,5",
                             "1,,3,4,5", "1,2,3,4,nan", "1,2,3,4,inf", "1;2;3;4;5", "1 2 3 4 5", "1,2,3,4,5x"}) {
        CameraPose pose;
        pose.position = glm::dvec3(7, 8, 9);
        pose.yawDegrees = 11;
        pose.pitchDegrees = 12;
        EXPECT_FALSE(parseCameraPose(text, pose)) << "'" << text << "'";
        EXPECT_EQ(pose.position, glm::dvec3(7, 8, 9)) << text;
        EXPECT_EQ(pose.yawDegrees, 11.0f) << text;
        EXPECT_EQ(pose.pitchDegrees, 12.0f) << text;
    }
}

// "1,,3,4,5" is rejected (an empty field), but an empty field at the end is silently dropped by
// the std::getline loop, so "1,2,3,4,5," counts as five numbers.
TEST(ParseCameraPose, RejectsTrailingEmptyField) {
    CameraPose pose;
    EXPECT_FALSE(parseCameraPose("1,2,3,4,5,", pose));
}

TEST(ParseCommandLine, Defaults) {
    ParseResult r = parse({});
    ASSERT_TRUE(r.ok) << r.error;
    const Options& o = r.options;
    EXPECT_EQ(o.command, Command::Default);
    EXPECT_FALSE(o.help);
    EXPECT_EQ(o.scene.width, 1280);
    EXPECT_EQ(o.scene.height, 720);
    EXPECT_EQ(o.scene.timeSeconds, 0.0);
    EXPECT_FALSE(o.scene.hour.has_value());
    EXPECT_FALSE(o.scene.camera.has_value());
    EXPECT_EQ(o.scene.gbuffer, defaultGBufferLayout().name);
    EXPECT_EQ(o.scene.gbuffer, defaultGBufferLayout().name);
    EXPECT_EQ(o.scene.water.level, 0.0f);              // the help text's defaults
    EXPECT_EQ(o.scene.water.rippleStrength, 1.0f);
    EXPECT_EQ(o.scene.water.absorption, 0.09f);
    EXPECT_TRUE(o.scene.water.reflections);
    EXPECT_EQ(o.pipeline, PipelineKind::Deferred);
    EXPECT_EQ(o.view, "final");
    EXPECT_EQ(o.out, "oasis.png");
    EXPECT_EQ(o.outDir, "oasis-out");
    EXPECT_FALSE(o.json);
    EXPECT_EQ(o.timingFrames, 9);
    EXPECT_FALSE(o.stencilView.has_value());
    EXPECT_TRUE(o.stopBefore.empty());
}

TEST(ParseCommandLine, Subcommands) {
    struct Case { const char* word; Command command; };
    for (Case c : {Case{"render", Command::Render}, Case{"compare", Command::Compare},
                   Case{"window", Command::Window}}) {
        ParseResult r = parse({c.word});
        ASSERT_TRUE(r.ok) << c.word << ": " << r.error;
        EXPECT_EQ(r.options.command, c.command);
        EXPECT_STREQ(commandName(c.command), c.word);
        // Defaults are the same under every subcommand.
        EXPECT_EQ(r.options.scene.width, 1280);
        EXPECT_EQ(r.options.scene.height, 720);
        EXPECT_EQ(r.options.scene.gbuffer, defaultGBufferLayout().name);
        EXPECT_EQ(r.options.pipeline, PipelineKind::Deferred);
        EXPECT_EQ(r.options.view, "final");
        EXPECT_FALSE(r.options.help);
    }
    EXPECT_STREQ(commandName(Command::Default), "");
}

TEST(ParseCommandLine, SubcommandOnlyInFirstPosition) {
    // After an option, a bare word is that option's value, and a second bare word is an error.
    ParseResult r = parse({"--out-dir", "render"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.command, Command::Default);
    EXPECT_EQ(r.options.outDir, "render");
    EXPECT_FALSE(parse({"render", "compare"}).ok);
}

TEST(ParseCommandLine, SceneOptionsUnderEverySubcommand) {
    for (const char* command : {"", "render", "compare", "window"}) {
        Args args;
        if (*command) args.push_back(command);
        for (const char* a : {"--size", "640x360", "--time", "12.5", "--hour", "6.5", "--camera",
                              "10,20.5,-30,90,-15", "--gbuffer", "full", "--reflections", "off", "--water-level",
                              "-3.5", "--ripples", "0.25", "--absorption", "0"})
            args.push_back(a);
        ParseResult r = parse(args);
        ASSERT_TRUE(r.ok) << command << ": " << r.error;
        const SceneOptions& s = r.options.scene;
        EXPECT_EQ(s.width, 640);
        EXPECT_EQ(s.height, 360);
        EXPECT_EQ(s.timeSeconds, 12.5);
        ASSERT_TRUE(s.hour.has_value());
        EXPECT_EQ(*s.hour, 6.5);
        ASSERT_TRUE(s.camera.has_value());
        EXPECT_EQ(s.camera->position, glm::dvec3(10, 20.5, -30));
        EXPECT_EQ(s.camera->yawDegrees, 90.0f);
        EXPECT_EQ(s.camera->pitchDegrees, -15.0f);
        EXPECT_EQ(s.gbuffer, "full");
        EXPECT_FALSE(s.water.reflections);
        EXPECT_EQ(s.water.level, -3.5f);
        EXPECT_EQ(s.water.rippleStrength, 0.25f);
        EXPECT_EQ(s.water.absorption, 0.0f);
    }
    EXPECT_TRUE(parse({"--reflections", "off", "--reflections", "on"}).options.scene.water.reflections);
}

TEST(ParseCommandLine, HourBoundsAndNegativeTime) {
    for (const char* hour : {"0", "24", "23.99", "12"}) {
        ParseResult r = parse({"--hour", hour});
        ASSERT_TRUE(r.ok) << hour << ": " << r.error;
        EXPECT_EQ(*r.options.scene.hour, std::stod(hour));
    }
    ParseResult r = parse({"--time", "-30"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.scene.timeSeconds, -30.0);
}

TEST(ParseCommandLine, LaterOptionWins) {
    ParseResult r = parse({"--size", "10x10", "--size", "20x30"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.scene.width, 20);
    EXPECT_EQ(r.options.scene.height, 30);
}

TEST(ParseCommandLine, RenderOptions) {
    ParseResult r = parse({"render", "--pipeline", "forward", "--view", "albedo", "--out", "frame.png",
                           "--stencil-view", "read-back", "--stop-before", "WaterCompositePass"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.pipeline, PipelineKind::Forward);
    EXPECT_EQ(r.options.view, "albedo");
    EXPECT_EQ(r.options.out, "frame.png");
    ASSERT_TRUE(r.options.stencilView.has_value());
    EXPECT_EQ(*r.options.stencilView, StencilViewPath::ReadBack);
    EXPECT_EQ(r.options.stopBefore, "WaterCompositePass");
    // A pass of the other pipeline is a usage error naming this pipeline's passes.
    ParseResult wrong = parse({"render", "--pipeline", "forward", "--stop-before", "LightingPass"});
    EXPECT_FALSE(wrong.ok);
    EXPECT_NE(wrong.error.find("SkyPass.forward"), std::string::npos) << wrong.error;

    r = parse({"render", "--pipeline", "deferred", "--stencil-view", "texturing", "--view", "overview"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.pipeline, PipelineKind::Deferred);
    EXPECT_EQ(*r.options.stencilView, StencilViewPath::Texturing);
    EXPECT_EQ(r.options.view, "overview");

    // Every view in the debug view table is accepted by name.
    for (const DebugView& view : debugViews()) {
        ParseResult v = parse({"render", "--view", view.name});
        ASSERT_TRUE(v.ok) << view.name << ": " << v.error;
        EXPECT_EQ(v.options.view, view.name);
    }
}

TEST(ParseCommandLine, CompareOptions) {
    ParseResult r = parse({"compare", "--out-dir", "results", "--json", "--frames", "3"});
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.options.outDir, "results");
    EXPECT_TRUE(r.options.json);
    EXPECT_EQ(r.options.timingFrames, 3);
    for (const char* frames : {"1", "1000"}) {
        ParseResult f = parse({"compare", "--frames", frames});
        ASSERT_TRUE(f.ok) << frames << ": " << f.error;
        EXPECT_EQ(f.options.timingFrames, std::stoi(frames));
    }
}

TEST(ParseCommandLine, Help) {
    for (Args args : {Args{"--help"}, Args{"-h"}, Args{"render", "--help"}, Args{"compare", "--size", "8x8", "--help"},
                      Args{"window", "-h"}}) {
        ParseResult r = parse(args);
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_TRUE(r.options.help) << args.back();
    }
    EXPECT_FALSE(parse({"render"}).options.help);
    // Each usage text names its own subcommand's options.
    EXPECT_NE(usage(Command::Render).find("--pipeline"), std::string::npos);
    EXPECT_NE(usage(Command::Render).find("--stop-before"), std::string::npos);
    EXPECT_NE(usage(Command::Compare).find("--frames"), std::string::npos);
    EXPECT_NE(usage(Command::Default).find("--gbuffer"), std::string::npos);
    EXPECT_NE(usage(Command::Window).find("--reflections"), std::string::npos);
}

TEST(ParseCommandLine, ErrorsNameTheOption) {
    expectError({"--bogus", "1"}, "--bogus");
    expectError({"render", "--bogus", "1"}, "--bogus");
    expectError({"paint"}, "paint");
    expectError({"--size"}, "--size");
    expectError({"render", "--view"}, "--view");
    expectError({"--size", "0x0"}, "--size");
    expectError({"--size", "abc"}, "--size");
    expectError({"--gbuffer", "nope"}, "--gbuffer");
    expectError({"render", "--view", "nope"}, "--view");
    expectError({"render", "--pipeline", "nope"}, "--pipeline");
    expectError({"render", "--stencil-view", "nope"}, "--stencil-view");
    expectError({"--hour", "25"}, "--hour");
    expectError({"--hour", "-0.5"}, "--hour");
    expectError({"--hour", "noon"}, "--hour");
    expectError({"--time", "soon"}, "--time");
    expectError({"--time", "inf"}, "--time");
    expectError({"--camera", "1,2,3"}, "--camera");
    expectError({"--reflections", "yes"}, "--reflections");
    expectError({"--water-level", "deep"}, "--water-level");
    expectError({"--water-level", "2e6"}, "--water-level");
    expectError({"--ripples", "-0.1"}, "--ripples");
    expectError({"--absorption", "-1"}, "--absorption");
    expectError({"--vegetation", "maybe"}, "--vegetation");
    expectError({"--vegetation-density", "4.5"}, "--vegetation-density");
    expectError({"--vegetation-density", "-1"}, "--vegetation-density");
    expectError({"--wind", "gale"}, "--wind");
    expectError({"--wind", "3.01"}, "--wind");
    expectError({"compare", "--frames", "0"}, "--frames");
    expectError({"compare", "--frames", "1001"}, "--frames");
    expectError({"compare", "--frames", "many"}, "--frames");
    // Options that belong to `render` are refused elsewhere, naming the option.
    for (const char* command : {"compare", "window"}) {
        expectError({command, "--view", "albedo"}, "--view");
        expectError({command, "--pipeline", "forward"}, "--pipeline");
        expectError({command, "--out", "x.png"}, "--out");
        expectError({command, "--stencil-view", "texturing"}, "--stencil-view");
        expectError({command, "--stop-before", "LightingPass"}, "--stop-before");
    }
    expectError({"--view", "albedo"}, "--view");
    // The bad values are quoted back too.
    expectError({"--gbuffer", "nope"}, "nope");
    expectError({"--size", "abc"}, "abc");
    // A negative water level is fine (only the other two are non-negative).
    EXPECT_TRUE(parse({"--water-level", "-12"}).ok);
}

TEST(ParseCommandLine, ErrorsListTheChoices) {
    ParseResult r = parse({"--gbuffer", "nope"});
    ASSERT_FALSE(r.ok);
    for (const GBufferLayout& layout : gbufferLayouts()) EXPECT_NE(r.error.find(layout.name), std::string::npos);
    r = parse({"render", "--view", "nope"});
    ASSERT_FALSE(r.ok);
    for (const DebugView& view : debugViews()) EXPECT_NE(r.error.find(view.name), std::string::npos);
}

// Every row of the reflection resolution table by name; anything else is refused, listing them.
// A choice option: every row of its table parses to that row's value, the default is the scene's,
// and a name outside the table is refused with a message naming every row.
template <typename Row, size_t N, typename Value, typename Field>
void expectEveryChoiceParses(const char* flag, const Row (&table)[N], Value Row::*value, Field field,
                             Value defaultValue, const char* outside) {
    EXPECT_EQ(field(parse({}).options.scene), defaultValue);
    for (const Row& row : table) {
        ParseResult r = parse({flag, row.name});
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_EQ(field(r.options.scene), row.*value);
    }
    ParseResult r = parse({flag, outside});
    ASSERT_FALSE(r.ok);
    for (const Row& row : table) EXPECT_NE(r.error.find(row.name), std::string::npos) << r.error;
}

TEST(ParseCommandLine, ReflectionResolution) {
    expectEveryChoiceParses("--reflection-resolution", kReflectionResolutions, &ReflectionResolution::divisor,
                            [](const SceneOptions& s) { return s.water.reflectionDivisor; }, 1, "eighth");
}

TEST(ParseCommandLine, ReflectionPlantCull) {
    expectEveryChoiceParses("--reflection-plant-cull", kMirroredPlantCullModes, &MirroredPlantCullMode::mode,
                            [](const SceneOptions& s) { return s.work.mirroredPlantCull; }, MirroredPlantCull::Auto,
                            "still");
}

// An unknown option given last is reported as "needs a value", which suggests it exists; the
// unknown-option check only runs after a value has been consumed.
TEST(ParseCommandLine, UnknownOptionLastIsReportedAsUnknown) {
    ParseResult r = parse({"render", "--bogus"});
    ASSERT_FALSE(r.ok);
    EXPECT_NE(r.error.find("unknown option"), std::string::npos) << r.error;
}

TEST(Cli, BenchOptions) {
    ParseResult bench = parse({"bench", "--quick", "--json", "--out-dir", "x", "--frames", "4", "--hour", "17"});
    ASSERT_TRUE(bench.ok) << bench.error;
    EXPECT_EQ(bench.options.command, Command::Bench);
    EXPECT_TRUE(bench.options.quick);
    EXPECT_TRUE(bench.options.json);
    EXPECT_TRUE(bench.options.outDirGiven);
    EXPECT_TRUE(bench.options.timingFramesGiven);
    EXPECT_EQ(bench.options.timingFrames, 4);
    EXPECT_FALSE(parse({"bench"}).options.outDirGiven);
    EXPECT_FALSE(parse({"bench"}).options.quick);
    EXPECT_NE(usage(Command::Bench).find("usage: oasis bench"), std::string::npos);
    // What the bench sets itself is refused, naming the option; --quick belongs to bench alone.
    for (const char* flag :
         {"--size", "--time", "--camera", "--gbuffer", "--reflections", "--vegetation-density", "--lights"}) {
        ParseResult refused = parse({"bench", flag, "1"});
        EXPECT_FALSE(refused.ok) << flag;
        EXPECT_NE(refused.error.find(flag), std::string::npos) << refused.error;
    }
    for (const char* command : {"render", "compare", "window"}) {
        ParseResult refused = parse({command, "--quick"});
        EXPECT_FALSE(refused.ok) << command;
        EXPECT_NE(refused.error.find("--quick"), std::string::npos) << refused.error;
    }
    EXPECT_FALSE(parse({"bench", "--passes"}).ok);
}

}  // namespace
}  // namespace oasis
