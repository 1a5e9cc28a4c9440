// The frames `oasis check` judges against: the repository's reference set (llvmpipe's frames) and a
// driver's own baseline (--baseline DIR). A set is never silently absent: a missing, unreadable or
// empty directory is refused before anything renders, and a missing, unreadable or wrongly sized
// frame fails its case. Each set is named in the report by the hash of its content.
#pragma once
#include <string>
#include <vector>

#include "render/image.h"

namespace oasis {

struct ReferenceSet {
    std::string dir;
    std::string hash;   // "fnv1a64:..." over every PNG's name and bytes, in name order
    int frames = 0;     // PNGs in it
};

// False with `error` when `dir` is missing, not a directory, unreadable or holds no PNG.
bool openReferenceSet(const std::string& dir, ReferenceSet& set, std::string& error);

struct ReferenceFrame {
    bool readable = false;
    std::string error;          // why not: "no file DIR/NAME.png", "not a readable PNG (...)"
    Image image;
    std::string renderer;       // its oasis:renderer (the driver that drew it), "" where unrecorded
    std::string driverRelease;  // driverRelease() of its oasis:gl-version
};
ReferenceFrame readReferenceFrame(const std::string& dir, const std::string& caseName);

// The driver's release in a GL_VERSION string: "Mesa 22.3.6" from "4.5 (Core Profile) Mesa 22.3.6"
// and from "OpenGL ES 3.2 Mesa 22.3.6" (a tier's version differs, the driver does not); the
// string after the version numbers otherwise.
std::string driverRelease(const std::string& glVersion);

// A baseline directory's manifest (DIR/baseline.json): who recorded it.
struct BaselineManifest {
    std::string renderer, glVersion, oasisCommit;
    std::vector<std::string> cases;
};
bool baselineExists(const std::string& dir);
bool readBaselineManifest(const std::string& dir, BaselineManifest& manifest, std::string& error);
std::string baselineManifestJson(const BaselineManifest& manifest);

}  // namespace oasis
