#!/usr/bin/env python3
"""Lists the public templates of include/relgeo that take a kernel parameter
without a concept (issue 29: every public algorithm states the kernel
concept it needs). A kernel parameter is a template parameter named K or
Kernel, or ending in _kernel/Kernel; it is constrained when it is declared
with a concept (`template <IntersectionKernel_3 K>`) or the template has a
requires-clause naming it, or (for a class that must be nameable while its
argument is only declared, as Cgal_kernel<CGAL::Epick>) its body opens with
`static_assert(Concept<K>, ...)`. Concept definitions themselves are skipped, and
so is what is not public: the files under internal/ and the blocks
`namespace internal { ... }  // namespace internal`.

Prints one line per unconstrained parameter (file:line: declaration) and
exits 1 when there is any, 0 (printing nothing) otherwise."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent / "include" / "relgeo"
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


def main():
    found = []
    for path in sorted(ROOT.rglob("*.h")):
        if "internal" in path.relative_to(ROOT).parts:
            continue
        text = path.read_text()
        for line, decl in unconstrained(text):
            found.append(f"{path.relative_to(ROOT.parent.parent)}:{line}: {decl}")
    for f in found:
        print(f)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
