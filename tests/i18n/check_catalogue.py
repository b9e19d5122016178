#!/usr/bin/env python3
"""Checks a Qt Linguist catalogue that lupdate has just brought up to date
with the sources: every message must have a finished, non-empty translation
(plural messages: every form), and no message may be left over from texts
the sources no longer have. Prints each problem; exit status 1 if any.
Usage: check_catalogue.py FILE.ts [--plural-only]"""
import sys
import xml.etree.ElementTree as ET


def problems(path, plural_only):
    found = []
    root = ET.parse(path).getroot()
    count = 0
    for context in root.iter("context"):
        name = context.findtext("name")
        for message in context.iter("message"):
            source = message.findtext("source") or ""
            translation = message.find("translation")
            numerus = message.get("numerus") == "yes"
            if plural_only and not numerus:
                found.append(f"{name}: not a plural text in the plural-only catalogue: {source!r}")
                continue
            count += 1
            kind = translation.get("type") if translation is not None else "missing"
            if kind in ("vanished", "obsolete"):
                found.append(f"{name}: text no longer in the sources: {source!r}")
            elif kind == "unfinished":
                found.append(f"{name}: no translation: {source!r}")
            elif numerus:
                forms = [f.text or "" for f in translation.iter("numerusform")]
                if not forms or any(not f.strip() for f in forms):
                    found.append(f"{name}: empty plural form: {source!r}")
            elif not (translation.text or "").strip():
                found.append(f"{name}: empty translation: {source!r}")
    return count, found


def main():
    path = sys.argv[1]
    count, found = problems(path, "--plural-only" in sys.argv[2:])
    for line in found:
        print(f"{path}: {line}")
    print(f"{path}: {count} messages, {len(found)} problems")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
