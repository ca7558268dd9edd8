#!/usr/bin/env python3
"""Fails where a library shader writes a uniform or storage block body by hand.

Every block the library's shaders read is declared once in C++ (a struct and its ShaderStruct, shaders/include/
penumbra/shaders/ShaderBlock.hpp) and generated into the shader as an include, so the C++ struct, the GLSL and the
layout that reflection checks cannot drift apart. This check looks for `uniform Name {` and `buffer Name {` in the
GLSL files of shaders/ (comments left out) and in the string literals of the libraries' and tools' C++ sources, and
names each one found. The examples and tests are users of the RHI and write their GLSL as users do; the Vulkan
backend's draw-count shader stays hand-written, as a backend knows nothing of the shaders library (ALLOWED).

Usage: check-shader-blocks.py [repository root]   (exit status 1 and one line per hand-written block)
       check-shader-blocks.py --self-test          (exit status 0 where a hand-written block is caught)
"""
import pathlib
import re
import sys
import tempfile

LIBRARY_ROOTS = ["rhi", "backends", "shadows", "scene", "scenes", "gltf", "truth", "render", "apps", "imageio",
                 "parity", "settings", "shaders"]
GLSL_SUFFIXES = {".vert", ".frag", ".comp", ".glsl"}
CPP_SUFFIXES = {".cpp", ".hpp"}
ALLOWED = {"backends/vulkan/src/VulkanDrawCount.cpp"}
BLOCK = re.compile(r"\b(uniform|buffer)\s+([A-Za-z_]\w*)\s*\{(?![{}])")  # not a format string's "{}"
RAW_STRING = re.compile(r'R"(\w*)\((.*?)\)\1"', re.S)
STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"')
COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)


def glsl_texts(path, text):
    """The parts of a file that are GLSL: a shader file without its comments, or a C++ file's string literals."""
    if path.suffix in GLSL_SUFFIXES:
        return [COMMENT.sub("", text)]
    raw = [m.group(2) for m in RAW_STRING.finditer(text)]
    rest = RAW_STRING.sub('""', text)
    return raw + [m.group(0) for m in STRING.finditer(COMMENT.sub("", rest))]


def hand_written_blocks(root):
    found = []
    for top in LIBRARY_ROOTS:
        for path in sorted((root / top).rglob("*")):
            if path.suffix not in GLSL_SUFFIXES | CPP_SUFFIXES or not path.is_file():
                continue
            name = path.relative_to(root).as_posix()
            if name in ALLOWED:
                continue
            for text in glsl_texts(path, path.read_text(encoding="utf-8")):
                for match in BLOCK.finditer(text):
                    found.append(f"{name}: the {match.group(1)} block {match.group(2)} is written by hand; declare "
                                 "it in C++ (penumbra/shaders/ShaderBlock.hpp) and generate it")
    return found


def self_test():
    """The check finds a block written in a shader file and in a C++ string, and passes generated ones."""
    with tempfile.TemporaryDirectory() as folder:
        root = pathlib.Path(folder)
        (root / "shaders").mkdir()
        (root / "render").mkdir()
        (root / "shaders" / "bad.comp").write_text(
            "#version 450\n// uniform Commented { is no block }\nlayout(std430, binding = 0) buffer Bins\n"
            "{\n    uint bins[];\n} bins;\n")
        (root / "shaders" / "good.vert").write_text('#version 450\n#include "good_blocks.glsl"\n')
        (root / "render" / "Bad.cpp").write_text(
            'const char* glsl = R"(layout(std140, binding = 0) uniform Frame { mat4 m; } frame;)";\n')
        (root / "render" / "Good.cpp").write_text(
            '// `uniform Frame { ... }` in a comment\nauto text = fmt::format("uniform {} {{\\n", name);\n'
            'auto error = fmt::format("vertex buffer slot {} is empty", slot);\n')
        found = hand_written_blocks(root)
        expected = ["render/Bad.cpp: the uniform block Frame", "shaders/bad.comp: the buffer block Bins"]
        if [f.split(" is written")[0] for f in found] != expected:
            print(f"check-shader-blocks self-test: expected {expected}, found {found}", file=sys.stderr)
            return 1
    return 0


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
    found = hand_written_blocks(root)
    for line in found:
        print(line, file=sys.stderr)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
