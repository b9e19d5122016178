#!/usr/bin/env bash
# Sets up, builds and runs the whole suite with ctest.
#   scripts/test.sh          Release build, every test (gl tests under xvfb-run)
#   scripts/test.sh --asan   Address+UB sanitizer build, every test but the gl ones
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
preset=release
ctest_args=()
if [ "${1:-}" = "--asan" ]; then
  preset=asan
  ctest_args+=(-LE gl)
  export LSAN_OPTIONS="suppressions=$here/tests/sanitizer/lsan.supp:print_suppressions=0"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  shift
fi
"$here/scripts/setup.sh" "$preset"
cd "$here/build/$preset"
jobs=$(nproc 2>/dev/null || echo 2)
ctest --output-on-failure --timeout 600 -j "$jobs" "${ctest_args[@]}" "$@"
