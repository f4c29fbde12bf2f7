#!/usr/bin/env python3
"""Checks the walls between photon's layers (docs/architecture.md) from the #include lines.

Each source file belongs to a layer; each include is resolved to the file it names and so to
a layer too. The check fails, listing file:line, when
  - a layer includes a layer it must not (e.g. server/ including api/, anything outside the
    engine including an engine-internal header instead of its face, engine/include/photon);
  - a header of the engine's face includes anything but the face and the standard library;
  - a third-party library's headers appear outside the layers that own it (Embree, oneTBB,
    OpenImageIO, Assimp inside the engine; httplib in the HTTP layer; SQLite in the server);
  - the engine's folders include each other in a circle (integrators/<family> count as
    folders of their own).
Run from anywhere: python3 scripts/check_walls.py
"""
import os
import re
import sys
from collections import defaultdict

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SOURCE_SUFFIXES = (".h", ".hpp", ".cpp", ".cc")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')

# What each layer may include (besides itself and the standard library).
ALLOWED = {
    "engine-face": set(),
    "engine": {"engine-face"},
    "server": {"engine-face"},
    "api": {"server", "engine-face"},
    "app": {"api", "server", "cli", "engine-face"},
    "cli": {"engine-face"},
    # White-box tests and measurements of the engine may see its insides.
    "engine-tests": {"engine", "engine-face", "test-support", "cli"},
    "test-support": {"engine", "engine-face"},
    # The service's tests use the service and the engine's face, as the server does.
    "service-tests": {"server", "api", "engine-face"},
    "fuzz": {"engine", "engine-face", "api", "server", "test-support"},
}
# Third-party headers (by the include's first path part or name) and the layers that may
# include them.
LIBRARIES = {
    "embree3": {"engine", "engine-tests"},
    "tbb": {"engine", "engine-tests", "test-support"},
    "oneapi": {"engine", "engine-tests"},
    "OpenImageIO": {"engine", "engine-tests", "test-support"},
    "assimp": {"engine", "engine-tests", "fuzz"},
    "tiny_obj_loader.h": {"engine"},
    "nanoflann.hpp": {"engine", "engine-tests"},
    "nanovdb": {"engine", "engine-tests"},
    "zlib.h": {"engine", "engine-tests", "test-support"},
    "httplib.h": {"api", "service-tests", "fuzz"},
    "sqlite3.h": {"server", "service-tests"},
    "hiredis": {"server"},
    "CLI": {"cli", "app", "engine-tests", "service-tests"},  # photon-bench, photon-farm-bench
}


def layer_of(rel):
    parts = rel.split("/")
    if parts[0] == "engine":
        return "engine-face" if parts[1] == "include" else "engine"
    if parts[0] in ("server", "api", "app", "cli"):
        return parts[0]
    if parts[0] == "tests":
        if parts[1] == "server":
            return "service-tests"
        if parts[1] == "fuzz":
            return "fuzz"
        if parts[1] == "support":
            return "test-support"
        return "engine-tests"
    return None


def engine_folder(rel):
    """The engine folder a file counts in for the circle check: engine/<folder>, or
    engine/integrators/<family> for the integrator families."""
    parts = rel.split("/")[1:]
    if len(parts) == 1:
        return "(root)"
    if parts[0] == "integrators" and len(parts) > 2:
        return "integrators/" + parts[1]
    return parts[0]


# Where a quoted include is looked for after the including file's own folder: the engine's
# private root, the face, the folders linked in as "folder/x.h", and the tests' support.
SEARCH = ["engine", "engine/include", ".", "tests/support", "tests/server", "tests/bench", "tests/fuzz"]


def resolve(including_rel, kind, name):
    candidates = []
    if kind == '"':
        candidates.append(os.path.join(os.path.dirname(including_rel), name))
    candidates += [os.path.join(base, name) for base in SEARCH]
    if kind == "<" and name.startswith("photon/"):
        candidates = [os.path.join("engine/include", name)]
    for c in candidates:
        c = os.path.normpath(c)
        if os.path.isfile(os.path.join(ROOT, c)):
            return c
    return None


def source_files():
    for top in ("engine", "server", "api", "app", "cli", "tests"):
        for folder, dirs, files in os.walk(os.path.join(ROOT, top)):
            dirs[:] = [d for d in dirs if d not in ("node_modules", "corpus")]
            for f in files:
                if f.endswith(SOURCE_SUFFIXES):
                    yield os.path.relpath(os.path.join(folder, f), ROOT)


def main():
    problems = []
    folder_edges = defaultdict(dict)  # engine folder -> {folder it includes: an example line}
    for rel in sorted(source_files()):
        layer = layer_of(rel)
        with open(os.path.join(ROOT, rel), encoding="utf-8", errors="replace") as f:
            lines = f.readlines()
        for number, line in enumerate(lines, 1):
            m = INCLUDE.match(line)
            if not m:
                continue
            kind, name = m.groups()
            where = f"{rel}:{number}: #include {line.split('include', 1)[1].strip()}"
            target = resolve(rel, kind, name)
            if target is None:
                library = name.split("/")[0]
                if kind == '"':
                    problems.append(f"{where}: names no file of the project")
                elif library in LIBRARIES and layer not in LIBRARIES[library]:
                    problems.append(f"{where}: {library} belongs to {', '.join(sorted(LIBRARIES[library]))}")
                elif layer == "engine-face" and ("/" in name or "." in name):
                    problems.append(f"{where}: the engine's face includes only the face and the standard library")
                continue
            target_layer = layer_of(target)
            if target_layer != layer and target_layer not in ALLOWED.get(layer, set()):
                problems.append(f"{where}: {layer} must not include {target_layer} ({target})")
            if layer == "engine" and target_layer == "engine":
                a, b = engine_folder(rel), engine_folder(target)
                if a != b:
                    folder_edges[a].setdefault(b, where)
    problems += circles(folder_edges)
    for p in problems:
        print(p)
    if problems:
        print(f"check_walls: {len(problems)} problem(s)")
        return 1
    print("check_walls: the walls hold (layers, the engine's face, libraries, no folder circles)")
    return 0


def circles(edges):
    """One line per circle among the engine's folders, with an include on it."""
    found, state, stack = [], {}, []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in sorted(edges.get(node, {})):
            if state.get(nxt) == "open":
                loop = stack[stack.index(nxt):] + [nxt]
                found.append("engine folders in a circle: " + " -> ".join(loop) + f" (e.g. {edges[node][nxt]})")
            elif nxt not in state:
                visit(nxt)
        stack.pop()
        state[node] = "done"

    for node in sorted(edges):
        if node not in state:
            visit(node)
    return found


if __name__ == "__main__":
    sys.exit(main())
