// The table of input domains and the strict reading of numbers against it.
#include "cli/input_domains.h"

#include "cli/options.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "render/light_paths.h"
#include "scene/vegetation.h"

namespace oasis {
namespace {

// Horizontal world coordinates: the terrain's finest octave counts noise cells as floats, exact to
// 2^24; past that, cells round and the CPU's heights (the flight, the plants' bases) leave the GPU's
// terrain. Measured with tests/gpu/domains_test.cpp's check on the diagonal x = z: bases within
// 1.5e-4 of the GPU's terrain up to 8e7, 1.5 units off at 9e7 and 1e8; 5e7 keeps a margin.
constexpr double kMaxHorizontal = 5.0e7;
// The default flight moves 7 units a second eastwards: it stays inside kMaxHorizontal.
constexpr double kMaxTime = 5.0e6;

}  // namespace

const std::vector<InputDomain>& inputDomains() {
    static const std::vector<InputDomain> table = {
        {"--time", "seconds", -kMaxTime, kMaxTime, DomainKind::Real,
         "the default flight flies 7 units/s east and must stay inside the --camera X domain"},
        {"--hour", "hours", 0.0, 24.0, DomainKind::Real, "one day; 24 is midnight like 0"},
        {"--camera X", "world units", -kMaxHorizontal, kMaxHorizontal, DomainKind::Real,
         "the terrain noise's finest cells are exact in float to 2^24: plants leave the GPU's terrain past 8e7"},
        {"--camera Y", "world units", -200.0, 2000.0, DomainKind::Real,
         "the terrain spans about -15 to 130 (4 million samples over 75 x 82 km); at 2000 looking down it is "
         "still seen, higher it fogs out"},
        {"--camera Z", "world units", -kMaxHorizontal, kMaxHorizontal, DomainKind::Real,
         "as --camera X"},
        {"--camera YAW", "degrees", -180.0, 180.0, DomainKind::Angle,
         "any finite angle, wrapped in double before the float camera sees it"},
        {"--camera PITCH", "degrees", -90.0, 90.0, DomainKind::Real, "straight down to straight up"},
        {"--water-level", "world units", -200.0, 200.0, DomainKind::Real,
         "past the terrain's span (about -15 to 130) the world is all dry or all flooded"},
        {"--ripples", "times the default strength", 0.0, 50.0, DomainKind::Real,
         "50 times the default is a storm; the far end renders finite and agreeing (tests/gpu/domains_test.cpp)"},
        {"--absorption", "per world unit", 0.0, 10.0, DomainKind::Real,
         "at 10 one unit of water passes at most e^-3 (5%) of the light: opaque water"},
        {"--vegetation-density", "times the default", 0.0, double(VegetationSettings::kMaxDensity),
         DomainKind::Real, "the placement's candidates per chunk"},
        {"--wind", "times the default strength", 0.0, double(VegetationSettings::kMaxWindStrength),
         DomainKind::Real, "the chunks' bounds allow this much sway"},
        {"--lights", "point lights", 0.0, double(kMaxLights), DomainKind::Integer,
         "the light list's capacity"},
        {"--size W", "pixels", 1.0, 32768.0, DomainKind::Integer,
         "also at most the driver's GL_MAX_TEXTURE_SIZE and 4 GiB of targets (checked on the context)"},
        {"--size H", "pixels", 1.0, 32768.0, DomainKind::Integer, "as --size W"},
        {"--frames", "frames", 1.0, 1000.0, DomainKind::Integer, "timed frames per measurement"},
        {"--seed", "a seed", 0.0, 999999.0, DomainKind::Integer,
         "the rounds' random order and the intervals' bootstrap; six digits are plenty to repeat a run"},
        {"--until-ci", "percent of the median", 0.5, 50.0, DomainKind::Real,
         "below 0.5% the round cap binds on every machine here; above 50% every run reaches it"},
        {"--driver-timeout", "seconds", 0.1, 86400.0, DomainKind::Real,
         "compare --driver: each child render's limit (default 300; softpipe takes ~10 s a 640x360 frame)"},
        {"--case-timeout", "seconds", 0.1, 86400.0, DomainKind::Real,
         "check: each case's child process limit (default 60; a healthy case on llvmpipe takes under 2 s, "
         "softpipe under 30 s)"},
        {"--jobs", "processes", 1.0, 64.0, DomainKind::Integer, "check: the cases' child processes at a time"},
        {"--retries", "re-runs", 0.0, 10.0, DomainKind::Integer, "check: a failing case runs again up to this often"},
        {"--shard I", "shard", 1.0, 1000.0, DomainKind::Integer, "check: which shard, at most N"},
        {"--shard N", "shards", 1.0, 1000.0, DomainKind::Integer, "check: how many shards the cases are dealt into"},
        {"--view-exposure", "stops", -20.0, 20.0, DomainKind::Real,
         "the HDR views' scale 2^stops: 1e-6 to 1e6 covers every value a half float holds"},
        {"--range LO", "the view's values", -1e9, 1e9, DomainKind::Real,
         "every view's values lie within it (positions within 5e7 + the view distance, half floats within "
         "65504); LO must also be below HI"},
        {"--range HI", "the view's values", -1e9, 1e9, DomainKind::Real, "as --range LO"},
        {"--at X", "pixels from the left", 0.0, 32767.0, DomainKind::Integer, "also inside the frame's --size"},
        {"--at Y", "pixels from the top", 0.0, 32767.0, DomainKind::Integer, "also inside the frame's --size"},
    };
    return table;
}

const InputDomain& inputDomain(const std::string& name) {
    for (const InputDomain& domain : inputDomains())
        if (name == domain.name) return domain;
    throw std::out_of_range("no input domain named " + name);
}

// 1e7 rather than 1e+07, 0.09 rather than 0.0899999.
std::string formatNumber(double value) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.6g", value);
    std::string s = text;
    size_t e = s.find('e');
    if (e == std::string::npos) return s;
    std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    bool negative = exponent[0] == '-';
    size_t digits = exponent.find_first_not_of("+-0");
    return mantissa + "e" + (negative ? "-" : "") + (digits == std::string::npos ? "0" : exponent.substr(digits));
}

