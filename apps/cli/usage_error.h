#pragma once
// A command-line mistake (a flag, its value, a combination): the CLI prints it and exits 2.
#include <stdexcept>

namespace rayo {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace rayo
