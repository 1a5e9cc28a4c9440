// `oasis check`'s options (cli/check_options.h): the check sets every scene option itself (its
// cases), so it takes only these; numbers are read against cli/input_domains.h.
#include "cli/check_options.h"

#include "cli/input_domains.h"
#include "gl/capabilities.h"

namespace oasis {
namespace {

const char* const kPathFlags[] = {"--out-dir", "--references", "--write-references", "--expectations", "--junit",
                                  "--baseline", "--child-out", "--where"};

std::string* pathField(const std::string& flag, Options& options) {
    if (flag == "--out-dir") return &options.outDir;
    if (flag == "--references") return &options.checkReferences;
    if (flag == "--write-references") return &options.writeReferences;
    if (flag == "--expectations") return &options.check.expectations;
    if (flag == "--junit") return &options.check.junit;
    if (flag == "--baseline") return &options.check.baseline;
    if (flag == "--child-out") return &options.check.childOut;
    if (flag == "--where") return &options.check.childWhere;
    return nullptr;
}

// "I/N" with 1 <= I <= N.
bool parseShard(const std::string& text, CheckOptions& check, std::string& error) {
    size_t slash = text.find('/');
    std::string index = slash == std::string::npos ? text : text.substr(0, slash);
    std::string count = slash == std::string::npos ? "" : text.substr(slash + 1);
    if (slash == std::string::npos) {
        error = "--shard expects I/N (the I-th of N shards, 1 <= I <= N), got '" + text + "'";
        return false;
    }
    if (!parseIntInDomain(index, inputDomain("--shard I"), check.shardIndex, error) ||
        !parseIntInDomain(count, inputDomain("--shard N"), check.shardCount, error))
        return false;
    if (check.shardIndex > check.shardCount) {
        error = "--shard expects I/N with I at most N, got '" + text + "'";
        return false;
    }
    return true;
}

}  // namespace

CheckOptionParse parseCheckOption(const std::vector<std::string>& arguments, size_t& i, Options& options) {
    const std::string& flag = arguments[i];
    CheckOptions& check = options.check;
    auto hasValue = [&](size_t count) { return i + count < arguments.size(); };
    auto fail = [](const std::string& message) { return CheckOptionParse{false, message}; };
    if (flag == "--quick") return options.quick = true, CheckOptionParse{};
    if (flag == "--tables") return options.checkTables = true, CheckOptionParse{};
    if (flag == "--gpu-plants") return check.childGpuPlants = true, CheckOptionParse{};
    if (flag == "--") {  // the child's case arguments: everything after it
        check.childArguments.assign(arguments.begin() + long(i) + 1, arguments.end());
        i = arguments.size();
        return {};
    }
    if (flag == "--diff") {
        if (!hasValue(2)) return fail("option --diff needs two reports: --diff A.json B.json");
        options.diffReports = {arguments[i + 1], arguments[i + 2]};
        i += 2;
        return {};
    }
    bool isPath = false;
    for (const char* pathFlag : kPathFlags) isPath = isPath || flag == pathFlag;
    bool takesValue = isPath || flag == "--api" || flag == "--case" || flag == "--shard" || flag == "--retries" || flag == "--jobs" ||
                      flag == "--case-timeout" || flag == "--expect-renderer" || flag == "--child";
    // A word that is not an option is an argument too many (`--diff a b c`), not a scene option.
    if (!takesValue && (flag.empty() || flag[0] != '-'))
        return fail("unexpected argument '" + flag + "'" +
                    (options.diffReports.empty() ? "" : " (--diff takes two reports: --diff A.json B.json)"));
    if (!takesValue)
        return fail("option " + flag + " does not belong to `oasis check` (it sets the scene itself; see oasis "
                    "check --help)");
    if (!hasValue(1)) return fail("option " + flag + " needs a value (see oasis check --help)");
    const std::string& value = arguments[++i];
    std::string error;
    if (isPath) {
        if (value.empty()) return fail(flag + " expects a file or directory name, got ''");
        *pathField(flag, options) = value;
        if (flag == "--out-dir") options.outDirGiven = true;
        return {};
    }
    if (flag == "--api") {
        if (!gl::parseApi(value, options.scene.api)) return fail("--api expects gl or gles, got '" + value + "'");
        return {};
    }
    if (flag == "--case") {
        if (value.empty()) return fail("--case expects a case name or a glob such as '*-ubo-*', got ''");
        check.caseGlobs.push_back(value);
        return {};
    }
    if (flag == "--shard") return parseShard(value, check, error) ? CheckOptionParse{} : fail(error);
    if (flag == "--retries")
        return parseIntInDomain(value, inputDomain("--retries"), check.retries, error) ? CheckOptionParse{} : fail(error);
    if (flag == "--jobs")
        return parseIntInDomain(value, inputDomain("--jobs"), check.jobs, error) ? CheckOptionParse{} : fail(error);
    if (flag == "--case-timeout")
        return parseInDomain(value, inputDomain("--case-timeout"), check.caseTimeoutSeconds, error) ? CheckOptionParse{}
                                                                                                    : fail(error);
    if (flag == "--expect-renderer") {
        if (value.empty()) return fail("--expect-renderer expects a regular expression, got ''");
        check.expectRenderer = value;
        return {};
    }
    // --child
    if (value != "frame" && value != "passes" && value != "driver")
        return fail("--child expects frame, passes or driver, got '" + value + "'");
    check.child = value;
    return {};
}

}  // namespace oasis