namespace {

// Decimal notation: an optional sign, digits with at most one point, an optional exponent.
bool isDecimal(const std::string& text) {
    size_t i = 0, n = text.size();
    if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
    size_t digits = 0, points = 0;
    for (; i < n && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.'); ++i)
        text[i] == '.' ? ++points : ++digits;
    if (digits == 0 || points > 1) return false;
    if (i < n && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < n && (text[i] == '+' || text[i] == '-')) ++i;
        size_t exponentDigits = 0;
        for (; i < n && std::isdigit(static_cast<unsigned char>(text[i])); ++i) ++exponentDigits;
        if (exponentDigits == 0) return false;
    }
    return i == n;
}

// Decimal digits only, at most 9 of them after any leading zeros (9 digits cannot overflow an int;
// "0000000004" is 4).
bool isDigits(const std::string& text) {
    if (text.empty()) return false;
    for (char c : text)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    size_t significant = text.find_first_not_of('0');
    return significant == std::string::npos || text.size() - significant <= 9;
}

}  // namespace

std::string describeDomain(const InputDomain& domain) {
    std::string range = "[" + formatNumber(domain.low) + ", " + formatNumber(domain.high);
    if (domain.kind == DomainKind::Angle) return range + "), wrapped";
    return range + "]" + (domain.kind == DomainKind::Integer ? " (an integer)" : "");
}

std::string domainError(const InputDomain& domain, const std::string& text) {
    return std::string(domain.name) + " expects " + domain.unit + " in " + describeDomain(domain) + ", got '" +
           text + "'";
}

