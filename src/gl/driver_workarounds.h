// The driver workarounds, one table: each row a driver bug oasis found (what the driver does wrong,
// which drivers by GL_RENDERER / GL_VERSION, what oasis does instead, its measured cost, the test
// that shows the bug), and how a command's request (--workarounds, --workarounds-file,
// $OASIS_WORKAROUNDS) turns the table into the set in effect, each with why. GL-free: the session
// resolves it against the context's strings; docs/drivers.md tells the bugs as bug reports.
#pragma once
#include <string>
#include <vector>

namespace oasis::gl {

// What a row changes in oasis; the renderer and its passes ask the set in effect for these.
enum class Workaround {
    FlushBeforeComputeRead,  // glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT) before a dispatch that reads a drawn texture
    ArrayWriteByLoop,        // local arrays written through a loop over constant indices (a shader #define)
    DepthClampOff,           // the no-depth-clamp fallback on a driver whose depth clamp is wrong (row.forces)
    ForcedFallback,          // a --force fallback, applied only where a file or --workarounds names it
};

struct WorkaroundRow {
    Workaround id;
    const char* name;      // "flush-before-compute-read": --workarounds and the file name it so
    const char* bug;       // what the driver does wrong
    const char* renderer;  // ECMAScript regex searched in GL_RENDERER: the drivers the table applies it to
    const char* version;   // ECMAScript regex searched in GL_VERSION ("" any version)
    const char* instead;   // what oasis does instead
    const char* cost;      // measured cost where it is applied, and elsewhere
    const char* test;      // the ctest that shows the bug and the mend (tests/driver_bugs/)
    const char* define;    // the #define the shaders get where it is applied ("" none)
    // The --force name a row applies ("" none). A forced-fallback row (`oasis check`'s proposed
    // profiles are made of them) has no driver of its own: it is applied only where a workarounds
    // file or --workarounds NAME asks, never by default nor by --workarounds all. A bug's row may
    // apply a fallback too (depth-clamp-off: no-depth-clamp); keyed by its driver, it is applied as
    // the other bugs' rows are.
    const char* forces = "";
    bool forcedOnly() const { return *forces && !*renderer; }  // a forced-fallback row, no driver
};

// Every row, in a fixed order.
const std::vector<WorkaroundRow>& workaroundTable();
const WorkaroundRow* findWorkaround(const std::string& name);
std::string workaroundNames();  // "flush-before-compute-read, array-write-by-loop"

// One line of a workarounds file: "NAME | RENDERER REGEX | VERSION REGEX" ('#' starts a comment;
// "-NAME" switches the row off where the line matches). The table's own rows printed this way
// (workaroundTableText) are a valid file.
struct WorkaroundRule {
    std::string name;  // a row's name
    bool on = true;
    std::string renderer, version;  // regexes, searched; "" matches anything
    std::string where;  // "FILE:LINE", for the reasons
};

// What a command asked for: the --workarounds value (default unless given) and the rules of
// --workarounds-file (or $OASIS_WORKAROUNDS, read when no file is given on the command line).
struct WorkaroundRequest {
    enum class Mode { Default, None, All, List };
    Mode mode = Mode::Default;
    std::vector<std::string> names;  // Mode::List: exactly these, every other row off
    std::string file;                // the file the rules came from ("" none)
    std::vector<WorkaroundRule> rules;
    std::string value() const;  // the --workarounds value as it would be given: "default", "none", "a,b"
};

// Parses a --workarounds value ("default", "none", "all" or a comma-separated list of row names)
// into `request`; false with `error` naming the bad word.
bool parseWorkaroundsValue(const std::string& text, WorkaroundRequest& request, std::string& error);
// Parses a workarounds file's text (`where` names it in the rules and errors); false with `error`
// on the first bad line ("FILE:3: unknown workaround 'x' (one of: ...)").
bool parseWorkaroundRules(const std::string& text, const std::string& where, std::vector<WorkaroundRule>& rules,
                          std::string& error);
// Reads FILE into request.file and request.rules; false with `error` when it cannot be read or parsed.
bool readWorkaroundsFile(const std::string& path, WorkaroundRequest& request, std::string& error);

// One row's answer for a driver: applied or not, and why ("table: GL_RENDERER matches /softpipe/").
struct WorkaroundState {
    std::string name;
    bool applied = false;
    std::string why;
};

// The set in effect: every row's state, in the table's order.
struct WorkaroundSet {
    std::vector<WorkaroundState> rows;
    bool has(Workaround id) const;
    std::vector<std::string> defines() const;  // the applied rows' shader #defines ("NAME 1")
    std::string appliedList() const;           // "flush-before-compute-read,array-write-by-loop" ("" none)
    // The applied rows' fallbacks: {--force name (row.forces), the row's name}.
    std::vector<std::pair<std::string, std::string>> forcedFallbacks() const;
};

// The table's default for this driver, then the file's matching rules in order, then the
// --workarounds value when it is not "default" (the command line has the last word).
WorkaroundSet resolveWorkarounds(const WorkaroundRequest& request, const std::string& renderer,
                                 const std::string& version);

// The table as a workarounds file (its rows' own renderer and version keys), for docs and tests.
std::string workaroundTableText();

// $OASIS_WORKAROUNDS: a workarounds file every command reads when no --workarounds-file is given.
constexpr const char* kWorkaroundsEnvironment = "OASIS_WORKAROUNDS";

}  // namespace oasis::gl
