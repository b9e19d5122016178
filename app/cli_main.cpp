#include <cstdio>

#include "cli/Cli.h"

int main(int argc, char** argv) {
    return mtc::cli::runCli(argc, argv);
}
