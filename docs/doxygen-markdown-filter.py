#!/usr/bin/env python3
"""Doxygen input filter for README.md and the guide's pages. Doxygen 1.9.4 makes no ids of its own for Markdown
headings and its labels are global, so every heading below a page's title gets the label <page>-<GitHub's anchor>
(page: the file's path without .md, slashes made hyphens: docs-rhi), and every link to an anchor, on the same page
(#anchor) or another (rhi.md#anchor), is pointed at that label. On GitHub the pages read as written."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "scripts" / "docs"))
import markdown  # noqa: E402


def page_label(path):
    return str(path.resolve().relative_to(ROOT).with_suffix("")).replace("/", "-").lower()


page = pathlib.Path(sys.argv[1])
text = page.read_text()
own = page_label(page)
prose = dict(markdown.prose_lines(text))
seen = {}


def relink(m):
    target = m.group(2)
    path, _, anchor = target.partition("#")
    if not anchor or "://" in target:
        return m.group(0)
    label = own if not path else page_label(page.parent / path)
    return f"{m.group(1)}(#{label}-{anchor})"


out = []
for number, line in enumerate(text.split("\n"), 1):
    if number in prose:
        if re.match(r"^#{2,6}\s", line):
            base = markdown.slug(re.sub(r"^#+\s+", "", line))
            count = seen.get(base, 0)
            seen[base] = count + 1
            line = f"{line} {{#{own}-{base if count == 0 else f'{base}-{count}'}}}"
        line = re.sub(r"(!?\[(?:[^\[\]]|\[[^\]]*\])*\])\(([^)\s]+)\)", relink, line)
    out.append(line)
sys.stdout.write("\n".join(out))
