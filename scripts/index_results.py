#!/usr/bin/env python3
"""Writes results/README.md: one line per result table (its first heading) and figure."""
import pathlib
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
lines = ["# Results", "",
         "Written by `scripts/index_results.py` (run by `scripts/regenerate.sh`); every file here",
         "is written by a program named in its first lines. Do not edit by hand.", "",
         "Timing files: a file whose name without extension ends in `_timing`, contains `_bench`, or",
         "starts with `p002_appendix_a` holds wall/CPU times (its description names the CPU, compiler",
         "and build flags) and changes on every run. Every other file must regenerate byte-identically;",
         "`scripts/check_reproducible.sh` (ctest label `reproducible`) checks a subset.", "",
         "## Tables", ""]
for md in sorted(root.glob("*.md")):
    if md.name == "README.md":
        continue
    title = next((l[2:].strip() for l in md.read_text().splitlines() if l.startswith("# ")), md.stem)
    csv = md.with_suffix(".csv")
    extra = f" ([csv]({csv.name}))" if csv.exists() else ""
    lines.append(f"- [{title}]({md.name}){extra}")
figs = sorted((root / "figures").glob("*.png")) if (root / "figures").exists() else []
if figs:
    lines += ["", "## Figures", ""]
    lines += [f"- [{f.stem}](figures/{f.name})" for f in figs]
(root / "README.md").write_text("\n".join(lines) + "\n")
