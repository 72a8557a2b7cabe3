#!/usr/bin/env python3
"""Lists the places in include/ and tools/ that compare a Certified_sign with
`==` or `!=` against a named sign (issue 29: one idiom for uncertainty).
relgeo's rule (core/certified_sign.h): a comparison says whether it means
`certainly(s, v)` (the kernel decided v) or `possibly(s, v)` (v, or the kernel
does not know), and `is_certain(s)` tests for `uncertain`; a bare `s != v`
silently counts `uncertain` as "not v". Prints one line per comparison
(file:line: text) and exits 1 when there is any, 0 (printing nothing)
otherwise."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
COMPARISON = re.compile(r"[!=]=\s*Certified_sign::\w+|Certified_sign::\w+\s*[!=]=")
HOME = ROOT / "include" / "relgeo" / "core" / "certified_sign.h"


def main():
    found = []
    for folder in ("include", "tools"):
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix not in (".h", ".cpp") or path == HOME:
                continue
            for n, line in enumerate(path.read_text().splitlines(), 1):
                if COMPARISON.search(line):
                    found.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    for f in found:
        print(f)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
