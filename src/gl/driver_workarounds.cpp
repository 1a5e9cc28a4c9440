// The driver workarounds' table and the resolution of a command's request against a driver
// (gl/driver_workarounds.h). The rows' numbers are measured: docs/drivers.md says how.
#include "gl/driver_workarounds.h"

#include <fstream>
#include <regex>
#include <sstream>

namespace oasis::gl {
namespace {

std::string trimmed(const std::string& text) {
    size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

// A key is searched, not matched whole: "softpipe" finds "softpipe" in any GL_RENDERER.
bool keyMatches(const std::string& pattern, const std::string& text) {
    return pattern.empty() || std::regex_search(text, std::regex(pattern));
}

std::string keyText(const std::string& renderer, const std::string& version) {
    return "GL_RENDERER /" + renderer + "/" + (version.empty() ? std::string() : ", GL_VERSION /" + version + "/");
}

WorkaroundRow forcedFallbackRow(const char* name, const char* fallback, const char* leavesOut) {
    WorkaroundRow row{Workaround::ForcedFallback, name,
                      "crashes, hangs or draws wrong on the path this fallback leaves out (what oasis check proposes "
                      "in oasis-check/workarounds for such a driver)",
                      "", "", leavesOut,
                      "the fallback's own (docs/compatibility.md: every forced fallback draws the unforced image on "
                      "llvmpipe)",
                      "cli.check_driver_crash", ""};
    row.forces = fallback;
    return row;
}

}  // namespace

const std::vector<WorkaroundRow>& workaroundTable() {
    static const std::vector<WorkaroundRow> rows = {
        {Workaround::FlushBeforeComputeRead, "flush-before-compute-read",
         "a compute dispatch issued while a framebuffer is bound reads that framebuffer's textures as they "
         "were before the last draws: the render-target cache is not flushed before glDispatchCompute",
         "softpipe", "",
         "glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT) before LightTilingPass's dispatch (the one dispatch "
         "that reads a texture drawn the same frame)",
         "one call per LightTilingPass; on llvmpipe (not applied there) the frame is bit-identical with it and "
         "the pass's time the same within this machine's noise (docs/drivers.md)",
         "driver_bug.compute_reads_drawn_texture.softpipe", ""},
        {Workaround::ArrayWriteByLoop, "array-write-by-loop",
         "in a compute shader, a local array written at an index that differs per invocation "
         "(a[i] = x) lands in the element the first of four invocations run together names",
         "softpipe", "",
         "light_tiles.comp writes its per-slice boxes through for (k) if (k == i) a[k] = x "
         "(OASIS_ARRAY_WRITE_BY_LOOP)",
         "four compares per tile pixel in LightTilingPass; on llvmpipe (not applied there) the frame is "
         "bit-identical with it and the pass's time the same within this machine's noise (docs/drivers.md)",
         "driver_bug.indexed_array_write.softpipe", "OASIS_ARRAY_WRITE_BY_LOOP 1"},
        // A bug whose mend is a fallback oasis already has: the row applies --force no-depth-clamp.
        {Workaround::DepthClampOff, "depth-clamp-off",
         "with GL_DEPTH_CLAMP and a polygon offset, a triangle crossing the near or far plane gets depths that "
         "fit its vertices' depths offset and clamped to [0, 1] before interpolation: the unclamped part too far "
         "(ShadowPass's casters nearer the sun than a cascade's box)",
         "softpipe", "",
         "no depth clamp anywhere, as on a driver without it (--force no-depth-clamp): the cascades' boxes reach "
         "towards the sun up to the highest caster, the water is found per fragment, the light volumes unclamped",
         "the no-depth-clamp tier's own (its water a full-screen pass; on llvmpipe, not applied there, the "
         "forced fallback draws within the ES 3.0 tier's rule of the clamped frame: docs/compatibility.md)",
         "driver_bug.depth_clamp.softpipe", "", "no-depth-clamp"},
        // The forced fallbacks a profile may name (check/check_profile.h): a driver that
        // crashes, hangs or draws wrong on a path is given the fallback that leaves the path out.
        forcedFallbackRow("force-no-compute", "no-compute", "compute shaders: the plants interpreted and the lights tiled on the CPU's side"),
        forcedFallbackRow("force-no-ssbo", "no-ssbo", "storage buffers: the UBO light list, volume lights"),
        forcedFallbackRow("force-no-stencil-texturing", "no-stencil-texturing", "stencil texturing: the stencil view read back"),
        forcedFallbackRow("force-no-depth-clamp", "no-depth-clamp", "depth clamp: the shadow casters and the water without it"),
        forcedFallbackRow("force-no-clip-control", "no-clip-control", "clip control: standard depth"),
        forcedFallbackRow("force-no-read-only-depth", "no-read-only-depth", "sampling a depth buffer also bound for testing: a copy"),
        forcedFallbackRow("force-no-dsa", "no-dsa", "direct state access: bind-to-edit"),
        forcedFallbackRow("force-gl33", "gl33", "everything past OpenGL 3.3: the gl33 tier"),
    };
    return rows;
}

const WorkaroundRow* findWorkaround(const std::string& name) {
    for (const WorkaroundRow& row : workaroundTable())
        if (name == row.name) return &row;
    return nullptr;
}

std::string workaroundNames() {
    std::string names;
    for (const WorkaroundRow& row : workaroundTable()) names += (names.empty() ? "" : ", ") + std::string(row.name);
    return names;
}

std::string WorkaroundRequest::value() const {
    switch (mode) {
        case Mode::Default: return "default";
        case Mode::None: return "none";
        case Mode::All: return "all";
        case Mode::List: break;
    }
    std::string list;
    for (const std::string& name : names) list += (list.empty() ? "" : ",") + name;
    return list;
}

bool parseWorkaroundsValue(const std::string& text, WorkaroundRequest& request, std::string& error) {
    if (text == "default" || text == "none" || text == "all") {
        request.mode = text == "default" ? WorkaroundRequest::Mode::Default
                       : text == "none"  ? WorkaroundRequest::Mode::None
                                         : WorkaroundRequest::Mode::All;
        request.names.clear();
        return true;
    }
    std::vector<std::string> names;
    std::stringstream stream(text);
    for (std::string name; std::getline(stream, name, ',');) {
        name = trimmed(name);
        if (!findWorkaround(name)) {
            error = "--workarounds expects default, none, all or a list of: " + workaroundNames() + "; got '" + name + "'";
            return false;
        }
        names.push_back(name);
    }
    if (names.empty()) {
        error = "--workarounds expects default, none, all or a list of: " + workaroundNames();
        return false;
    }
    request.mode = WorkaroundRequest::Mode::List;
    request.names = names;
    return true;
}

bool parseWorkaroundRules(const std::string& text, const std::string& where, std::vector<WorkaroundRule>& rules,
                          std::string& error) {
    std::stringstream stream(text);
    int number = 0;
    for (std::string line; std::getline(stream, line);) {
        ++number;
        std::string place = where + ":" + std::to_string(number);
        line = trimmed(line.substr(0, line.find('#')));
        if (line.empty()) continue;
        std::vector<std::string> fields;
        std::stringstream parts(line);
        for (std::string field; std::getline(parts, field, '|');) fields.push_back(trimmed(field));
        if (fields.size() < 1 || fields.size() > 3) {
            error = place + ": expected NAME | RENDERER REGEX | VERSION REGEX, got '" + line + "'";
            return false;
        }
        WorkaroundRule rule;
        rule.on = fields[0].empty() || fields[0][0] != '-';
        rule.name = rule.on ? fields[0] : fields[0].substr(1);
        if (!findWorkaround(rule.name)) {
            error = place + ": unknown workaround '" + rule.name + "' (one of: " + workaroundNames() + ")";
            return false;
        }
        rule.renderer = fields.size() > 1 ? fields[1] : "";
        rule.version = fields.size() > 2 ? fields[2] : "";
        for (const std::string* pattern : {&rule.renderer, &rule.version}) try {
                std::regex check(*pattern);
            } catch (const std::regex_error&) {
                error = place + ": not a regular expression: '" + *pattern + "'";
                return false;
            }
        rule.where = place;
        rules.push_back(rule);
    }
    return true;
}

bool readWorkaroundsFile(const std::string& path, WorkaroundRequest& request, std::string& error) {
    std::ifstream in(path);
    if (!in) {
        error = "cannot read workarounds file '" + path + "'";
        return false;
    }
    std::stringstream text;
    text << in.rdbuf();
    std::vector<WorkaroundRule> rules;
    if (!parseWorkaroundRules(text.str(), path, rules, error)) return false;
    request.file = path;
    request.rules = rules;
    return true;
}

bool WorkaroundSet::has(Workaround id) const {
    for (const WorkaroundRow& row : workaroundTable())
        if (row.id == id)
            for (const WorkaroundState& state : rows)
                if (state.name == row.name) return state.applied;
    return false;
}

std::vector<std::string> WorkaroundSet::defines() const {
    std::vector<std::string> list;
    for (const WorkaroundState& state : rows) {
        const WorkaroundRow* row = findWorkaround(state.name);
        if (state.applied && row && *row->define) list.push_back(row->define);
    }
    return list;
}

std::vector<std::pair<std::string, std::string>> WorkaroundSet::forcedFallbacks() const {
    std::vector<std::pair<std::string, std::string>> fallbacks;
    for (const WorkaroundState& state : rows) {
        const WorkaroundRow* row = findWorkaround(state.name);
        if (state.applied && row && *row->forces) fallbacks.push_back({row->forces, row->name});
    }
    return fallbacks;
}

std::string WorkaroundSet::appliedList() const {
    std::string list;
    for (const WorkaroundState& state : rows)
        if (state.applied) list += (list.empty() ? "" : ",") + state.name;
    return list;
}

WorkaroundSet resolveWorkarounds(const WorkaroundRequest& request, const std::string& renderer,
                                 const std::string& version) {
    WorkaroundSet set;
    for (const WorkaroundRow& row : workaroundTable()) {
        WorkaroundState state{row.name, false, {}};
        bool forced = row.forcedOnly();
        state.applied = !forced && keyMatches(row.renderer, renderer) && keyMatches(row.version, version);
        state.why = forced ? std::string("table: only where a workarounds file or --workarounds names it (--force ") +
                                 row.forces + ")"
                           : std::string("table: ") + (state.applied ? "" : "no match: ") + keyText(row.renderer, row.version);
        for (const WorkaroundRule& rule : request.rules)
            if (rule.name == row.name && keyMatches(rule.renderer, renderer) && keyMatches(rule.version, version)) {
                state.applied = rule.on;
                state.why = rule.where + ": " + (rule.on ? "" : "off for ") + keyText(rule.renderer, rule.version);
            }
        using Mode = WorkaroundRequest::Mode;
        if (request.mode == Mode::None || request.mode == Mode::All) {
            state.applied = request.mode == Mode::All && !forced;
            state.why = "--workarounds " + request.value();
        } else if (request.mode == Mode::List) {
            state.applied = false;
            for (const std::string& name : request.names) state.applied = state.applied || name == row.name;
            state.why = "--workarounds " + request.value() + (state.applied ? "" : " (not listed)");
        }
        set.rows.push_back(state);
    }
    return set;
}

std::string workaroundTableText() {
    std::string text = "# oasis driver workarounds: NAME | GL_RENDERER regex | GL_VERSION regex (-NAME: off)\n";
    for (const WorkaroundRow& row : workaroundTable())
        if (!row.forcedOnly())  // a forced-fallback row has no driver of its own to key it by
            text += std::string(row.name) + " | " + row.renderer + (*row.version ? std::string(" | ") + row.version : "") + "\n";
    return text;
}

}  // namespace oasis::gl
