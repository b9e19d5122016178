#!/usr/bin/env python3
"""Reads clang-query output of init-order.query (scripts/lint.sh) and reports
every constructor initialiser that uses a member declared after the member
it initialises: that member is not constructed yet when it is used (read,
or passed by reference to a function that uses it). A use that only stores
a reference or an address may be legitimate; mark the initialiser's line
with `// lint: init-order ok (<why>)` to accept it."""
import os
import re
import sys

NOTE = re.compile(r'^(?P<path>/[^:]+):(?P<line>\d+):(?P<col>\d+): note: "(?P<name>\w+)" binds here')


def accepted(path, line):
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            lines = f.readlines()
    except OSError:
        return False
    return 0 < line <= len(lines) and "lint: init-order ok" in lines[line - 1]


def main(log):
    findings = set()
    match = {}

    def flush():
        if {"initialised", "used", "use"} <= match.keys():
            init, used, use = match["initialised"], match["used"], match["use"]
            same_file = os.path.realpath(init[0]) == os.path.realpath(used[0])
            if same_file and used[1:] >= init[1:] and not accepted(*use[:2]):
                findings.add((os.path.realpath(use[0]), use[1], use[2],
                              init[3].strip(), used[3].strip()))
        match.clear()

    with open(log, encoding="utf-8", errors="replace") as f:
        lines = f.readlines()
    for i, text in enumerate(lines):
        if text.startswith("Match #"):
            flush()
            continue
        m = NOTE.match(text)
        if m:
            source = lines[i + 1] if i + 1 < len(lines) else ""
            match[m.group("name")] = (m.group("path"), int(m.group("line")), int(m.group("col")),
                                      source)
    flush()
    for path, line, col, init, used in sorted(findings):
        print(f"{path}:{line}:{col}: error: member used before it is constructed: "
              f"'{used}' is declared after '{init}' [init-order]")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
