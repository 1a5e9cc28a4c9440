// Provenance: what made a PNG oasis writes, kept in the PNG's text chunks (io/png_text.h) under
// one table of keys: oasis's version, the options that made the picture, its view and pipeline,
// whether a legend strip is stacked under the frame, the renderer and GL version, the command.
// compare --reference reads it to render the sender's frame or refuse a reference that cannot be
// compared (commands/driver_compare.h).
#pragma once
#include <string>
#include <vector>

#include "io/png_text.h"

namespace oasis {

struct Options;

// "0.1 (git 168d70a)", or "0.1 (unknown commit)" outside a git checkout; defined in the build's
// generated oasis_version.cpp (cmake/version.cmake), made again at every build.
const char* oasisVersion();
// Its parts: the project's version ("0.1") and the commit ("git 1a2b3c4-dirty", or "unknown commit").
const char* oasisRelease();
const char* oasisCommit();

struct Provenance {
    std::string version;        // oasisVersion() of the oasis that wrote it
    std::string options;        // the picture's options, canonical (cli/scene_arguments.h): "--size 160x90 --hour 18"
    std::string driverOptions;  // the driver-path options it was drawn with, "" for none: "--api gles"
    std::string view;           // "final", a debug view's name, "overview" or "difference"
    std::string viewOptions;    // render's options that change the view as drawn, "" for none: "--range 0,1"
    std::string pipeline;       // "deferred", "forward", or a difference's "forward and deferred"
    std::string legend;         // "off", or "on, frame height H": a legend strip under the frame's top H rows
    std::string renderer;       // GL_RENDERER of the context that drew it
    std::string glVersion;      // GL_VERSION of that context
    std::string command;        // the command line of the oasis that wrote it

    bool hasLegend() const { return legend.rfind("on", 0) == 0; }
};

struct ProvenanceKey {
    const char* key;  // the PNG text keyword, "oasis:..."
    std::string Provenance::*field;
    bool required;  // a PNG whose oasis keys lack it is read as one without provenance
};
// The keys, in the order they are written: the one table the writer, the reader and the docs'
// list (docs/outputs.md, held to it by a test) follow.
const std::vector<ProvenanceKey>& provenanceKeys();

// The provenance of a picture this process draws now with `options`: the version, the picture's
// and the driver's options and the command from `options`, the renderer and GL version of the
// current context (there must be one). `frameHeight` is the frame's height in the image: a taller
// image has a legend strip under it.
Provenance pictureProvenance(const Options& options, const std::string& view, const std::string& pipeline,
                             int imageHeight, int frameHeight);

// The text chunks that carry it (empty values included: a key present and empty says "none").
std::vector<PngText> provenanceTexts(const Provenance& provenance);

// The provenance in a PNG's texts: false with `why` when there is none to use ("no oasis text
// chunks", "oasis:options is missing"), naming a chunk left out where one was.
bool readProvenance(const PngTexts& texts, Provenance& provenance, std::string& why);

}  // namespace oasis
