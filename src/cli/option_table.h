// The scene options, one row each: flag, how its value is read and written back, --help's text,
// the window panel's widget, the bench's levels and the provenance's kind. The parser, --help (and docs/command-line.md
// through it), the panel and the bench knobs are made from these rows; a new option is a row.
// Domains stay in cli/input_domains.h, idle combinations in cli/option_rules.h.
#pragma once
#include <string>
#include <vector>

namespace oasis {

struct Options;
struct SceneOptions;
struct SceneSettings;

// The window panel's widget for a row: the section (a collapsing header) it sits in and its kind.
enum class OptionWidgetKind {
    None,      // not in the panel (or drawn by hand there: time, camera, lights)
    Checkbox,  // a two-way switch: checked is the row's `on` word
    Slider,    // a real number between low and high
    Radios,    // one radio button per choice, on the line of `label` (or of the widget before)
};

struct OptionWidget {
    OptionWidgetKind kind = OptionWidgetKind::None;
    const char* section = nullptr;  // "shadows", "water", "vegetation", "frame work"
    const char* label = nullptr;    // null for Radios that follow the widget before on its line
    float low = 0.0f, high = 0.0f;  // a slider's range (inside the row's input domain)
    const char* format = "%.3f";
    bool applyOnRelease = false;  // the value rebuilds scene content (plant placement): set on release
};

// The bench's knob for a row: its levels are values of the option, cheapest first; the reference
// render takes the last. `knob` names it in bench.csv and bench.json.
struct OptionBenchKnob {
    const char* knob = nullptr;  // null: the bench does not vary this option
    const char* description = nullptr;
    std::vector<const char*> levels;
    int defaultLevel = 0;
};

// Where a row's value goes in a picture's provenance (cli/scene_arguments.h): what the frame
// shows, or which of this driver's paths drew it.
enum class SceneArgumentKind {
    Picture,  // what the frame shows (--size, --hour, --camera, ...): compare --reference adopts or checks them
    Driver,   // which of this driver's paths drew it (--api, --force, ...): a driver comparison varies them
    None,     // not written (--gl-debug)
};

struct OptionRow {
    const char* flag = nullptr;
    const char* synopsis = "";  // the value's form in --help ("WxH"; a switch's is its words); "" given bare
    const char* help = "";      // --help's description, lines separated by '\n'
    std::string (*helpTail)() = nullptr;  // appended to the help (names taken from another table)

    // Reading the value. A two-way switch names its words and field; a real number names its field
    // (read in the flag's input domain); anything else has its own reader and writer.
    const char* on = nullptr;
    const char* off = nullptr;
    bool& (*switchField)(SceneOptions&) = nullptr;
    float& (*numberField)(SceneOptions&) = nullptr;
    bool (*read)(const std::string& value, Options& options, std::vector<std::string>& notes,
                 std::string& error) = nullptr;
    std::string (*write)(const SceneOptions& scene) = nullptr;  // the value as it would be given
    std::vector<std::string> (*choices)() = nullptr;            // the words a Radios widget offers
    bool bare = false;  // given without a value (--no-compute): `read` gets ""
    SceneArgumentKind provenance = SceneArgumentKind::Picture;

    OptionWidget widget;
    OptionBenchKnob bench;

    bool isSwitch() const { return switchField != nullptr; }
};

// Every row, in --help's order.
const std::vector<OptionRow>& optionTable();
// The row of `flag`; null for options that are not scene options (--view, --out, ...).
const OptionRow* findOption(const std::string& flag);

// Reads `value` into `options` as the row says; false with the parser's message in `error`.
bool readOption(const OptionRow& row, const std::string& value, Options& options, std::vector<std::string>& notes,
                std::string& error);
// The row's value in `scene` as it would be given on the command line ("on", "0.5", "half").
std::string optionValue(const OptionRow& row, const SceneOptions& scene);

// --help's scene option lines, one entry per row: "  --size WxH                frame size ...".
std::string sceneOptionsHelp();

// The fields the rows reach, between a running scene and SceneOptions: the window's panel and the
// bench edit a scene through the rows this way.
SceneOptions sceneOptionsOf(const SceneSettings& scene);
void applySceneOptions(const SceneOptions& options, SceneSettings& scene);

}  // namespace oasis
