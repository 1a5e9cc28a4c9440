// The driver workarounds' table and how a request resolves against a driver (gl/driver_workarounds.h):
// the table's default by GL_RENDERER, the file's rules, --workarounds last, each with why.
#include <gtest/gtest.h>

#include "gl/capabilities.h"
#include "gl/driver_workarounds.h"

namespace oasis::gl {
namespace {

const char* kSoftpipe = "softpipe";
const char* kLlvmpipe = "llvmpipe (LLVM 15.0.6, 256 bits)";
const char* kVersion = "3.3 (Core Profile) Mesa 22.3.6";
using Fallbacks = std::vector<std::pair<std::string, std::string>>;  // {--force name, row}

TEST(DriverWorkarounds, TableRowsAreComplete) {
    ASSERT_EQ(workaroundTable().size(), 11u);  // three driver bugs, eight forced fallbacks
    for (const WorkaroundRow& row : workaroundTable()) {
        EXPECT_EQ(findWorkaround(row.name), &row);
        for (const char* field : {row.bug, row.instead, row.cost, row.test}) EXPECT_STRNE(field, "");
        // A bug's row names its drivers; a forced fallback's its --force name, and no driver. A bug's
        // row may apply a fallback too (depth-clamp-off), keyed by its driver.
        if (*row.forces) {
            EXPECT_EQ(row.forcedOnly(), row.id == Workaround::ForcedFallback) << row.name;
            std::string error;
            ForcedFallbacks parsed;
            EXPECT_TRUE(parseForcedFallbacks(row.forces, parsed, error)) << row.forces << ": " << error;
        } else {
            EXPECT_STRNE(row.renderer, "") << row.name;
        }
    }
}

TEST(DriverWorkarounds, DefaultAppliesTheTableBySoftpipesRenderer) {
    WorkaroundSet softpipe = resolveWorkarounds({}, kSoftpipe, kVersion);
    EXPECT_TRUE(softpipe.has(Workaround::FlushBeforeComputeRead));
    EXPECT_TRUE(softpipe.has(Workaround::ArrayWriteByLoop));
    EXPECT_TRUE(softpipe.has(Workaround::DepthClampOff));
    EXPECT_EQ(softpipe.forcedFallbacks(), (Fallbacks{{"no-depth-clamp", "depth-clamp-off"}}));  // the row's fallback
    EXPECT_EQ(softpipe.defines(), std::vector<std::string>{"OASIS_ARRAY_WRITE_BY_LOOP 1"});
    EXPECT_EQ(softpipe.rows[0].why, "table: GL_RENDERER /softpipe/");
    WorkaroundSet llvmpipe = resolveWorkarounds({}, kLlvmpipe, kVersion);
    EXPECT_EQ(llvmpipe.appliedList(), "");
    EXPECT_EQ(llvmpipe.rows[1].why, "table: no match: GL_RENDERER /softpipe/");
}

TEST(DriverWorkarounds, CommandLineValueOverridesTheTable) {
    WorkaroundRequest request;
    std::string error;
    ASSERT_TRUE(parseWorkaroundsValue("none", request, error));
    EXPECT_EQ(resolveWorkarounds(request, kSoftpipe, kVersion).appliedList(), "");
    ASSERT_TRUE(parseWorkaroundsValue("all", request, error));
    EXPECT_EQ(resolveWorkarounds(request, kLlvmpipe, kVersion).appliedList(),
              "flush-before-compute-read,array-write-by-loop,depth-clamp-off");
    ASSERT_TRUE(parseWorkaroundsValue("array-write-by-loop", request, error));
    WorkaroundSet one = resolveWorkarounds(request, kSoftpipe, kVersion);
    EXPECT_EQ(one.appliedList(), "array-write-by-loop");
    EXPECT_EQ(one.rows[0].why, "--workarounds array-write-by-loop (not listed)");
    EXPECT_FALSE(parseWorkaroundsValue("no-such", request, error));
    EXPECT_NE(error.find("got 'no-such'"), std::string::npos);
}

TEST(DriverWorkarounds, FileRulesMatchRendererAndVersion) {
    WorkaroundRequest request;
    std::string error;
    ASSERT_TRUE(parseWorkaroundRules("# comment\n-array-write-by-loop | softpipe | Mesa 22\\.3\n"
                                     "flush-before-compute-read | llvmpipe\n",
                                     "w.txt", request.rules, error))
        << error;
    WorkaroundSet softpipe = resolveWorkarounds(request, kSoftpipe, kVersion);
    EXPECT_EQ(softpipe.appliedList(), "flush-before-compute-read,depth-clamp-off");  // the table's, the file switched one off
    EXPECT_EQ(softpipe.rows[1].why, "w.txt:2: off for GL_RENDERER /softpipe/, GL_VERSION /Mesa 22\\.3/");
    EXPECT_EQ(resolveWorkarounds(request, kSoftpipe, "3.3 Mesa 23.1").appliedList(),
              "flush-before-compute-read,array-write-by-loop,depth-clamp-off");  // another version: the table's
    EXPECT_EQ(resolveWorkarounds(request, kLlvmpipe, kVersion).appliedList(), "flush-before-compute-read");
    EXPECT_FALSE(parseWorkaroundRules("bogus | x\n", "w.txt", request.rules, error));
    EXPECT_EQ(error.rfind("w.txt:1: unknown workaround 'bogus' (one of: flush-before-compute-read, array-write-by-loop, "
                          "depth-clamp-off, force-no-compute", 0), 0u) << error;
    EXPECT_FALSE(parseWorkaroundRules("array-write-by-loop | (\n", "w.txt", request.rules, error));
}

TEST(DriverWorkarounds, ForcedFallbacksApplyOnlyWhereAFileOrTheListNamesThem) {
    // By default only the bug row depth-clamp-off's fallback, on its driver.
    EXPECT_EQ(resolveWorkarounds({}, kSoftpipe, kVersion).forcedFallbacks(), (Fallbacks{{"no-depth-clamp", "depth-clamp-off"}}));
    EXPECT_TRUE(resolveWorkarounds({}, kLlvmpipe, kVersion).forcedFallbacks().empty());
    WorkaroundRequest request;
    std::string error;
    ASSERT_TRUE(parseWorkaroundsValue("all", request, error));
    EXPECT_EQ(resolveWorkarounds(request, kLlvmpipe, kVersion).forcedFallbacks(),
              (Fallbacks{{"no-depth-clamp", "depth-clamp-off"}}));  // every bug's row, no forced-fallback row
    // A proposed profile (oasis check's oasis-check/workarounds) keyed by this renderer and release.
    ASSERT_TRUE(parseWorkaroundRules("force-no-compute | ^llvmpipe \\(LLVM 15\\.0\\.6, 256 bits\\)$ | Mesa 22\\.3\\.6$\n",
                                     "profile", request.rules, error))
        << error;
    request.mode = WorkaroundRequest::Mode::Default;
    WorkaroundSet here = resolveWorkarounds(request, kLlvmpipe, kVersion);
    EXPECT_EQ(here.forcedFallbacks(), (Fallbacks{{"no-compute", "force-no-compute"}}));
    EXPECT_EQ(here.appliedList(), "force-no-compute");
    EXPECT_TRUE(resolveWorkarounds(request, kLlvmpipe, "3.3 (Core Profile) Mesa 23.0.1").forcedFallbacks().empty());
    EXPECT_EQ(resolveWorkarounds(request, kSoftpipe, kVersion).forcedFallbacks(),
              (Fallbacks{{"no-depth-clamp", "depth-clamp-off"}}));  // the table's row, not the profile's
}

TEST(DriverWorkarounds, TheTableAsAFileReadsBackToTheTable) {
    WorkaroundRequest request;
    std::string error;
    ASSERT_TRUE(parseWorkaroundRules(workaroundTableText(), "table", request.rules, error)) << error;
    EXPECT_EQ(request.rules.size(), 3u);  // the driver bugs' rows: a forced fallback has no key
    EXPECT_EQ(resolveWorkarounds(request, kSoftpipe, kVersion).appliedList(),
              resolveWorkarounds({}, kSoftpipe, kVersion).appliedList());
}

// A reason names what switched a feature off: --force, or the driver workaround whose row applies
// the fallback (caps said "--force no-depth-clamp" on softpipe, where depth-clamp-off did it).
TEST(DriverWorkarounds, AFallbackSaysWhatForcedIt) {
    ForcedFallbacks forced;
    std::string error;
    ASSERT_TRUE(parseForcedFallbacks("no-ssbo,no-depth-clamp", forced, error));
    forced.byWorkaround["no-depth-clamp"] = "depth-clamp-off";
    EXPECT_EQ(forced.forcedBy("no-ssbo"), "--force no-ssbo");
    EXPECT_EQ(forced.forcedBy("no-depth-clamp"), "the driver workaround depth-clamp-off");
    // A workaround forces what --force did not; what --force asked stays --force's.
    ForcedFallbacks byRow;
    ASSERT_TRUE(parseForcedFallbacks("no-ssbo", byRow, error));
    byRow.forceByWorkaround("no-ssbo", "force-no-ssbo");
    byRow.forceByWorkaround("no-compute", "force-no-compute");
    EXPECT_TRUE(byRow.has("no-compute") && byRow.has("no-ssbo") && !byRow.has("no-dsa"));
    EXPECT_EQ(byRow.forcedBy("no-ssbo"), "--force no-ssbo");
    EXPECT_EQ(byRow.forcedBy("no-compute"), "the driver workaround force-no-compute");
}

}  // namespace
}  // namespace oasis::gl
