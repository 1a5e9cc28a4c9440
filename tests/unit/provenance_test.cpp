// Covers src/commands/provenance.h without GL: the table of keys (valid PNG keywords, each in
// docs/outputs.md), provenance written into a PNG and read back, and PNGs whose provenance is
// missing or partial read as having none, saying why.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "commands/provenance.h"
#include "render/image.h"
#include "render/shader_library.h"

namespace oasis {
namespace {

Provenance example() {
    Provenance p;
    p.version = "0.1 (git abc1234)";
    p.options = "--size 16x9 --hour 18";
    p.driverOptions = "";
    p.view = "final";
    p.viewOptions = "";
    p.pipeline = "deferred";
    p.legend = "off";
    p.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    p.glVersion = "4.5 (Core Profile) Mesa 22.3.6";
    p.command = "oasis render --size 16x9 --hour 18 --legend off --out 'a b.png'";
    return p;
}

std::string png(const std::vector<PngText>& texts) {
    std::string bytes;
    EXPECT_TRUE(encodePng(Image(16, 9), bytes, texts));
    return bytes;
}

TEST(Provenance, KeysAreUniqueValidKeywordsAndDocumented) {
    std::ifstream file(findShaderDirectory() + "/../docs/outputs.md");
    ASSERT_TRUE(file) << "docs/outputs.md beside the shaders";
    std::stringstream docs;
    docs << file.rdbuf();
    std::set<std::string> keys;
    for (const ProvenanceKey& key : provenanceKeys()) {
        EXPECT_TRUE(keys.insert(key.key).second) << key.key;
        EXPECT_EQ(std::string(key.key).rfind("oasis:", 0), 0u) << key.key;
        EXPECT_TRUE(validPngKeyword(key.key)) << key.key;
        EXPECT_NE(docs.str().find("| `" + std::string(key.key) + "` |"), std::string::npos)
            << "docs/outputs.md's Provenance table lacks " << key.key;
    }
    EXPECT_TRUE(keys.count("oasis:version") && keys.count("oasis:options") && keys.count("oasis:view") &&
                keys.count("oasis:pipeline") && keys.count("oasis:legend") && keys.count("oasis:renderer") &&
                keys.count("oasis:gl-version") && keys.count("oasis:command"));
}

TEST(Provenance, RoundTripThroughAPng) {
    Provenance written = example();
    Provenance read;
    std::string why;
    ASSERT_TRUE(readProvenance(readPngTexts(png(provenanceTexts(written))), read, why)) << why;
    for (const ProvenanceKey& key : provenanceKeys()) EXPECT_EQ(read.*key.field, written.*key.field) << key.key;
    EXPECT_FALSE(read.hasLegend());
    read.legend = "on, frame height 9";
    EXPECT_TRUE(read.hasLegend());
}

TEST(Provenance, NoneOrPartialIsNoProvenanceWithAReason) {
    Provenance read;
    std::string why;
    EXPECT_FALSE(readProvenance(readPngTexts(png({})), read, why));
    EXPECT_NE(why.find("no oasis text chunks"), std::string::npos) << why;
    EXPECT_FALSE(readProvenance(readPngTexts(png({{"Software", "another program"}})), read, why));
    EXPECT_NE(why.find("no oasis text chunks"), std::string::npos) << why;

    std::vector<PngText> texts = provenanceTexts(example());
    texts.erase(texts.begin() + 1);  // oasis:options
    EXPECT_FALSE(readProvenance(readPngTexts(png(texts)), read, why));
    EXPECT_NE(why.find("lack oasis:options"), std::string::npos) << why;

    // A chunk left out (its CRC spoilt) is named in the reason.
    std::string bytes = png({{"oasis:view", "final"}});
    bytes[45] ^= 1;  // inside the chunk's keyword (its data starts at byte 41)
    EXPECT_FALSE(readProvenance(readPngTexts(bytes), read, why));
    EXPECT_NE(why.find("CRC error"), std::string::npos) << why;
}

// The project version and the commit (cmake/version.cmake), or "unknown commit" outside git.
TEST(Provenance, TheVersionNamesTheProjectVersionAndCommit) {
    EXPECT_TRUE(std::regex_match(oasisVersion(), std::regex(R"([0-9]+(\.[0-9]+)* \((git [A-Za-z0-9._+-]+|unknown commit)\))")))
        << oasisVersion();
}

}  // namespace
}  // namespace oasis
