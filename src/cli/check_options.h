// `oasis check`'s command-line options (the fields: CheckOptions in cli/options.h).
#pragma once
#include <string>
#include <vector>

#include "cli/options.h"

namespace oasis {

struct CheckOptionParse {
    bool ok = true;
    std::string error;  // when !ok: the message, naming the option and what it expects
};

// Reads the check option at arguments[i] (and its value, advancing i past it) into `options`.
CheckOptionParse parseCheckOption(const std::vector<std::string>& arguments, size_t& i, Options& options);

}  // namespace oasis
