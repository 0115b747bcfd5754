#!/usr/bin/env python3
"""Checks the tree's structure: includes point down the layers and, inside
compute/raycast/, down its role rooms; every rule has its include guard and
its two lines in rules/instance.h; no source file outside tests/ is longer
than MAX_LINES and no function in one longer than MAX_FUNCTION_LINES
(long_function_violations); and no test's result hangs on the wall clock
(wall_clock_violations).

    python3 tools/check_structure.py [repo root]

Exits 0 with a one-line summary, or 1 after printing every violation.
Python 3 standard library only, so it runs wherever the build does.
"""

import argparse
import os
import re
import subprocess
import sys
from collections import defaultdict, deque

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from function_spans import brace_functions, python_functions  # noqa: E402  (beside this script)

# The layers, (folder, rank): a file may include files of its own layer or of
# a layer of strictly lower rank. This table IS the layering that
# docs/architecture.md ("Layers") draws; change both together. A folder that
# is split into sub-layers (engine/) owns only the files directly in it, so a
# new subfolder must be named here before it can be included.
LAYERS = [
    ("rules", 0),  # the rules both backends apply, in the GLSL/C++ subset
    ("include", 0),  # the public API headers, include/facet/
    ("materials", 1),
    ("engine/gpu", 1),
    ("engine/image", 1),
    ("engine/stages", 1),  # the stages a render reports, named for every reader
    ("scenes", 2),
    ("engine/camera", 3),
    ("engine/ibl", 3),
    # The two halves of the backends are peers: the CPU reference shares
    # nothing with the GPU's kernels and buffer layouts but rules/.
    ("engine/cpu", 4),
    ("compute", 4),  # GLSL kernels and GPU buffer layouts
    ("engine/gpu_backend", 5),
    ("engine", 6),  # engine/renderer.h, engine/smoke.h
    ("analysis", 7),
    ("api", 8),
    ("apps", 8),
    ("benchmarks", 8),
    ("fuzz", 8),
    ("python", 9),
    ("tools", 9),
]

# The role rooms of the ray caster, (room, rank), ranked like LAYERS inside
# the compute layer: a file of a room may include files of its own room or
# of a room of strictly lower rank, so a piece a second room needs lives in
# common/. A new room must be named here.
RAYCAST = "compute/raycast"
ROOMS = [
    ("common", 0),  # what more than one room uses
    ("dicing", 1),
    ("finish", 1),
    ("shading", 1),
    ("paths", 1),
    ("film", 1),
    ("traversal", 2),  # calls the finishes at each candidate cell
]

# A rule (rules/language.h states the convention) is guarded by
# FACET_RULE_<its path below rules/>, which rules/instance.h undefines after
# each real type: a rule whose #undef is missing would be left out of the
# next type without a word.
RULE_INSTANCE = "rules/instance.h"
NOT_RULES = ("rules/language.h", "rules/rules.h", RULE_INSTANCE)

MAX_LINES = 450
INCLUDING_SUFFIXES = (".h", ".cpp", ".glsl", ".comp")
COUNTED_SUFFIXES = INCLUDING_SUFFIXES + (".py",)

# Include roots other than the repository root: the public API is included as
# "facet/...", and the build generates the headers that embed SPIR-V
# (cmake/FacetShaders.cmake), which exist in no source folder.
PUBLIC_API = ("facet/", "include/facet/")
GENERATED_HEADER_LAYERS = {
    "facet_kernels/": "compute",
    "facet_raycast_kernels/": "compute",
    "facet_ibl_kernels/": "compute",
    "facet_materials_spirv/": "compute",
    "ceiling_kernels/": "benchmarks",
}

