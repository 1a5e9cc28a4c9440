// The page's hooks into the running app (called from shell.html and tests/web/web_test.mjs through
// ccall): the capability report, switching pipeline and view, and the final frame as a PNG file
// in the page's file system, written by the same readDisplay + writePng as the native `render`.
#include <emscripten.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "web/web_app.h"

namespace oasis::web {
WebApp& app();  // web_main.cpp
}

namespace {
// `text` as a JSON string's contents: shader logs carry newlines and quotes.
std::string escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\', out += c;
        else if (c == '\n') out += "\\n";
        else if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
    return out;
}

char* copy(const std::string& text) {
    char* out = static_cast<char*>(std::malloc(text.size() + 1));
    std::memcpy(out, text.c_str(), text.size() + 1);
    return out;
}
}  // namespace

extern "C" {
// JSON: the context (unmasked renderer where the browser gives it), every feature, the fallbacks.
// The caller frees the string.
EMSCRIPTEN_KEEPALIVE char* oasis_capabilities() { return copy(oasis::web::app().capabilityJson()); }

// The window app's state (WebApp::windowStateJson); the caller frees the string.
EMSCRIPTEN_KEEPALIVE char* oasis_window_state() { return copy(oasis::web::app().windowStateJson()); }

EMSCRIPTEN_KEEPALIVE int oasis_frames_drawn() { return oasis::web::app().framesDrawn(); }

// 0 forward, 1 deferred.
EMSCRIPTEN_KEEPALIVE void oasis_set_pipeline(int deferred) {
    oasis::web::app().setPipeline(deferred ? oasis::PipelineKind::Deferred : oasis::PipelineKind::Forward);
}

// 1 when `view` names a view (the panel's view list: the debug views, the error views, overview).
EMSCRIPTEN_KEEPALIVE int oasis_set_view(const char* view) { return oasis::web::app().setView(view) ? 1 : 0; }

// `oasis probe --at X,Y --json` in the page; the caller frees the string.
EMSCRIPTEN_KEEPALIVE char* oasis_probe_json(int deferred, int x, int y) {
    try {
        return copy(oasis::web::app().probeJson(deferred ? oasis::PipelineKind::Deferred : oasis::PipelineKind::Forward, x, y));
    } catch (const std::exception& e) {
        return copy(std::string("{\"error\":\"") + escaped(e.what()) + "\"}");
    }
}

// 1 when the PNG was written.
EMSCRIPTEN_KEEPALIVE int oasis_write_final_png(int deferred, const char* path) {
    return oasis::web::app().writeFinalPng(deferred ? oasis::PipelineKind::Deferred : oasis::PipelineKind::Forward,
                                           path) ? 1 : 0;
}
}

#include "check/check_judge.h"
#include "render/image.h"

namespace {
std::string jsonNumber(double value) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.3f", value);
    return text;
}
}  // namespace

extern "C" {
// Judges the PNG at `result` against the PNG at `reference` (both in the page's file system) by the
// rule of `oasis check` named `rule` ("cross-driver", ...): the same judge() as the native check.
// JSON {"pass", "psnr_db", "max_abs", "pixels_over", "pixels", "summary"} or {"error"}; caller frees.
EMSCRIPTEN_KEEPALIVE char* oasis_judge(const char* result, const char* reference, const char* rule) {
    oasis::Image a, b;
    std::string error;
    if (!oasis::readPng(result, a, error) || !oasis::readPng(reference, b, error))
        return copy("{\"error\":\"" + error + "\"}");
    try {
        oasis::Judgement j = oasis::judge(a, b, oasis::imageRule(rule));
        return copy(std::string("{\"pass\":") + (j.pass ? "true" : "false") + ",\"psnr_db\":" + jsonNumber(j.psnrDb) +
                    ",\"max_abs\":" + std::to_string(j.maxAbs) + ",\"pixels_over\":" + std::to_string(j.pixelsOver) +
                    ",\"pixels\":" + std::to_string(long(a.width) * a.height) + ",\"summary\":\"" + j.summary + "\"}");
    } catch (const std::exception& e) {
        return copy(std::string("{\"error\":\"") + e.what() + "\"}");
    }
}
}

#include "cli/options.h"
#include "check/check.h"
#include "check/check_diff.h"
#include "commands/json_value.h"

extern "C" {
// `oasis check ARGS` in the page, run to the end before it returns (the page's frame loop waits):
// argsJson is a JSON array of the command's arguments (["--quick"], [] for the full check); the
// page's context is OpenGL ES, so `--api gles` is added unless given, and `--out-dir /oasis-check`
// unless given. The same cases, rules and report (report.json, report.html) as the native command,
// written into the page's file system. Returns JSON {"exit", "dir", "json", "html", "pass",
// "fail", "skip", "cases", "renderer"} (read back from report.json) or {"exit", "error"}; the
// caller frees it.
EMSCRIPTEN_KEEPALIVE char* oasis_check(const char* argsJson) {
    oasis::JsonValue parsed;
    std::string error;
    if (!oasis::parseJson(argsJson ? argsJson : "[]", parsed, error) || !parsed.isArray())
        return copy("{\"exit\":2,\"error\":\"oasis_check expects a JSON array of arguments" +
                    escaped(error.empty() ? "" : ": " + error) + "\"}");
    std::vector<std::string> arguments = {"check"};
    bool hasApi = false, hasOutDir = false;
    for (const oasis::JsonValue& item : parsed.items) {
        if (!item.isString()) return copy("{\"exit\":2,\"error\":\"oasis_check's arguments are strings\"}");
        hasApi = hasApi || item.text == "--api";
        hasOutDir = hasOutDir || item.text == "--out-dir";
        arguments.push_back(item.text);
    }
    if (!hasApi) arguments.insert(arguments.end(), {"--api", "gles"});
    if (!hasOutDir) arguments.insert(arguments.end(), {"--out-dir", "/oasis-check"});
    oasis::ParseResult options = oasis::parseCommandLine(arguments);
    if (!options.ok) return copy("{\"exit\":2,\"error\":\"" + escaped(options.error) + "\"}");
    std::fflush(stdout);
    int exitCode = oasis::runCheckCommand(options.options);
    std::fflush(stdout);
    std::string dir = options.options.outDir;
    oasis::CheckRun run;
    if (!oasis::readCheckRun(dir + "/report.json", run, error))
        return copy("{\"exit\":" + std::to_string(exitCode) + ",\"error\":\"" + escaped(error) + "\"}");
    return copy("{\"exit\":" + std::to_string(exitCode) + ",\"dir\":\"" + escaped(dir) + "\",\"json\":\"" +
                escaped(dir + "/report.json") + "\",\"html\":\"" + escaped(dir + "/report.html") +
                "\",\"pass\":" + std::to_string(run.count("pass")) + ",\"fail\":" + std::to_string(run.count("fail")) +
                ",\"skip\":" + std::to_string(run.count("skip")) + ",\"cases\":" + std::to_string(run.cases.size()) +
                ",\"renderer\":\"" + escaped(run.renderer) + "\"}");
}
}
