#!/usr/bin/env python3
"""Fails when an include in src/ points the wrong way between the layers (docs/architecture.md).

CMake's target links already refuse most upward dependencies (a library links only the layers below
it), but a header-only piece of a higher layer would still compile in: this reads the includes
themselves. Each layer is a folder under src/; a file may include its own layer and those the table
allows. The core (src/rgb) includes no outside geometry library.

Usage: layer_check.py SRC_DIR        (prints each violation as FILE:LINE; exit 1 if there are any)
"""
import re
import sys
from pathlib import Path

# Layer folder -> the layers it may include (besides itself). The core first, bottom up.
CORE = ["rgb/support", "rgb/rules", "rgb/mesh", "rgb/values", "rgb/lod"]
ALLOWED = {layer: CORE[:i] for i, layer in enumerate(CORE)}
ALLOWED.update({
    "io": CORE,
    "render": CORE,
    "detail": CORE,
    "app": CORE + ["io", "render", "detail"],
    "cli": CORE + ["io", "render", "detail", "app"],
})
# Third-party geometry libraries the core must not use (README: the core knows no outside library).
FORBIDDEN_IN_CORE = re.compile(r"#include\s*<(OpenMesh|CGAL|Eigen|embree\d*|meshoptimizer|assimp|opensubdiv|GL|GLFW|imgui)\b")
IO_FOLDERS: list[str] = []
INCLUDE = re.compile(r'#include\s*"([^"]+)"')


def layer_of(path: str) -> str | None:
    """The longest layer folder that path (relative to src/) lies in."""
    best = None
    for layer in ALLOWED:
        if (path == layer or path.startswith(layer + "/")) and (best is None or len(layer) > len(best)):
            best = layer
    return best


def add_io_sublayers(src: Path) -> None:
    """io's folders, bottom up, as src/io/layers.txt lists them (one folder and its allowed folders a line)."""
    table = src / "io" / "layers.txt"
    if not table.exists():
        return
    def folder(name: str) -> str:
        return "io" if name == "." else "io/" + name

    for line in table.read_text().splitlines():
        words = line.split("#", 1)[0].split()
        if words:
            ALLOWED[folder(words[0])] = CORE + [folder(b) for b in words[1:]]
            if words[0] != ".":
                IO_FOLDERS.append(words[0])


def main() -> int:
    src = Path(sys.argv[1])
    add_io_sublayers(src)
    violations = []
    for file in sorted(src.rglob("*")):
        if file.suffix not in (".h", ".cpp"):
            continue
        rel = file.relative_to(src).as_posix()
        layer = layer_of(rel)
        if layer is None:
            violations.append(f"{file}: in no layer of the table")
            continue
        for number, text in enumerate(file.read_text(encoding="utf-8").splitlines(), 1):
            if layer.startswith("rgb") and FORBIDDEN_IN_CORE.search(text):
                violations.append(f"{file}:{number}: the core includes an outside library: {text.strip()}")
            match = INCLUDE.search(text)
            if not match or "/" not in match.group(1):
                continue
            target = layer_of(match.group(1))
            if target is None or target == layer:
                continue
            # A layer above io may use every folder of it.
            allowed = ALLOWED[layer] + (["io/" + f for f in IO_FOLDERS] if "io" in ALLOWED[layer] else [])
            if target not in allowed:
                violations.append(f"{file}:{number}: {layer} may not include {target}: {text.strip()}")
    for v in violations:
        print(v)
    print(f"layer check: {len(violations)} violation(s)")
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
