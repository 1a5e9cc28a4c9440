// The check's reference sets and baselines (check/check_references.h).
#include "check/check_references.h"

#include <dirent.h>
#include <sys/stat.h>

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/json_text.h"
#include "commands/json_value.h"
#include "io/png_text.h"

namespace oasis {
namespace {

bool endsWithPng(const std::string& name) { return name.size() > 4 && name.compare(name.size() - 4, 4, ".png") == 0; }

void fnv1a(uint64_t& hash, const std::string& bytes) {
    for (unsigned char c : bytes) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
}

std::string readWhole(const std::string& path, bool& ok) {
    std::ifstream file(path, std::ios::binary);
    std::stringstream bytes;
    bytes << file.rdbuf();
    ok = bool(file) || file.eof();
    return bytes.str();
}

std::string textOf(const PngTexts& texts, const char* keyword) {
    const PngText* text = texts.find(keyword);
    return text ? text->text : std::string();
}

}  // namespace

bool openReferenceSet(const std::string& dir, ReferenceSet& set, std::string& error) {
    struct stat info;
    if (stat(dir.c_str(), &info) != 0) {
        error = "the reference directory " + dir + " does not exist";
        return false;
    }
    if (!S_ISDIR(info.st_mode)) {
        error = "the reference directory " + dir + " is not a directory";
        return false;
    }
    DIR* listing = opendir(dir.c_str());
    if (!listing) {
        error = "the reference directory " + dir + " cannot be read";
        return false;
    }
    std::vector<std::string> names;
    while (dirent* entry = readdir(listing))
        if (endsWithPng(entry->d_name)) names.push_back(entry->d_name);
    closedir(listing);
    if (names.empty()) {
        error = "the reference directory " + dir + " holds no PNG";
        return false;
    }
    std::sort(names.begin(), names.end());
    uint64_t hash = 14695981039346656037ull;
    for (const std::string& name : names) {
        bool ok = false;
        fnv1a(hash, name + '\0');
        fnv1a(hash, readWhole(dir + "/" + name, ok));
    }
    char text[32];
    std::snprintf(text, sizeof(text), "fnv1a64:%016" PRIx64, hash);
    set = {dir, text, int(names.size())};
    return true;
}

ReferenceFrame readReferenceFrame(const std::string& dir, const std::string& caseName) {
    ReferenceFrame frame;
    std::string path = dir + "/" + caseName + ".png";
    struct stat info;
    if (stat(path.c_str(), &info) != 0) {
        frame.error = "no file " + path;
        return frame;
    }
    PngTexts texts;
    if (!readPng(path, frame.image, frame.error, &texts)) return frame;
    frame.renderer = textOf(texts, "oasis:renderer");
    frame.driverRelease = driverRelease(textOf(texts, "oasis:gl-version"));
    frame.readable = true;
    return frame;
}

std::string driverRelease(const std::string& glVersion) {
    size_t mesa = glVersion.rfind("Mesa ");
    if (mesa != std::string::npos) return glVersion.substr(mesa);
    size_t afterNumbers = glVersion.find(' ', glVersion.find_first_of("0123456789"));
    return afterNumbers == std::string::npos ? glVersion : glVersion.substr(afterNumbers + 1);
}

bool baselineExists(const std::string& dir) {
    struct stat info;
    return stat((dir + "/baseline.json").c_str(), &info) == 0;
}

bool readBaselineManifest(const std::string& dir, BaselineManifest& manifest, std::string& error) {
    bool ok = false;
    std::string text = readWhole(dir + "/baseline.json", ok);
    JsonValue root;
    if (!ok || !parseJson(text, root, error) || !root.isObject()) {
        error = dir + "/baseline.json is not a baseline manifest" + (error.empty() ? "" : ": " + error);
        return false;
    }
    auto string = [&](const char* key) {
        const JsonValue* value = root.find(key);
        return value && value->isString() ? value->text : std::string();
    };
    manifest.renderer = string("renderer");
    manifest.glVersion = string("gl_version");
    manifest.oasisCommit = string("oasis_commit");
    if (const JsonValue* cases = root.find("cases"); cases && cases->isArray())
        for (const JsonValue& name : cases->items)
            if (name.isString()) manifest.cases.push_back(name.text);
    if (manifest.renderer.empty()) {
        error = dir + "/baseline.json names no renderer";
        return false;
    }
    return true;
}

std::string baselineManifestJson(const BaselineManifest& manifest) {
    std::string json = "{\"schema\": \"oasis-baseline/1\", \"renderer\": " + jsonString(manifest.renderer) +
                       ", \"gl_version\": " + jsonString(manifest.glVersion) + ", \"oasis_commit\": " +
                       jsonString(manifest.oasisCommit) + ", \"cases\": [";
    for (size_t i = 0; i < manifest.cases.size(); ++i) json += (i ? ", " : "") + jsonString(manifest.cases[i]);
    return json + "]}\n";
}

}  // namespace oasis
