// Helpers more than one unit test file uses: the whole shader program table, a file's text, and a
// varied test image. One definition each (the test files compile in unity batches, where two
// file-local copies of a name cannot meet in one translation unit).
#pragma once
#include <deque>
#include <fstream>
#include <sstream>
#include <string>

#include "debug/debug_views.h"
#include "render/image.h"
#include "render/shader_variants.h"

namespace oasis::unittest {

// The whole program table: the fixed programs and the debug views' (which debug/ adds).
inline const std::deque<ProgramVariant>& everyProgramVariant() {
    registerDebugViewPrograms();
    return programVariants();
}

// A file's whole text ("" when it cannot be read).
inline std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// A deterministic varied image (so flips and comparisons see distinct pixels).
inline Image pattern(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) image.pixel(x, y)[c] = uint8_t((x * 7 + y * 31 + c * 64) & 255);
    return image;
}

}  // namespace oasis::unittest
