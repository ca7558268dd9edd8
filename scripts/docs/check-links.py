#!/usr/bin/env python3
"""docs.links: every relative link and #anchor in README.md and docs/**/*.md resolves (GitHub's anchor rules).
Usage: check-links.py [repository root]"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
import markdown  # noqa: E402

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parents[2]).resolve()
pages = [root / "README.md", *sorted((root / "docs").rglob("*.md"))]
anchor_cache = {}


def anchors_of(page):
    if page not in anchor_cache:
        anchor_cache[page] = markdown.anchors(page.read_text())
    return anchor_cache[page]


broken, checked = [], 0
for page in pages:
    for number, target in markdown.links(page.read_text()):
        if "://" in target or target.startswith("mailto:"):
            continue
        checked += 1
        path, _, anchor = target.partition("#")
        file = (page.parent / path).resolve() if path else page
        where = f"{page.relative_to(root)}:{number}: {target}"
        if not file.exists():
            broken.append(f"{where}: no such file")
        elif not str(file).startswith(str(root)):
            broken.append(f"{where}: outside the repository")
        elif anchor and file.suffix == ".md" and anchor not in anchors_of(file):
            broken.append(f"{where}: no heading with the anchor #{anchor} in {file.relative_to(root)}")
        elif anchor and file.suffix != ".md":
            broken.append(f"{where}: an anchor into a file that is not Markdown")
print(f"check-links: {checked} relative links in {len(pages)} pages, {len(broken)} broken")
for line in broken:
    print(line)
sys.exit(1 if broken else 0)
