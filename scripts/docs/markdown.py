"""What the docs scripts read from the guide's Markdown: fenced blocks with their info strings, headings as GitHub
anchors them, and relative links. Code fences are skipped for headings and links."""
import re

FENCE = re.compile(r"^(```+|~~~+)(.*)$")


def blocks(text):
    """Every fenced block as (info words, attributes {key: value}, body)."""
    found, lines, i = [], text.split("\n"), 0
    while i < len(lines):
        m = FENCE.match(lines[i].strip())
        if not m:
            i += 1
            continue
        fence, info = m.group(1), m.group(2).split()
        body, i = [], i + 1
        while i < len(lines) and not lines[i].strip().startswith(fence):
            body.append(lines[i])
            i += 1
        i += 1
        words = [w for w in info if "=" not in w]
        attributes = dict(w.split("=", 1) for w in info if "=" in w)
        found.append((words, attributes, "\n".join(body) + "\n"))
    return found


def prose_lines(text):
    """The lines outside fenced blocks, with their 1-based numbers."""
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        m = FENCE.match(line.strip())
        if fence is None and m:
            fence = m.group(1)
        elif fence is not None and line.strip().startswith(fence):
            fence = None
        elif fence is None:
            yield number, line


def slug(heading):
    """GitHub's anchor for a heading: its text (links and code marks dropped) lower-cased, punctuation other than
    hyphens and underscores removed, spaces made hyphens."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)
    text = text.replace("`", "").strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(text):
    """Every heading's anchor, duplicates numbered -1, -2, ... as GitHub numbers them."""
    seen, result = {}, set()
    for _, line in prose_lines(text):
        m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        base = slug(m.group(1))
        count = seen.get(base, 0)
        seen[base] = count + 1
        result.add(base if count == 0 else f"{base}-{count}")
    return result


LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")


def links(text):
    """Every link target outside code, as (line number, target)."""
    for number, line in prose_lines(text):
        line = re.sub(r"`[^`]*`", "", line)
        for m in LINK.finditer(line):
            yield number, m.group(1)
