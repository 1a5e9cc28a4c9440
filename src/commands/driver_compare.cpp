// compare --driver / --reference (commands/driver_compare.h): the children's environments and
// output (run by commands/child_process.h), the driver check, a reference's provenance, then the comparison of the two PNGs.
#include "commands/driver_compare.h"

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "cli/driver_setups.h"
#include "cli/input_domains.h"
#include "cli/scene_arguments.h"
#include "io/json_text.h"
#include "commands/child_process.h"
#include "commands/headless_commands.h"
#include "commands/provenance.h"
#include "context/gl_context.h"
#include "io/file_output.h"
#include "render/image.h"
#include "io/interruption.h"
#include "io/printable_text.h"

extern char** environ;

namespace oasis {
namespace {

// One side of the comparison: a set-up rendered here (null setup = this process's own environment,
// "here"), or the reference file.
struct Side {
    explicit Side(std::string name, const DriverSetup* driver = nullptr) : label(std::move(name)), setup(driver) {}
    std::string label;  // in messages, the legend and the image's file name
    const DriverSetup* setup = nullptr;
    bool reference = false;
    std::string path;      // the PNG (a set-up's: in the staging directory until the set is written)
    std::string renderer;  // GL_RENDERER the child reported
    std::string workarounds;  // the driver workarounds the child applied ("none"; "" for a reference)
    Image image;
    std::string bytes;     // a set-up's PNG file as its child wrote it
};

std::vector<std::string> childEnvironment(const DriverSetup* setup, const std::string& runtimeDir) {
    std::vector<std::string> environment;
    auto overridden = [&](const std::string& entry) {
        std::string name = entry.substr(0, entry.find('='));
        if (!setup) return false;
        for (const std::string& variable : driverSelectingVariables())
            if (name == variable) return true;
        for (const auto& [variable, value] : setup->environment)
            if (name == variable) return true;
        return false;
    };
    for (char** entry = environ; *entry; ++entry)
        if (!overridden(*entry)) environment.push_back(*entry);
    if (setup)
        for (const auto& [variable, value] : setup->environment)
            environment.push_back(variable + "=" + (value == kRuntimeDirValue ? runtimeDir : value));
    return environment;
}

std::string indented(const std::string& text) {
    std::string out = "    ";
    for (size_t i = 0; i < text.size(); ++i) {
        out += text[i];
        if (text[i] == '\n' && i + 1 < text.size()) out += "    ";
    }
    if (!out.empty() && out.back() != '\n') out += '\n';
    return out;
}

// The value of the child's `oasis render` line that starts with `marker`, up to the first of
// `ends` or the line's end, or "": "oasis: renderer: NAME; GL VERSION", "oasis: workarounds: a,b".
std::string reportedValue(const std::string& output, const std::string& marker, const char* ends) {
    size_t at = output.find(marker);
    if (at == std::string::npos) return {};
    size_t start = at + marker.size();
    return output.substr(start, output.find_first_of(ends, start) - start);
}

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// The arguments of `side`'s child `oasis render` (argv[0] first), writing its frame to side.path.
std::vector<std::string> childArguments(const Options& options, const Side& side,
                                        const std::vector<std::string>& extraArguments) {
    std::vector<std::string> arguments = {"oasis", "render"};
    arguments.insert(arguments.end(), options.sceneArguments.begin(), options.sceneArguments.end());
    arguments.insert(arguments.end(), extraArguments.begin(), extraArguments.end());
    if (side.setup) arguments.insert(arguments.end(), side.setup->arguments.begin(), side.setup->arguments.end());
    for (const char* argument : {"--view", "final", "--legend", "off", "--out"}) arguments.push_back(argument);
    arguments.push_back(side.path);
    return arguments;
}

// Every child's arguments parsed here first, as the child would: a set-up that would refuse them
// (--force gl33 with the gles set-up) is a usage error before any child starts. 0 or 2.
int checkChildArguments(const Options& options, const std::vector<Side>& sides,
                        const std::vector<std::string>& extraArguments) {
    for (const Side& side : sides) {
        if (side.reference) continue;
        std::vector<std::string> arguments = childArguments(options, side, extraArguments);
        ParseResult parsed = parseCommandLine(std::vector<std::string>(arguments.begin() + 1, arguments.end()));
        if (parsed.ok) continue;
        std::fprintf(stderr, "oasis: %s: %s (nothing was rendered)\n",
                     side.setup ? ("set-up " + side.setup->name).c_str() : "the frame here", parsed.error.c_str());
        return 2;
    }
    return 0;
}

// Renders `side` in a child, into side.path in the staging directory. Returns 0, or the exit code
// after saying what went wrong.
int renderSide(const Options& options, Side& side, const std::vector<std::string>& extraArguments,
               const std::string& runtimeDir) {
    std::vector<std::string> arguments = childArguments(options, side, extraArguments);
    ChildResult child = runChild(arguments, childEnvironment(side.setup, runtimeDir), options.driverTimeoutSeconds);
    std::string name = side.setup ? "set-up " + side.setup->name : "the frame here";
    if (child.timedOut) {
        std::fprintf(stderr, "oasis: %s: `oasis render` did not finish within --driver-timeout %s s: its process "
                     "group was killed; its output until then:\n%s", name.c_str(),
                     formatNumber(options.driverTimeoutSeconds).c_str(), indented(child.output).c_str());
        return 1;
    }
    if (WIFSIGNALED(child.status)) {
        std::fprintf(stderr, "oasis: %s: `oasis render` was killed by signal %d (%s); its output:\n%s", name.c_str(),
                     WTERMSIG(child.status), strsignal(WTERMSIG(child.status)), indented(child.output).c_str());
        return 1;
    }
    int code = WIFEXITED(child.status) ? WEXITSTATUS(child.status) : 1;
    // No EGL display or context under the set-up's variables: its driver is not on this machine
    // (zink without lavapipe fails here rather than falling back).
    bool noContext = child.output.find("oasis: cannot initialise a surfaceless EGL") != std::string::npos ||
                     child.output.find("oasis: EGL ") != std::string::npos;
    if (code != 0 && side.setup && noContext) {
        std::fprintf(stderr, "oasis: set-up %s is not available here: no GL context under its environment (it "
                     "needs %s); the child's output:\n%s", side.setup->name.c_str(), side.setup->needs.c_str(),
                     indented(child.output).c_str());
        return 1;
    }
    if (code != 0) {
        std::fprintf(stderr, "oasis: %s: `oasis render` exited with %d%s; its output:\n%s", name.c_str(), code,
                     side.setup ? (" (it needs " + side.setup->needs + ")").c_str() : "",
                     indented(child.output).c_str());
        return code == 2 ? 2 : 1;  // a usage error stays one (e.g. a reference's size outside --size's domain)
    }
    side.renderer = reportedValue(child.output, "oasis: renderer: ", ";\n");
    side.workarounds = reportedValue(child.output, "oasis: workarounds: ", "\n");  // the driver workarounds applied
    const bool anyRenderer = side.setup && side.setup->rendererPrefix.empty();  // native: whatever this machine gives
    if (side.setup && !anyRenderer && side.renderer.rfind(side.setup->rendererPrefix, 0) != 0) {
        // Mesa falls back to another driver rather than failing: the frame is not the set-up's.
        std::fprintf(stderr, "oasis: set-up %s is not available here: the frame was rendered by '%s', not %s (it needs %s)\n",
                     side.setup->name.c_str(), side.renderer.empty() ? "an unreported renderer" : side.renderer.c_str(),
                     side.setup->rendererPrefix.c_str(), side.setup->needs.c_str());
        return 1;
    }
    std::string error;
    PngHeader header;  // a frame rendered here at --size: the --size domain is its limit
    if (!readPngFile(side.path, side.bytes, header, error, kMaxPngSide) ||
        !decodePng(side.path, side.bytes, side.image, error, kMaxPngSide)) {
        std::fprintf(stderr, "oasis: %s: %s\n", name.c_str(), error.c_str());
        return 1;
    }
    return 0;
}

std::string fileLabel(const std::string& path) {
    size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// 2 after saying so when --size was given and the reference is another size, else 0.
int referenceSizeRefused(const Options& options, int width, int height) {
    const SceneOptions& scene = options.scene;
    if (!options.sizeGiven || (width == scene.width && height == scene.height)) return 0;
    std::fprintf(stderr, "oasis: --reference %s is %s but --size is %s: give the reference's size, or leave "
                 "--size out to render at the reference's size\n", options.reference.c_str(),
                 sizeText(width, height).c_str(), sizeText(scene.width, scene.height).c_str());
    return 2;
}

// FLAG -> value of canonical scene arguments ({"--size", "160x90", "--hour", "18"}).
std::vector<std::pair<std::string, std::string>> argumentPairs(const std::vector<std::string>& arguments) {
    std::vector<std::pair<std::string, std::string>> pairs;
    for (size_t k = 0; k + 1 < arguments.size(); k += 2) pairs.push_back({arguments[k], arguments[k + 1]});
    return pairs;
}

std::string valueIn(const std::vector<std::pair<std::string, std::string>>& pairs, const std::string& flag) {
    for (const auto& [name, value] : pairs)
        if (name == flag) return value;
    return {};
}

// The reference's provenance (commands/provenance.h) applied to the comparison: with none, a
// warning and the reference compared as it is; a reference that is not a plain frame, or whose
// options this oasis cannot read, or that differs from the scene options given, is refused (2,
// saying why); otherwise `run` gets its options (all of them when no scene option was given, and
// its pipeline when --pipeline was not) and 0 is returned.
int adoptReference(const Options& options, const PngHeader& header, Side& reference, Options& run) {
    // Every text of the file is printed escaped (io/printable_text.h): it came from outside.
    const std::string shownPath = printableText(options.reference);
    const char* path = shownPath.c_str();
    Provenance provenance;
    std::string why;
    if (!readProvenance(header.texts, provenance, why)) {
        std::fprintf(stderr, "oasis: --reference %s has no oasis provenance: %s; it is compared as it is (its scene "
                     "options, view and legend unchecked)\n", path, why.c_str());
        return 0;
    }
    reference.renderer = provenance.renderer;
    std::string madeBy = "written by oasis " + printableText(provenance.version);
    if (provenance.view != "final" || provenance.hasLegend() || !provenance.viewOptions.empty()) {
        std::string what = "--view " + provenance.view + (provenance.viewOptions.empty() ? "" : " " + provenance.viewOptions) +
                           (provenance.hasLegend() ? " with a legend strip under the frame (oasis:legend: " +
                                                         provenance.legend + ")"
                                                   : " without a legend strip");
        std::fprintf(stderr, "oasis: --reference %s is not a frame alone: it is %s; compare --reference compares the "
                     "final view without a legend, as `oasis render --legend off` writes it\n", path, printableText(what).c_str());
        return 2;
    }
    PipelineKind pipeline;
    if (!parsePipelineKind(provenance.pipeline, pipeline)) {
        std::fprintf(stderr, "oasis: --reference %s: its oasis:pipeline '%s' is not forward or deferred (%s)\n", path,
                     printableText(provenance.pipeline).c_str(), madeBy.c_str());
        return 2;
    }
    // Its options read as this oasis reads them: only the picture's options, each known here.
    std::vector<std::string> arguments = splitArguments(provenance.options);
    for (size_t k = 0; k < arguments.size(); k += 2) {
        const SceneArgument* row = findSceneArgument(arguments[k]);
        if (!row || row->kind != SceneArgumentKind::Picture || row->bare) {
            std::fprintf(stderr, "oasis: --reference %s: its oasis:options '%s' hold '%s', not a scene option of this "
                         "oasis (%s)\n", path, printableText(provenance.options).c_str(), printableText(arguments[k]).c_str(), madeBy.c_str());
            return 2;
        }
    }
    std::vector<std::string> renderArguments = {"render"};
    renderArguments.insert(renderArguments.end(), arguments.begin(), arguments.end());
    ParseResult parsed = parseCommandLine(renderArguments);
    if (!parsed.ok || std::find(arguments.begin(), arguments.end(), "--size") == arguments.end()) {
        std::fprintf(stderr, "oasis: --reference %s: its oasis:options '%s' cannot be read here: %s (%s)\n", path,
                     printableText(provenance.options).c_str(), parsed.ok ? "no --size" : printableText(parsed.error).c_str(), madeBy.c_str());
        return 2;
    }
    const SceneOptions& theirs = parsed.options.scene;
    const int width = int(header.width), height = int(header.height);
    if (theirs.width != width || theirs.height != height) {
        std::fprintf(stderr, "oasis: --reference %s is %s but its oasis:options say --size %s (%s)\n", path,
                     sizeText(width, height).c_str(),
                     sizeText(theirs.width, theirs.height).c_str(), madeBy.c_str());
        return 2;
    }
    if (int code = referenceSizeRefused(options, width, height)) return code;
    // The scene options given here must be the reference's, every one (an option left out is at its
    // default here). --size alone gives nothing new: it was held to the reference's size above.
    bool sceneGiven = false;
    for (const std::string& flag : options.givenFlags) {
        const SceneArgument* row = findSceneArgument(flag);
        sceneGiven = sceneGiven || (row && row->kind == SceneArgumentKind::Picture && flag != "--size");
    }
    auto there = argumentPairs(sceneArguments(theirs, SceneArgumentKind::Picture));
    std::string differences;
    auto differ = [&](const std::string& flag, const std::string& thereValue, const std::string& hereValue) {
        differences += "\n  " + flag + ": " + (thereValue.empty() ? "the default" : thereValue) +
                       " there, " + (hereValue.empty() ? "the default" : hereValue) + " here";
    };
    if (sceneGiven) {
        SceneOptions mine = options.scene;
        if (!options.sizeGiven) std::tie(mine.width, mine.height) = std::pair{theirs.width, theirs.height};
        auto here = argumentPairs(sceneArguments(mine, SceneArgumentKind::Picture));
        for (const SceneArgument& row : sceneArgumentTable()) {
            if (row.kind != SceneArgumentKind::Picture) continue;
            std::string thereValue = valueIn(there, row.flag), hereValue = valueIn(here, row.flag);
            if (thereValue != hereValue) differ(row.flag, thereValue, hereValue);
        }
    }
    if (options.pipelineGiven && options.pipeline != pipeline)
        differ("--pipeline", pipelineName(pipeline), pipelineName(options.pipeline));
    std::string adopted = joinArguments(sceneArguments(theirs, SceneArgumentKind::Picture)) + " --pipeline " +
                          pipelineName(pipeline);
    if (!differences.empty()) {
        std::fprintf(stderr, "oasis: --reference %s was rendered with other options than the ones given:%s\n"
                     "  leave the scene options out to render with the reference's: %s\n", path, differences.c_str(),
                     adopted.c_str());
        return 2;
    }
    if (!sceneGiven) {
        run.sceneArguments = sceneArguments(theirs, SceneArgumentKind::Picture);
        run.sceneArguments.insert(run.sceneArguments.end(), options.sceneArguments.begin(), options.sceneArguments.end());
        run.sizeGiven = true;
    }
    if (!options.pipelineGiven) {
        run.pipeline = pipeline;
        run.pipelineGiven = true;
        run.sceneArguments.insert(run.sceneArguments.end(), {"--pipeline", pipelineName(pipeline)});
    }
    std::vector<std::string> runArguments = {"render"};
    runArguments.insert(runArguments.end(), run.sceneArguments.begin(), run.sceneArguments.end());
    ParseResult runParsed = parseCommandLine(runArguments);
    if (runParsed.ok) run.scene = runParsed.options.scene;  // else checkChildArguments says why
    if (!sceneGiven || !options.pipelineGiven)
        std::fprintf(stderr, "oasis: --reference %s: rendering with its options: %s (%s on %s)\n", path,
                     adopted.c_str(), madeBy.c_str(),
                     provenance.renderer.empty() ? "an unnamed renderer" : printableText(provenance.renderer).c_str());
    if (!provenance.driverOptions.empty())
        std::fprintf(stderr, "oasis: --reference %s was drawn with %s: driver options are not taken from a reference "
                     "(each side is drawn with its own set-up's)\n", path, printableText(provenance.driverOptions).c_str());
    return 0;
}

}  // namespace

int runDriverCompare(const Options& given) {
    Options options = given;  // with a reference's options and pipeline where it has them (adoptReference)
    std::vector<Side> sides;
    for (const std::string& name : options.drivers) sides.push_back(Side(name, findDriverSetup(name)));
    if (options.drivers.size() == 2 && options.drivers[0] == options.drivers[1]) sides[1].label += "-2";
    if (!options.reference.empty() && sides.empty()) sides.push_back(Side("here"));
    std::vector<std::string> extraArguments;
    if (!options.reference.empty()) {
        Side reference(fileLabel(options.reference));
        reference.reference = true;
        reference.path = options.reference;
        // What the file claims (its size, its provenance) is judged before its pixels are decoded.
        std::string error, bytes;
        PngHeader header;
        const uint32_t maxSide = given.allowLarge ? kMaxPngSide : kDefaultMaxPngSide;
        if (!readPngFile(options.reference, bytes, header, error, maxSide)) {
            std::fprintf(stderr, "oasis: --reference: %s\n", error.c_str());
            return 2;
        }
        if (int code = adoptReference(given, header, reference, options)) return code;
        if (int code = referenceSizeRefused(given, int(header.width), int(header.height))) return code;
        if (!decodePng(options.reference, bytes, reference.image, error, maxSide)) {
            std::fprintf(stderr, "oasis: --reference: %s\n", error.c_str());
            return 2;
        }
        if (!options.sizeGiven) {
            extraArguments = {"--size", sizeText(reference.image.width, reference.image.height)};
            options.scene.width = reference.image.width;
            options.scene.height = reference.image.height;
        }
        sides.push_back(std::move(reference));
    }
    // Where each set-up's frame ends up; the file sent must not be one of them.
    std::vector<std::string> finalPaths(sides.size());
    for (size_t k = 0; k < sides.size(); ++k) {
        if (sides[k].reference) continue;
        sides[k].path = finalPaths[k] = options.outDir + "/" + sides[k].label + ".png";  // staged later
        struct stat rendered, reference;
        if (!options.reference.empty() && stat(finalPaths[k].c_str(), &rendered) == 0 &&
            stat(options.reference.c_str(), &reference) == 0 && rendered.st_dev == reference.st_dev &&
            rendered.st_ino == reference.st_ino) {
            std::fprintf(stderr, "oasis: --reference %s is where %s's frame is written: move it, or give "
                         "another --out-dir\n", options.reference.c_str(), sides[k].label.c_str());
            return 2;
        }
    }
    if (int code = checkChildArguments(options, sides, extraArguments)) return code;
    if (mkdir(options.outDir.c_str(), 0755) != 0 && errno != EEXIST) {
        std::fprintf(stderr, "oasis: cannot create directory %s: %s\n", options.outDir.c_str(), std::strerror(errno));
        return 1;
    }
    // The children's frames are staged in a private directory, which is also their runtime
    // directory (zink warns without XDG_RUNTIME_DIR; mkdtemp makes it 0700, as one must be). The set
    // is written to --out-dir only when every side is there, and the directory goes with whatever a
    // driver or an interrupted child left in it, also when a signal ends oasis.
    const char* temporaryRoot = std::getenv("TMPDIR");
    std::string stagingTemplate = std::string(temporaryRoot && *temporaryRoot ? temporaryRoot : "/tmp") +
                                  "/oasis-runtime-XXXXXX";
    if (!mkdtemp(stagingTemplate.data())) {
        std::fprintf(stderr, "oasis: cannot create a directory like %s: %s\n", stagingTemplate.c_str(),
                     std::strerror(errno));
        return 1;
    }
    std::string stagingDir = stagingTemplate;
    RemovedOnInterrupt stagingRemoval(stagingDir, RemovedOnInterrupt::Kind::DirectoryTree);
    int code = 0;
    try {
        for (Side& side : sides) {
            if (side.reference) continue;
            side.path = stagingDir + "/" + side.label + ".png";
            if ((code = renderSide(options, side, extraArguments, stagingDir)) != 0) break;
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: %s\n", error.what());
        code = 1;
    }
    removeDirectoryTree(stagingDir);
    stagingRemoval.release();
    for (size_t k = 0; k < sides.size(); ++k)
        if (!sides[k].reference) sides[k].path = finalPaths[k];
    if (code != 0) return code;

    const Side &a = sides[0], &b = sides[1];
    if (a.image.width != b.image.width || a.image.height != b.image.height) {
        std::fprintf(stderr, "oasis: %s is %s but %s is %s\n", printableText(a.label).c_str(),
                     sizeText(a.image.width, a.image.height).c_str(), printableText(b.label).c_str(),
                     sizeText(b.image.width, b.image.height).c_str());
        return 1;
    }
    ImageDifference difference = compareImages(a.image, b.image);
    DifferingPixels differing = countDifferingPixels(a.image, b.image);
    Image heat;
    Provenance provenance;
    try {
        HeadlessContext context;  // the legend's text is drawn with GL, on this process's own driver
        heat = differenceImage(a.image, a.label, b.image, b.label);
        provenance = pictureProvenance(options, "difference", pipelineName(options.pipeline), heat.height, a.image.height);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "oasis: difference.png: %s\n", error.what());
        return 1;
    }
    std::string differencePath = options.outDir + "/difference.png", error;
    std::vector<OutputFile> set;
    for (const Side* s : {&a, &b})
        if (!s->reference) set.push_back({s->path, s->bytes});
    set.push_back({differencePath, {}});
    std::vector<std::string> written;
    if (!encodePng(heat, set.back().bytes, provenanceTexts(provenance)) || !writeFilesWhole(set, written, error)) {
        std::fprintf(stderr, "oasis: %s\n", error.empty() ? ("cannot write " + differencePath + ": PNG encoding failed").c_str()
                                                            : error.c_str());
        for (const std::string& path : written)
            std::fprintf(stderr, "oasis: wrote %s before the failure (complete, kept)\n", printableText(path).c_str());
        return 1;
    }
    bool identical = difference.maxAbs == 0;
    std::string pictureOptions = joinArguments(sceneArguments(options.scene, SceneArgumentKind::Picture));
    if (options.json) {
        auto side = [](const Side& s) {
            return "{\"name\": " + jsonString(s.label) + ", \"kind\": " +
                   jsonString(s.reference ? "reference" : s.setup ? "set-up" : "here") + ", \"image\": " +
                   jsonString(s.path) + ", \"renderer\": " + jsonString(s.renderer) + ", \"workarounds\": " +
                   jsonString(s.workarounds) + "}";
        };
        std::printf("{\"a\": %s, \"b\": %s, \"width\": %d, \"height\": %d, \"pipeline\": \"%s\", \"options\": %s, "
                    "\"psnr_db\": %.4f, \"max_abs\": %d, \"rmse\": %.6f, \"pixels_differing\": %s, \"identical\": %s, "
                    "\"difference\": %s}\n",
                    side(a).c_str(), side(b).c_str(), a.image.width, a.image.height, pipelineName(options.pipeline),
                    jsonString(pictureOptions).c_str(), difference.psnrDb, difference.maxAbs, difference.rmse, differing.json().c_str(),
                    identical ? "true" : "false", jsonString(differencePath).c_str());
        return 0;
    }
    std::printf("oasis: %s vs %s, %s, %s pipeline: PSNR %.2f dB%s, max abs %d, RMSE %.4f (8-bit RGB)\n",
                a.label.c_str(), b.label.c_str(), sizeText(a.image.width, a.image.height).c_str(),
                pipelineName(options.pipeline), difference.psnrDb, identical ? " (identical)" : "", difference.maxAbs,
                difference.rmse);
    std::printf("  %s\n", differing.describe().c_str());
    std::printf("  %-12s %s\n", "options:", pictureOptions.c_str());
    for (const Side* s : {&a, &b})
        std::printf("  %-12s %s\n", (s->label + ":").c_str(),
                    printableText(s->reference ? "saved image " + s->path + (s->renderer.empty() ? "" : ", drawn on " + s->renderer)
                                               : s->renderer + ", workarounds " + s->workarounds + ", " + s->path).c_str());
    std::fprintf(stderr, "  wrote %s\n", printableText(differencePath).c_str());  // a log line: stderr, as every command's
    return 0;
}

}  // namespace oasis
