#!/usr/bin/env python3
"""Fails when a file-local name could change meaning in a unity build.

The libraries, tools and tests compile their .cpp files in batches (CMake's UNITY_BUILD, CMakeLists.txt): the anonymous
namespaces of a batch's files become one, so a name two files define there is a redefinition, or worse an overload
that silently wins, and a file-local name hides a namespace-scope one of the same target from the files after it (a
file-local kFloat array once hid the glTF schema's kFloat constant, and every FLOAT accessor was refused). Which
files share a batch changes as files are added, so the rule is kept for every pair of files of a target: a name
declared at namespace scope inside `namespace {` is declared nowhere else at namespace scope in the target's sources
and headers (a target: the .cpp and .hpp files under the nearest folder with a CMakeLists.txt; in tests/, a folder
under tests/ with tests/support's headers). A using-directive at file scope is refused in a .cpp file for the same
reason.

Usage: check-unity-names.py [repository root]   (exit status 1 and one line per clash)
"""
import collections
import pathlib
import re
import sys

ROOTS = ["rhi", "backends", "shadows", "scene", "scenes", "gltf", "truth", "render", "apps", "imageio", "parity",
         "settings", "shaders", "tests"]
DECLARATION = re.compile(r"^(?:template\s*<[^>]*>\s*)?(?:(?:static|inline|constexpr|const|extern)\s+)*"
                         r"(?:[\w:<>,\s\*&]+?\s+)?[\*&]?(\w+)\s*(?:\(|=|\{|;|\[)")
TYPE = re.compile(r"^(?:struct|class|enum class|enum|union)\s+(\w+)|^using\s+(\w+)\s*=")
MACRO = re.compile(r"^[A-Z][A-Z0-9_]*$")  # TEST_F(...), INSTANTIATE_TEST_SUITE_P(...): macro calls, not names
NOT_NAMES = {"if", "for", "while", "return", "switch", "namespace", "template", "operator", "sizeof", "static_assert",
             "main"}


def namespace_scope_names(text):
    """(file-local names, other namespace-scope names) declared at column 0, raw string literals left out."""
    text = re.sub(r'R"(\w*)\(.*?\)\1"', '""', text, flags=re.S)
    local, named = set(), set()
    in_anonymous = False
    for line in text.split("\n"):
        if re.match(r"^namespace\s*\{", line):
            in_anonymous = True
            continue
        if in_anonymous and re.match(r"^\}\s*//\s*namespace\s*$", line):
            in_anonymous = False
            continue
        if not line or line[0].isspace() or line.startswith(("//", "#", "}", "{", "namespace", "extern \"C\"")):
            continue
        match = TYPE.match(line) or DECLARATION.match(line)
        name = match and (match.group(1) or match.group(match.lastindex))
        if name and name not in NOT_NAMES and not MACRO.match(name):
            (local if in_anonymous else named).add(name)
    return local, named


def target_of(path, root):
    tests = root / "tests"
    if tests in path.parents:
        # One folder of tests/ builds one or a few executables; tests/support's headers go with every one of them.
        return tests / path.relative_to(tests).parts[0]
    folder = path.parent
    while folder != root and not (folder / "CMakeLists.txt").exists():
        folder = folder.parent
    return folder


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    targets = collections.defaultdict(list)
    for top in ROOTS:
        for path in sorted((root / top).rglob("*")):
            if path.suffix in (".cpp", ".hpp"):
                targets[target_of(path, root)].append(path)
    support = [path for path in targets.get(root / "tests" / "support", []) if path.suffix == ".hpp"]
    for folder, files in targets.items():
        if root / "tests" in folder.parents and folder.name != "support":
            files.extend(support)
    clashes = []
    for files in targets.values():
        for path in files:
            if path.suffix == ".cpp" and re.search(r"^using namespace", path.read_text(), flags=re.M):
                clashes.append(f"{path.relative_to(root)}: a using-directive at file scope reaches the files after it "
                               f"in a unity batch")
        declared = {path: namespace_scope_names(path.read_text()) for path in files}
        for path, (local, _) in declared.items():
            for name in sorted(local):
                for other, (other_local, other_named) in declared.items():
                    if other != path and (name in other_named or (name in other_local and str(path) < str(other))):
                        clashes.append(f"{path.relative_to(root)}: file-local '{name}' is also declared in "
                                       f"{other.relative_to(root)}; a unity batch holding both changes its meaning")
    for clash in clashes:
        print(clash)
    return 1 if clashes else 0


if __name__ == "__main__":
    sys.exit(main())
