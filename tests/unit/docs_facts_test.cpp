// Facts the docs state about the code, held to the code (issue 44, item 7: the docs had drifted
// from it in five places): the window's view keys, what compare's bytes/pixel and bench's B/px
// count for compact, and the compact layout's depth read in place by default.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cli/option_table.h"
#include "cli/options.h"
#include "debug/debug_views.h"
#include "render/depth_convention.h"
#include "render/gbuffer_layout.h"
#include "render/shader_library.h"

namespace oasis {
namespace {

std::string page(const std::string& path) {
    std::ifstream file(findShaderDirectory() + "/../" + path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

// Keys 1 to 9 choose the first nine views of the table (window/window_input.cpp); the window's
// pages and the browser's say so.
TEST(DocsFacts, TheViewKeysAreTheFirstNineViews) {
    ASSERT_GE(debugViews().size(), 9u) << "the docs promise nine view keys";
    EXPECT_NE(page("README.md").find("Tab pipeline, 1-9 views, 0 overview"), std::string::npos);
    EXPECT_NE(page("docs/command-line.md").find("1-9 views (the first nine of the views' table)"), std::string::npos);
    EXPECT_NE(page("docs/web.md").find("1..9 and 0 the first nine debug views"), std::string::npos);
    EXPECT_EQ(page("docs/web.md").find("1..7"), std::string::npos);
}

// compare's "bytes/pixel" is the G-buffer with its depth-stencil; bench's B/px adds radiance,
// reflection and final (bench/bench.cpp measureError). docs/bench.md states both for compact.
TEST(DocsFacts, CompactsBytesPerPixelAsBothCommandsCountThem) {
    const GBufferLayout& compact = *findGBufferLayout("compact");
    int gbuffer = gbufferBytesPerPixel(compact, standardDepthConvention());
    int frame = gbuffer + compact.format(Target::Radiance).bytesPerPixel +
                compact.format(Target::Reflection).bytesPerPixel + compact.format(Target::Final).bytesPerPixel;
    std::string stated = "(compact: " + std::to_string(gbuffer) + " there, " + std::to_string(frame) + " here)";
    EXPECT_NE(page("docs/bench.md").find(stated), std::string::npos) << "docs/bench.md lacks " << stated;
}

// The compact layout's lighting samples the depth-stencil target itself unless --depth-read copy:
// docs/limits.md lists it as done and default, as `oasis caps` does.
TEST(DocsFacts, CompactReadsDepthInPlaceByDefault) {
    EXPECT_TRUE(SceneOptions{}.work.depthReadInPlace);
    std::string limits = page("docs/limits.md");
    EXPECT_NE(limits.find("`--depth-read in-place`"), std::string::npos);
    EXPECT_EQ(limits.find("no such driver here"), std::string::npos) << "zink's timer queries are trusted here";
}

}  // namespace
}  // namespace oasis
