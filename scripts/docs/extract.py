#!/usr/bin/env python3
"""Writes the guide's tested blocks into a folder.
  extract.py snippets <source> <out>: every ```cpp example block without a file= as snippet-N.cpp, and a
      CMakeLists.txt compiling them all against find_package(Penumbra) as one object library;
  extract.py steps <source> <out>: docs/getting-started.md's blocks with a file= into <out>/<file>, and its
      ```sh getting-started blocks, in order, into <out>/getting-started.sh."""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).parent))
import markdown  # noqa: E402

mode, source, out = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
if mode == "snippets":
    names = []
    for page in [source / "README.md", *sorted((source / "docs").rglob("*.md"))]:
        for words, attributes, body in markdown.blocks(page.read_text()):
            if words[:2] == ["cpp", "example"] and "file" not in attributes:
                name = f"snippet-{len(names)}.cpp"
                (out / name).write_text(f"// {page.relative_to(source)}\n" + body)
                names.append(name)
    if not names:
        sys.exit("extract.py: no ```cpp example blocks found")
    (out / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.25)\nproject(PenumbraDocSnippets LANGUAGES CXX)\n"
        "set(CMAKE_CXX_STANDARD 20)\nset(CMAKE_CXX_STANDARD_REQUIRED ON)\n"
        "find_package(Penumbra 0.1 REQUIRED)\n"
        f"add_library(doc_snippets OBJECT {' '.join(names)})\n"
        "target_link_libraries(doc_snippets PRIVATE penumbra::backends penumbra::render penumbra::parity penumbra::imageio penumbra::gltf penumbra::scenes penumbra::truth)\n")
    print(f"extract.py: {len(names)} snippets")
elif mode == "steps":
    steps = []
    for words, attributes, body in markdown.blocks((source / "docs" / "getting-started.md").read_text()):
        if "file" in attributes:
            path = out / attributes["file"]
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(body)
        if words[:2] == ["sh", "getting-started"]:
            steps.append(body)
    if not steps:
        sys.exit("extract.py: no ```sh getting-started block in docs/getting-started.md")
    (out / "getting-started.sh").write_text("".join(steps))
else:
    sys.exit(f"extract.py: unknown mode {mode}")
