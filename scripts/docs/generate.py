#!/usr/bin/env python3
"""Regenerates the generated regions of the guide from what the code prints, or checks them (--check).

A region is delimited by `<!-- generated: penumbra ARGS -->` and `<!-- end generated -->`; its text is the output of
`penumbra ARGS`, run as `penumbra` (so usage lines do not carry the build folder's path): fenced as text, or as it is
when ARGS asks for --markdown. Usage: generate.py [--check] --penumbra build/bin/penumbra [page.md ...]
(default: every page of docs/ and README.md).
"""
import argparse
import difflib
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
REGION = re.compile(r"(<!-- generated: penumbra (?P<args>[^>]*?) -->\n)(?P<body>.*?)(<!-- end generated -->)", re.S)


def run(penumbra, args):
    result = subprocess.run(["penumbra", *args.split()], executable=penumbra, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"generate.py: penumbra {args} failed ({result.returncode}): {result.stderr.strip()}")
    text = result.stdout if result.stdout.endswith("\n") else result.stdout + "\n"
    return text if "--markdown" in args.split() else "```text\n" + text + "```\n"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--check", action="store_true", help="fail, with a diff, where a page differs")
    parser.add_argument("--penumbra", required=True, help="the built tool")
    parser.add_argument("pages", nargs="*", type=pathlib.Path)
    options = parser.parse_args()
    pages = options.pages or [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
    stale = []
    for page in pages:
        text = page.read_text()
        new = REGION.sub(lambda m: m.group(1) + run(options.penumbra, m.group("args")) + m.group(4), text)
        if new == text:
            continue
        if options.check:
            stale.append(page)
            sys.stdout.writelines(difflib.unified_diff(text.splitlines(True), new.splitlines(True), str(page), "generated"))
        else:
            page.write_text(new)
            print(f"generate.py: wrote {page.relative_to(ROOT)}")
    if stale:
        sys.exit("generate.py: out of date (run scripts/docs/generate.sh): " + ", ".join(str(p) for p in stale))


if __name__ == "__main__":
    main()
