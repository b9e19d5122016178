#pragma once

namespace mtc::cli {

/// Entry point of mtc200-cli (CLI-CONTRACT.md). Returns the process exit code:
/// 0 success, 1 program/run errors, 2 usage or file error.
int runCli(int argc, char** argv);

}  // namespace mtc::cli