bool parseInDomain(const std::string& text, const InputDomain& domain, double& value, std::string& error,
                   bool* wrapped) {
    if (wrapped) *wrapped = false;
    if (domain.kind == DomainKind::Integer) {
        int integer = 0;
        if (!parseIntInDomain(text, domain, integer, error)) return false;
        value = integer;
        return true;
    }
    double parsed = 0.0;
    if (isDecimal(text)) {
        errno = 0;
        parsed = std::strtod(text.c_str(), nullptr);  // ERANGE for a subnormal too: its value is fine
    }
    if (!isDecimal(text) || !std::isfinite(parsed)) {
        error = domainError(domain, text);
        return false;
    }
    parsed += 0.0;  // -0 reads as 0
    if (domain.kind == DomainKind::Angle) {
        double span = domain.high - domain.low;
        double turned = std::fmod(parsed - domain.low, span);  // exact, for any finite value
        if (turned < 0.0) turned += span;
        double inRange = domain.low + turned;
        if (inRange >= domain.high) inRange = domain.low;  // a tiny negative remainder rounds up to the span
        if (wrapped) *wrapped = inRange != parsed;
        value = inRange;
        return true;
    }
    if (!(parsed >= domain.low && parsed <= domain.high)) {
        error = domainError(domain, text);
        return false;
    }
    value = parsed;
    return true;
}

bool parseIntInDomain(const std::string& text, const InputDomain& domain, int& value, std::string& error) {
    if (!isDigits(text)) {
        error = domainError(domain, text);
        return false;
    }
    long parsed = std::strtol(text.c_str(), nullptr, 10);
    if (double(parsed) < domain.low || double(parsed) > domain.high) {
        error = domainError(domain, text);
        return false;
    }
    value = int(parsed);
    return true;
}

std::string inputDomainsHelp() {
    std::string help = "input domains (outside them a value is refused; an angle wraps):\n";
    for (const InputDomain& domain : inputDomains()) {
        char line[160];
        std::snprintf(line, sizeof(line), "  %-22s %s in %s\n", domain.name, domain.unit, describeDomain(domain).c_str());
        help += line;
    }
    return help;
}

// The readers of the values of several numbers (--size, --camera; declared in cli/options.h),
// each number read against its own domain.
bool parseSize(const std::string& text, int& width, int& height, std::string* error) {
    size_t x = text.find('x');
    std::string why;
    int w = 0, h = 0;
    bool ok = x != std::string::npos && parseIntInDomain(text.substr(0, x), inputDomain("--size W"), w, why) &&
              parseIntInDomain(text.substr(x + 1), inputDomain("--size H"), h, why);
    if (!ok) {
        if (error)
            *error = "--size expects WxH, each " + std::string(inputDomain("--size W").unit) + " in " +
                     describeDomain(inputDomain("--size W")) + ", e.g. 1280x720, got '" + text + "'";
        return false;
    }
    width = w;
    height = h;
    return true;
}

bool parseCameraPose(const std::string& text, CameraPose& pose, std::string* error, std::string* note) {
    static const char* const kFields[] = {"--camera X", "--camera Y", "--camera Z", "--camera YAW", "--camera PITCH"};
    auto fail = [&](const std::string& why) {
        if (error) *error = why;
        return false;
    };
    std::vector<std::string> items;
    size_t start = 0;
    for (size_t comma; (comma = text.find(',', start)) != std::string::npos; start = comma + 1)
        items.push_back(text.substr(start, comma - start));
    items.push_back(text.substr(start));
    if (items.size() != 5)
        return fail("--camera expects X,Y,Z,YAW,PITCH (five numbers), got '" + text + "'");
    double values[5];
    bool yawWrapped = false;
    for (size_t k = 0; k < 5; ++k) {
        std::string why;
        if (!parseInDomain(items[k], inputDomain(kFields[k]), values[k], why, k == 3 ? &yawWrapped : nullptr))
            return fail(why + " (in --camera '" + text + "')");
    }
    pose.position = glm::dvec3(values[0], values[1], values[2]);
    pose.yawDegrees = float(values[3]);
    pose.pitchDegrees = float(values[4]);
    const InputDomain& yaw = inputDomain("--camera YAW");
    if (note) *note = yawWrapped ? "--camera YAW " + items[3] + " is " + formatNumber(values[3]) + " degrees, wrapped into [" +
                                       formatNumber(yaw.low) + ", " + formatNumber(yaw.high) + ")"
                                 : std::string();
    return true;
}

}  // namespace oasis
