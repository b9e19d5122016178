#!/usr/bin/env bash
# The suite once under Valgrind memcheck (issue 22 §1; not part of CI: it
# takes hours on 2 cores). Release build, as users run it.
#   scripts/valgrind.sh [core|fuzz|gui|shell ...]    default: all four
# - core, fuzz: core_tests and fuzz_replay_tests, each one process;
# - gui: every tests/gui QtTest binary (offscreen);
# - shell: the tests/cli scripts with MTC_CLI / MTC_PANEL pointing to
#   wrappers that run the real binaries under memcheck.
# gl tests are not run (an X server and OpenGL under memcheck). Leaks are
# the LeakSanitizer's business (scripts/test.sh --asan): memcheck looks for
# invalid reads/writes, uses of freed memory and of uninitialised values.
# Logs: build/release/valgrind/<pid>.log; the script prints every log with an
# error and exits 1 when there is one. Test failures from the slowdown
# (timeouts of the shell tests' 60 s limit) are listed but are not errors.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$here/build/release"
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=(core fuzz gui shell)
command -v valgrind >/dev/null || { echo "valgrind: valgrind is needed (scripts/setup.sh tools)" >&2; exit 2; }
"$here/scripts/setup.sh" release >/dev/null || exit 2

logs="$build/valgrind"
rm -rf "$logs" && mkdir -p "$logs/bin"
memcheck=(valgrind --error-exitcode=99 --leak-check=no --track-origins=yes
          --suppressions="$here/tests/sanitizer/valgrind.supp" --log-file="$logs/%p.log")
for tool in mtc200-cli mtc200-panel; do
  real="$build/app/$tool"
  printf '#!/usr/bin/env bash\nexec %s "%s" "$@"\n' "${memcheck[*]}" "$real" >"$logs/bin/$tool"
  chmod +x "$logs/bin/$tool"
done

failed=()
run() {  # name command...
  local name="$1"; shift
  echo "== $name"
  if ! "$@" >"$logs/$name.out" 2>&1; then failed+=("$name"); fi
}
export QT_QPA_PLATFORM=offscreen
export XDG_RUNTIME_DIR="$logs/xdg" && mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
for part in "${parts[@]}"; do
  case "$part" in
    core) run core_tests "${memcheck[@]}" "$build/tests/core_tests" ;;
    fuzz) run fuzz_replay_tests "${memcheck[@]}" "$build/tests/fuzz/fuzz_replay_tests" ;;
    gui)
      for source in "$here"/tests/gui/test_*.cpp; do
        name="$(basename "$source" .cpp)"
        run "$name" "${memcheck[@]}" "$build/tests/$name"
      done ;;
    shell)
      for script in "$here"/tests/cli/*.sh; do
        name="$(basename "$script" .sh)"
        run "$name" env MTC_CLI="$logs/bin/mtc200-cli" MTC_PANEL="$logs/bin/mtc200-panel" \
          MTC_GOLDEN="$here/tests/golden" MTC_SOURCE_DIR="$here" bash "$script"
      done ;;
    *) echo "valgrind: unknown part '$part'" >&2; exit 2 ;;
  esac
done

errors=0
for log in "$logs"/*.log; do
  if grep -q -E 'ERROR SUMMARY: [1-9]' "$log"; then
    errors=$((errors + 1))
    echo "---- $log"
    cat "$log"
  fi
done
echo "== $(ls "$logs"/*.log | wc -l) processes under memcheck, $errors with errors"
[ ${#failed[@]} -eq 0 ] || echo "tests that failed under valgrind (see $logs/<name>.out): ${failed[*]}"
[ "$errors" -eq 0 ]