INCLUDE_PATTERN = re.compile(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"', re.MULTILINE)


def source_files(root):
    """The tracked files under root, as '/'-separated relative paths; where
    root is not the top of a git work tree, every file on disk but those in
    hidden and build folders."""
    if git_top_level(root) == os.path.realpath(root):
        listed = subprocess.run(["git", "ls-files", "-z"], cwd=root, capture_output=True, check=True).stdout
        paths = [p for p in listed.decode("utf-8", "replace").split("\0") if p]
    else:
        paths = []
        for folder, subfolders, files in os.walk(root):
            subfolders[:] = [s for s in subfolders if not s.startswith((".", "build"))]
            relative = os.path.relpath(folder, root).replace(os.sep, "/")
            paths += [f if relative == "." else f"{relative}/{f}" for f in files]
    # A tracked file deleted in the work tree is not part of the tree being checked.
    return sorted(p for p in paths if not p.startswith("tests/") and os.path.isfile(os.path.join(root, p)))


def git_top_level(root):
    try:
        found = subprocess.run(["git", "rev-parse", "--show-toplevel"], cwd=root, capture_output=True, text=True)
    except OSError:  # no git installed
        return None
    return os.path.realpath(found.stdout.strip()) if found.returncode == 0 else None


def layer_of(path, layers=LAYERS):
    """(layer, rank) of the longest layer folder holding path, or None. A
    layer with sub-layers keeps only its direct files (see LAYERS)."""
    folders = {folder for folder, _ in layers}
    for folder, rank in sorted(layers, key=lambda entry: -len(entry[0])):
        if not path.startswith(folder + "/"):
            continue
        rest = path[len(folder) + 1 :]
        split_further = any(other.startswith(folder + "/") for other in folders)
        if split_further and "/" in rest:
            return None
        return folder, rank
    return None


def room_of(path, rooms=ROOMS):
    """(room, rank) of a file inside RAYCAST, rank None for one in no room;
    None for a file outside RAYCAST."""
    if not path.startswith(RAYCAST + "/"):
        return None
    rest = path[len(RAYCAST) + 1 :]
    room = f"{RAYCAST}/{rest.split('/')[0]}" if "/" in rest else RAYCAST
    return room, {f"{RAYCAST}/{name}": rank for name, rank in rooms}.get(room)


def resolve_include(root, including_path, name):
    """The repository path (or, for a generated header, the layer) a quoted
    include names, the way the build's include paths find it."""
    folder = os.path.dirname(including_path)
    beside = os.path.normpath(os.path.join(folder, name)).replace(os.sep, "/")
    if "/" not in name:
        return beside, None
    for prefix, layer in GENERATED_HEADER_LAYERS.items():
        if name.startswith(prefix):
            return name, layer
    if os.path.isfile(os.path.join(root, name)):
        return name, None
    if os.path.isfile(os.path.join(root, beside)):
        return beside, None
    if name.startswith(PUBLIC_API[0]):
        return PUBLIC_API[1] + name[len(PUBLIC_API[0]) :], None
    return name, None


def rule_guard(path):
    return "FACET_RULE_" + re.sub(r"\W", "_", path[len("rules/") : -len(".h")]).upper()


def rule_violations(root, paths):
    rules = [p for p in paths if p.startswith("rules/") and p.endswith(".h") and p not in NOT_RULES]
    if not rules:
        return []
    instance = read_text(root, RULE_INSTANCE) if RULE_INSTANCE in paths else ""
    violations = []
    for path in rules:
        guard = rule_guard(path)
        text = read_text(root, path)
        opening = rf"(?:[ \t]*(?://[^\n]*)?\n)*#ifndef {guard}\n#define {guard}\n"  # after comments only
        if not re.match(opening, text) or not text.rstrip().endswith("#endif"):
            violations.append(f"{path}: not inside its guard #ifndef {guard} / #define {guard} / ... / #endif")
        if f'#include "{path}"' not in instance or not re.search(rf"^#undef {guard}$", instance, re.M):
            violations.append(f'{RULE_INSTANCE}: lacks #include "{path}" or, at its end, #undef {guard}')
    return violations


def read_text(root, path):
    with open(os.path.join(root, path), "rb") as source:
        return source.read().decode("utf-8", "replace")


def count_lines(data):
    return data.count(b"\n") + (1 if data and not data.endswith(b"\n") else 0)


def check(root, layers=LAYERS, max_lines=MAX_LINES, rooms=ROOMS):
    """Returns (violations, cycles, stats): violations are printable lines,
    cycles come from layer_cycles, the layers' first, then the rooms'."""
    ranks = dict(layers)
    violations = []
    edges = defaultdict(dict)  # layer -> {included layer: an example "path:line"}
    room_edges = defaultdict(dict)  # the same between the rooms of RAYCAST
    files = includes = 0
    paths = source_files(root)
    violations += rule_violations(root, paths)
    for path in paths:
        if not path.endswith(COUNTED_SUFFIXES):
            continue
        files += 1
        with open(os.path.join(root, path), "rb") as source:
            data = source.read()
        lines = count_lines(data)
        if lines > max_lines:
            violations.append(f"{path}: {lines} lines > {max_lines}")
        if not path.endswith(INCLUDING_SUFFIXES):
            continue
        own_room = room_of(path, rooms)
        if own_room is not None and own_room[1] is None:
            violations.append(f"{path}: in no room of {RAYCAST}: add its folder to ROOMS in tools/check_structure.py")
        own = layer_of(path, layers)
        if own is None:
            violations.append(f"{path}: in no layer: add its folder to LAYERS in tools/check_structure.py")
            continue
        text = data.decode("utf-8", "replace")
        for match in INCLUDE_PATTERN.finditer(text):
            includes += 1
            name = match.group(1)
            line = text.count("\n", 0, match.start(1)) + 1
            target, generated_layer = resolve_include(root, path, name)
            if generated_layer is not None:
                other = (generated_layer, ranks.get(generated_layer))
            else:
                other = layer_of(target, layers)
            where = f"{path}:{line}"
            other_room = room_of(target, rooms) if generated_layer is None else None
            if own_room and other_room and own_room[0] != other_room[0] and None not in (own_room[1], other_room[1]):
                room_edges[own_room[0]].setdefault(other_room[0], where)
                if other_room[1] >= own_room[1]:
                    violations.append(f'{where}: includes "{name}" (room {own_room[0]}, rank {own_room[1]}) -> '
                                      f"room {other_room[0]} (rank {other_room[1]}): includes must point down")
            if other is None or other[1] is None:
                violations.append(f'{where}: includes "{name}" (layer {own[0]}, rank {own[1]}) -> {target}, '
                                  "in no layer: add its folder to LAYERS in tools/check_structure.py")
                continue
            if other[0] == own[0]:
                continue
            edges[own[0]].setdefault(other[0], where)
            if other[1] >= own[1]:
                violations.append(f'{where}: includes "{name}" (layer {own[0]}, rank {own[1]}) -> '
                                  f"layer {other[0]} (rank {other[1]}): includes must point down")
    stats = {"files": files, "includes": includes, "layers": len(layers), "rooms": len(rooms)}
    return violations, layer_cycles(edges) + layer_cycles(room_edges), stats


def layer_cycles(edges):
    """One cycle through each group of layers that reach one another (Tarjan's
    strongly connected components), as steps (layer, included layer, "path:line")."""
    index, lowlink, stack, groups = {}, {}, [], []

    def visit(node):
        index[node] = lowlink[node] = len(index)
        stack.append(node)
        for successor in edges.get(node, {}):
            if successor not in index:
                visit(successor)
                lowlink[node] = min(lowlink[node], lowlink[successor])
            elif successor in stack:
                lowlink[node] = min(lowlink[node], index[successor])
        if lowlink[node] == index[node]:
            group = set()
            while node not in group:
                group.add(stack.pop())
            if len(group) > 1:
                groups.append(group)

    for node in sorted(edges):
        if node not in index:
            visit(node)
    cycles = []
    for group in sorted(groups, key=min):
        layers = shortest_cycle(min(group), group, edges)
        cycles.append([(a, b, edges[a][b]) for a, b in zip(layers, layers[1:])])
    return cycles


def shortest_cycle(start, group, edges):
    """[start, ..., start]: the shortest way back to start inside group (breadth first)."""
    came_from = {}
    queue = deque([start])
    while start not in came_from:
        node = queue.popleft()
        for successor in sorted(edges[node]):
            if successor in group and successor not in came_from:
                came_from[successor] = node
                queue.append(successor)
    path = [start, came_from[start]]
    while path[-1] != start:
        path.append(came_from[path[-1]])
    return list(reversed(path))


# A test's result must not depend on how busy the machine is
# (docs/reliability.md, "Tests and the wall clock"). An adaptive render's time
# limit in a test is at least a day, which no test comes near; a positive
# one below that is a violation (zero, negative and nan are refusal tests,
# which limit nothing).
UNREACHABLE_TIME_LIMIT = 86400
TIME_LIMIT_PATTERN = re.compile(r"(?:timeLimitSeconds\s*=|--time-limit[ \t=]|time_limit\s*=)[ \t]*([0-9][0-9.eE+-]*)")
# Reading the clock or waiting on it, in C++, Python and shell; a file that
# does is named in ALLOWED_CLOCK_READS with why its result cannot depend on it.
CLOCK_PATTERN = re.compile(r"\b(?:steady_clock|system_clock|high_resolution_clock|sleep_for|sleep_until)\b"
                           r"|\btime\.(?:time|monotonic|perf_counter|sleep)\(|\bdatetime\.now\b"
                           r"|\bSECONDS\b|\bdate \+%s|\btimeout [0-9$]|\bsleep [0-9$]")
ALLOWED_CLOCK_READS = {
    "tests/engine/cpu/transmission_render_test.cpp": "prints how long the paths took; asserts nothing on it",
    "tests/engine/cpu/intersect_exact_test.cpp": "prints the time per ray; asserts nothing on it",
    "tests/engine/gpu/gpu_timestamps_test.cpp": "the host's wait bounds the device's time from above, and load only "
                                                "lengthens the wait",
    "tests/apps/facet/check_watch.sh": "waits for events; one deadline far beyond a run on a busy machine catches "
                                       "a hung facet",
    "tests/tools/farm/slurm_end_to_end.sh": "waits for the daemons; deadlines far beyond a busy machine's catch a "
                                            "hang and stop the daemons",
}
# (path, the limit as written): why a busy machine cannot change the result.
ALLOWED_TIME_LIMITS = {
    ("tests/engine/adaptive_render_test.cpp", "1e-6"): "the time cap's own test: a limit every round passes, "
                                                       "however idle the machine",
}
# `facet preview` stops its rounds after 60 s unless told otherwise, so a test
# line that runs it names its --time-limit (TIME_LIMIT_PATTERN checks the value).
PREVIEW_PATTERN = re.compile(r'(?:"\$facet"|"?\$\{facet\}"?|\$facet|facet;)[ \t]*preview\b')
# (path, a piece of the line): why the line may run it with the 60 s.
ALLOWED_PREVIEWS = {
    ("tests/apps/facet/check_preview_stage.sh", '-o bad.png "$@"'): "the refusals, each refused before any render",
}
TEST_SUFFIXES = (".h", ".cpp", ".py", ".sh", ".cmake", "CMakeLists.txt")
# This check's own test holds the patterns as the data of its cases.
OWN_TEST = "tests/tools/structure_check_test.py"


def wall_clock_violations(root):
    """Printable lines: each time limit a test could reach and each clock read
    not in the allow-lists, and each allow-listed file that no longer needs
    its entry."""
    violations, limited, previewed, clocked = [], set(), set(), set()
    for folder, subfolders, files in os.walk(os.path.join(root, "tests")):
        subfolders[:] = sorted(s for s in subfolders if not s.startswith((".", "build", "__pycache__")))
        for name in sorted(f for f in files if f.endswith(TEST_SUFFIXES)):
            path = os.path.relpath(os.path.join(folder, name), root).replace(os.sep, "/")
            if path == OWN_TEST:
                continue
            with open(os.path.join(folder, name), encoding="utf-8", errors="replace") as source:
                text = source.read()
            for match in TIME_LIMIT_PATTERN.finditer(text):
                try:
                    seconds = float(match.group(1))
                except ValueError:
                    continue
                if not 0 < seconds < UNREACHABLE_TIME_LIMIT:
                    continue
                limited.add((path, match.group(1)))
                if (path, match.group(1)) not in ALLOWED_TIME_LIMITS:
                    line = text.count("\n", 0, match.start()) + 1
                    violations.append(f"{path}:{line}: a time limit of {match.group(1)} s: a busy machine can reach "
                                      f"it; use at least {UNREACHABLE_TIME_LIMIT} or count rounds")
            for match in PREVIEW_PATTERN.finditer(text):
                start = text.rfind("\n", 0, match.start()) + 1
                end = text.find("\n", match.end())
                line_text = text[start : end if end >= 0 else len(text)]
                if "--time-limit" in line_text:
                    continue
                allowed = [key for key in ALLOWED_PREVIEWS if key[0] == path and key[1] in line_text]
                previewed.update(allowed)
                if not allowed:
                    line = text.count("\n", 0, match.start()) + 1
                    violations.append(f"{path}:{line}: runs facet preview without --time-limit, so with its 60 s: "
                                      f"pass --time-limit {UNREACHABLE_TIME_LIMIT}")
            match = CLOCK_PATTERN.search(text)
            if match:
                clocked.add(path)
                if path not in ALLOWED_CLOCK_READS:
                    line = text.count("\n", 0, match.start()) + 1
                    violations.append(f'{path}:{line}: reads the wall clock ("{match.group(0)}"): a test\'s result '
                                      "must not depend on it; add the file to ALLOWED_CLOCK_READS only with why it "
                                      "cannot")
    for allowed, used, kind in ((ALLOWED_TIME_LIMITS, limited, "ALLOWED_TIME_LIMITS"),
                                (ALLOWED_PREVIEWS, previewed, "ALLOWED_PREVIEWS"),
                                (ALLOWED_CLOCK_READS, clocked, "ALLOWED_CLOCK_READS")):
        for entry in sorted(set(allowed) - used):
            path = entry if isinstance(entry, str) else entry[0]
            if os.path.isfile(os.path.join(root, path)):
                violations.append(f"{path}: {entry} is in {kind} but no longer needed there: remove it")
    return violations


# A function, from its signature's first line to its closing brace (C++,
# GLSL) or its last line (Python under tools/), has at most this many lines;
# a longer one is split into functions of one concept each.
MAX_FUNCTION_LINES = 100
BRACE_SUFFIXES = (".h", ".cpp", ".glsl", ".comp")


def long_function_violations(root, max_lines=MAX_FUNCTION_LINES):
    """Printable lines: each function outside tests/ longer than max_lines."""
    violations = []
    for path in source_files(root):
        if path.endswith(BRACE_SUFFIXES):
            functions = brace_functions(read_text(root, path))
        elif path.startswith("tools/") and path.endswith(".py"):
            functions = python_functions(read_text(root, path))
        else:
            continue
        for name, first, last in functions:
            if last - first + 1 > max_lines:
                violations.append(f"{path}:{first}: {name} is {last - first + 1} lines > {max_lines}: split it into "
                                  "functions of one concept each")
    return violations


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", nargs="?", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                        help="the repository root (default: the one holding this script)")
    root = parser.parse_args(argv).root
    violations, cycles, stats = check(root)
    violations += long_function_violations(root)
    violations += wall_clock_violations(root)
    counts = f"{stats['files']} files, {stats['includes']} includes, {stats['layers']} layers, {stats['rooms']} rooms"
    for violation in violations:
        print(violation)
    for cycle in cycles:
        kind = "room" if cycle[0][0].startswith(RAYCAST + "/") else "layer"
        print(f"{kind} cycle: " + " -> ".join([layer for layer, _, _ in cycle] + [cycle[0][0]]))
        for layer, included, where in cycle:
            print(f"    {layer} -> {included}: {where}")
    if violations or cycles:
        print(f"check_structure: {len(violations)} violations, {len(cycles)} cycles ({counts})")
        return 1
    print(f"check_structure: {counts}: includes point down, no file over {MAX_LINES} lines, no function over "
          f"{MAX_FUNCTION_LINES}, no test on the wall clock")
    return 0


if __name__ == "__main__":
    sys.exit(main())
