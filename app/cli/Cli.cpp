#include "cli/Cli.h"

#include <cstdio>
#include <string>

namespace mtc::cli {

int runCli(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: mtc200-cli check|run|restart|compile|md ...\n");
        return 2;
    }
    std::fprintf(stderr, "mtc200-cli: unknown command '%s'\n", argv[1]);
    return 2;
}

}  // namespace mtc::cli
