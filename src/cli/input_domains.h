// The domain of every numeric command-line input, in one table: the parser checks values against
// it, --help and docs/cli.md print it, the tests render its far ends. Inside a domain the picture is
// right (tests/gpu/domains_test.cpp); outside it the parser refuses the value (exit 2), except for
// an angle, which wraps.
#pragma once
#include <string>
#include <vector>

namespace oasis {

enum class DomainKind {
    Real,     // a decimal number in [low, high]
    Integer,  // digits only, in [low, high]
    Angle,    // any finite decimal number of degrees, wrapped into [low, high)
};

struct InputDomain {
    const char* name;    // the flag, or the flag and field: "--time", "--camera X"
    const char* unit;    // what the number counts: "seconds", "world units"
    double low, high;
    DomainKind kind;
    const char* reason;  // why the bounds are where they are (measured; see docs/cli.md)
};

// Every row; the order is --help's and docs/cli.md's.
const std::vector<InputDomain>& inputDomains();
// The row named `name`; throws std::out_of_range for a name not in the table (a programming error).
const InputDomain& inputDomain(const std::string& name);

// 1e7, 0.09, -80: a number as the messages print it.
std::string formatNumber(double value);
// "[-1e7, 1e7]" (an angle: "[-180, 180), wrapped"), as messages and --help print it.
std::string describeDomain(const InputDomain& domain);
// "--time expects seconds in [-5e6, 5e6], got '1e300'"
std::string domainError(const InputDomain& domain, const std::string& text);

// Reads `text` as a value of `domain`: decimal notation only (no leading space, hex, inf or nan),
// finite, inside the bounds; -0 reads as 0. An angle outside [low, high) is wrapped (in double, so
// 1e9 degrees keeps its exact remainder) and `wrapped` says so. False with `error` set otherwise.
bool parseInDomain(const std::string& text, const InputDomain& domain, double& value, std::string& error,
                   bool* wrapped = nullptr);

// An integer domain's value (the row must be DomainKind::Integer).
bool parseIntInDomain(const std::string& text, const InputDomain& domain, int& value, std::string& error);

// The help lines of the table: "  --time   seconds in [-5e6, 5e6]" one per row.
std::string inputDomainsHelp();

}  // namespace oasis
