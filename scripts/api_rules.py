#!/usr/bin/env python3
"""Checks two rules of relgeo's code (issue 29) and lists what breaks them,
one line per place (file:line: text); exits 1 when anything is listed, 0
(printing nothing) otherwise. `api_rules.py kernels`, `api_rules.py signs`,
or both when no rule is named.

kernels: the public templates of include/relgeo that take a kernel
parameter without a concept (every public algorithm states the kernel
concept it needs). A kernel parameter is a template parameter named K or
Kernel, or ending in _kernel/Kernel; it is constrained when it is declared
with a concept (`template <IntersectionKernel_3 K>`) or the template has a
requires-clause naming it, or (for a class that must be nameable while its
argument is only declared, as Cgal_kernel<CGAL::Epick>) its body opens with
`static_assert(Concept<K>, ...)`. Concept definitions and forward
declarations are skipped, and so is what is not public: the files under
internal/ and the blocks `namespace internal { ... }  // namespace internal`.

signs: the places in include/ and tools/ that compare a Certified_sign with
`==` or `!=` against a named sign. The rule (core/certified_sign.h): a test
says whether it means `certainly(s, v)` (the kernel decided v) or
`possibly(s, v)` (v, or the kernel does not know), and `is_certain(s)` tests
for `uncertain`; a bare `s != v` silently counts `uncertain` as "not v"."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
INCLUDE = ROOT / "include" / "relgeo"

# A template head up to its closing '>' (no nested template heads in ours:
# defaults like `= Filtered_exact_kernel` or `= void` are plain names).
HEAD = re.compile(r"template\s*<((?:[^<>]|<[^<>]*>)*)>", re.S)
PARAM = re.compile(r"^\s*(class|typename)\s+(\w+)\b")
KERNEL_NAME = re.compile(r"^(K|Kernel|\w*_kernel|\w*Kernel)$")

INTERNAL = re.compile(r"namespace internal \{.*?\}\s*// namespace internal", re.S)


def unconstrained(text):
    hidden = [(m.start(), m.end()) for m in INTERNAL.finditer(text)]
    for head in HEAD.finditer(text):
        if any(a <= head.start() < b for a, b in hidden):
            continue
        after = text[head.end():head.end() + 200].lstrip()
        if re.match(r"concept\b", after):
            continue
        if re.match(r"(class|struct)\s+\w+\s*;", after):  # a forward declaration: its definition is checked
            continue
        requires_clause = re.match(r"requires\b", after) is not None
        body = text[head.end():head.end() + 400]
        brace = body.find("{")
        asserted = brace >= 0 and re.match(r"\s*static_assert\((\w+)<(\w+)>", body[brace + 1:])
        for param in head.group(1).split(","):
            m = PARAM.match(param)
            if not m or not KERNEL_NAME.match(m.group(2)):
                continue
            if requires_clause and re.search(r"\b%s\b" % m.group(2), after.split("\n")[0]):
                continue
            if asserted and asserted.group(2) == m.group(2):
                continue
            line = text.count("\n", 0, head.start()) + 1
            yield line, " ".join(head.group(0).split())



def unconstrained_kernels():
    for path in sorted(INCLUDE.rglob("*.h")):
        if "internal" in path.relative_to(INCLUDE).parts:
            continue
        for line, decl in unconstrained(path.read_text()):
            yield f"{path.relative_to(ROOT)}:{line}: {decl}"


COMPARISON = re.compile(r"[!=]=\s*Certified_sign::\w+|Certified_sign::\w+\s*[!=]=")
SIGN_HOME = INCLUDE / "core" / "certified_sign.h"


def bare_sign_comparisons():
    for folder in ("include", "tools"):
        for path in sorted((ROOT / folder).rglob("*")):
            if path.suffix not in (".h", ".cpp") or path == SIGN_HOME:
                continue
            for n, line in enumerate(path.read_text().splitlines(), 1):
                if COMPARISON.search(line):
                    yield f"{path.relative_to(ROOT)}:{n}: {line.strip()}"


RULES = {"kernels": unconstrained_kernels, "signs": bare_sign_comparisons}


def main(names):
    unknown = [n for n in names if n not in RULES]
    if unknown:
        print(f"unknown rule {unknown[0]!r}; the rules: {', '.join(RULES)}", file=sys.stderr)
        return 2
    found = [place for name in names or RULES for place in RULES[name]()]
    for place in found:
        print(place)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
