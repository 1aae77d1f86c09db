#pragma once
// The `rayo` command line: `rayo render [SCENE] [options]`, `rayo info SCENE`, `--help`,
// `--version`. Returns the process exit status (0 ok, 1 bad input or failure, 2 bad usage).
#include <iosfwd>

namespace rayo {

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace rayo
