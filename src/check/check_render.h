// How one check case is rendered, on a context of its own tier (natively in a child process of its
// own: check/check_runner.h): the frame (or the view the case asks for) exactly as `oasis render`
// draws it, which paths the session really took and why, and, for a failing case, the frame pass
// by pass to find where two paths part.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "check/check_report.h"
#include "check/shading_oracle.h"
#include "render/image.h"
#include "io/png_text.h"

namespace oasis::gl {
struct Capabilities;
}

namespace oasis {

struct Options;

struct CaseFrame {
    bool rendered = false;
    std::string skipReason;  // why it could not be rendered as asked (no ES context, a path fell back)
    std::string limitedBy;   // "driver" or "forced tier" when skipped
    // A fallback the frame was drawn with that changes no path the case tests, said in its report:
    // the G-buffer layout where the one asked for cannot be drawn (OpenGL ES without
    // EXT_texture_norm16 draws standard for compact), "" when none.
    std::string drawnWith;
    Image image;
    std::vector<PngText> provenance;  // what made it (commands/provenance.h), for the PNGs the check writes
    CaseContext context;  // empty where no context was made
    // A shaded frame's (the final view's) shading oracle over the frame just drawn; not run otherwise.
    ShadingOracle oracle;
    // A shaded frame's pixels split by its own geometry (check/pixel_classes.h), top row first: 0
    // an interior pixel, else why it is an edge; empty where the oracle's inputs were not read.
    std::vector<uint8_t> pixelClasses;
};

// Renders `oasis render ARGUMENTS` (the final view or the one asked for, no legend) and checks that
// every path the arguments ask for was taken (and the plants on the GPU where `gpuPlants`, which no
// argument forces): a fallback makes it a skip, saying whose limit it was, except the G-buffer
// layout's, which the renderer takes itself and the frame is judged with (drawnWith). Throws
// std::runtime_error for a failure that is not a limit (a shader that does not build).
// `quiet`: the session's report lines go to a scratch file (in the page and in-process; a child's
// output is its parent's to keep).
CaseFrame renderCaseFrame(const std::vector<std::string>& arguments, bool gpuPlants, bool quiet = true);

// A buffer read back whole and decoded (check/check_buffers.h): entries of `stride` floats,
// compared in order, or as a multiset where the order is no part of what it means.
struct BufferSnapshot {
    std::string name;  // the resource's name (LightList, PlantInstances)
    uint32_t stride = 1;
    bool unordered = false;
    std::vector<float> values;
};

// The frame after each pass, for every target the views can read (albedo ... final) and the
// buffers the pass writes (check/check_buffers.h): a name per pass in order and, per pass, each
// target's values; per pixel, a buffer's check (LightTiles: the lights its lists miss there, one
// float a pixel; a path without the buffer misses none); whole buffers decoded. The search's
// first step, kFrameInputsStep, holds the buffers uploaded before the passes.
struct PassSnapshot {
    std::string pass;
    std::vector<std::pair<std::string, std::vector<float>>> targets;  // target name, RGBA floats
    std::vector<std::pair<std::string, std::vector<float>>> pixelChecks = {};  // buffer name, a count a pixel
    std::vector<BufferSnapshot> buffers = {};
};
std::vector<PassSnapshot> renderPassByPass(const std::vector<std::string>& arguments, bool quiet = true);

// The driver's strings and capabilities (vendor, renderer, versions, api, caps; nothing else of
// the report) on the context `oasis caps ARGUMENTS` would make (--api gles, --no-compute).
CheckReport driverReport(const std::vector<std::string>& arguments);

struct Divergence {
    std::string pass, target;
    long pixels = 0;
};
// The first pass after which a buffer or a target of `candidate` differs from `reference` beyond the
// level: a decoded buffer (`pixels`: the entries that differ), then a buffer's per-pixel check
// (`pixels`: those whose counts differ, a check one path lacks counting as 0), then a target
// (`pixels`: those that differ); the level is
// (levels of 1/255, relative above 1) at a pixel of `where` (the pixels whose final colours differ,
// bottom row first as the views read: a difference a later pass overwrites, such as a tier's
// lighting leaving the sky black for the sky pass, is not the one the frame shows), or none.
bool firstDivergence(const std::vector<PassSnapshot>& reference, const std::vector<PassSnapshot>& candidate,
                     int level, const std::vector<bool>& where, Divergence& found);

}  // namespace oasis
