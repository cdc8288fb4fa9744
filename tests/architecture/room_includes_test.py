#!/usr/bin/env python3
"""A room includes only from the rooms its target links: the link lines are the only directions.

The targets and their links are read from lab/**/CMakeLists.txt: `lab_library(NAME files...)`,
`add_executable(NAME files...)` and `add_library(NAME INTERFACE)` define a target, with the files
listed relative to their CMakeLists.txt (`target_sources` adds more); `target_link_libraries(NAME
PUBLIC|PRIVATE|INTERFACE a b c)` adds links to the latest definition of NAME in that file, so the
branches of lab/platform's `if(LAB_PLATFORM ...)` each keep their own link line. Only links to
targets defined under lab/ count (lab_imgui and lab_warnings, defined at the top, are libraries,
not rooms). Files are mapped to targets one by one, not by folder: lab/ui's folder holds two
targets, lab_ui_kit and lab_ui.

A header belongs to the target that lists its .cpp (same folder, same name); a header without a
.cpp belongs to its folder's target, or, in a folder with several targets, to the one FOLDER_TARGET
below names. A file in shaders/ belongs to the target that puts shaders/ on its include path
(lab_lighting). An include is resolved as the compiler does: beside the including file first, then
from lab/, then from shaders/; one that resolves to none (a generated header such as
render/shader_sources.h, a system header) is not checked.

Every `#include "..."` in a file of target T must name a file of T itself or of a target T links,
directly or through other targets. A .cpp compiled into several definitions of the same name (the
platform's branches) must keep to each one's links. The links between targets must not form a
cycle.

    room_includes_test.py <repository root>
"""
import pathlib
import re
import sys

# Folders with several targets: the target that owns their headers without a .cpp.
FOLDER_TARGET = {
    'lab/ui': 'lab_ui_kit',        # widget_map.h: the kit, which every ui room links
    'lab/platform': 'lab_platform',  # window.h: the seam lab_platform implements
    'lab/cli': 'lab_cli',          # command_kit.h: what the commands share
    'lab/core/gltf': 'lab_gltf',   # draco_decoder.h: the seam draco_linked.cpp and draco_fetched.cpp implement
    'lab/core/share': 'lab_share', # qr_encoder.h: the seam qr_linked.cpp and qr_fetched.cpp implement
}
SOURCES = ('.h', '.cpp')

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.').resolve()
lab = root / 'lab'
shaders = root / 'shaders'
problems = []


def rel(path):
    return path.relative_to(root).as_posix()


def cmake_commands(text):
    """(command, [arguments]) of each command call in a CMakeLists.txt, comments left out."""
    text = re.sub(r'#[^\n]*', '', text)  # no '#' in this tree's quoted arguments
    for m in re.finditer(r'\b(\w+)\s*\(([^()]*)\)', text):
        yield m.group(1).lower(), re.findall(r'"[^"]*"|[^\s"]+', m.group(2))


class Definition:
    def __init__(self, name, folder):
        self.name, self.folder, self.files, self.links = name, folder, [], []


definitions = []        # every definition, in the order the files are read
shader_owner = None     # the target that puts shaders/ on its include path
for cmake in sorted(lab.rglob('CMakeLists.txt')):
    folder = cmake.parent
    latest = {}
    for command, args in cmake_commands(cmake.read_text(encoding='utf-8')):
        if not args:
            continue
        name, rest = args[0], args[1:]
        if command in ('lab_library', 'add_executable', 'add_library'):
            d = Definition(name, folder)
            definitions.append(d)
            latest[name] = d
            command = 'target_sources'
        if name not in latest:
            continue  # a command on a target this file did not define (none in this tree)
        d = latest[name]
        if command == 'target_sources':
            d.files += [(folder / a).resolve() for a in rest if a.endswith(SOURCES)]
        elif command == 'target_link_libraries':
            d.links += [a for a in rest if a not in ('PUBLIC', 'PRIVATE', 'INTERFACE')]
        elif command == 'target_include_directories':
            if any(a.strip('"').endswith('/shaders') for a in rest):
                shader_owner = name

names = {d.name for d in definitions}
for d in definitions:
    d.links = [a for a in d.links if a in names]
links = {n: set() for n in names}  # a target's links over all its definitions
for d in definitions:
    links[d.name].update(d.links)


def reach(start):
    """The targets reachable from `start` (a set of names) through the links."""
    seen, todo = set(), list(start)
    while todo:
        n = todo.pop()
        if n not in seen:
            seen.add(n)
            todo += links.get(n, ())
    return seen


# --- which target each file belongs to --------------------------------------------------------
cpp_definitions = {}  # a .cpp: the definitions that compile it
for d in definitions:
    for f in d.files:
        cpp_definitions.setdefault(f, []).append(d)
folder_targets = {}
for d in definitions:
    folder_targets.setdefault(rel(d.folder), [])
    if d.name not in folder_targets[rel(d.folder)]:
        folder_targets[rel(d.folder)].append(d.name)


owners = {}


def owner(path):
    """The target a file belongs to, or None (with a problem, once) when it cannot be told."""
    if path not in owners:
        owners[path] = find_owner(path)
    return owners[path]


def find_owner(path):
    if path.parent == shaders:
        return shader_owner
    cpp = path.with_suffix('.cpp')
    if cpp in cpp_definitions:
        return cpp_definitions[cpp][0].name
    folder = rel(path.parent)
    candidates = folder_targets.get(folder, [])
    if len(candidates) == 1:
        return candidates[0]
    if folder in FOLDER_TARGET:
        return FOLDER_TARGET[folder]
    problems.append(f'{rel(path)}: has no .cpp and {folder}/ has {len(candidates)} targets '
                    f'({", ".join(candidates) or "none"}): name its owner in FOLDER_TARGET')
    return None


def resolve(including, name):
    for base in (including.parent, lab, shaders):
        candidate = (base / name).resolve()
        if candidate.is_file():
            return candidate
    return None


# --- every include against the link lines -----------------------------------------------------
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
files = sorted(p for p in lab.rglob('*') if p.suffix in SOURCES)
checked = 0
for path in files:
    path = path.resolve()
    if path.suffix == '.cpp':
        if path not in cpp_definitions:
            problems.append(f'{rel(path)}: no target in lab/**/CMakeLists.txt lists it')
            continue
        # Each definition that compiles it, with its own link line (past it, any definition's).
        scopes = [(d.name, {d.name} | reach(set(d.links))) for d in cpp_definitions[path]]
    else:
        t = owner(path)
        if t is None:
            continue
        scopes = [(t, reach({t}))]
    for number, line in enumerate(path.read_text(encoding='utf-8').splitlines(), 1):
        m = INCLUDE.match(line)
        if not m:
            continue
        target_path = resolve(path, m.group(1))
        if target_path is None:
            continue
        a = owner(target_path)
        if a is None:
            continue
        checked += 1
        for t, allowed in scopes:
            if a not in allowed:
                problems.append(f'{rel(path)}:{number}: includes {m.group(1)} (target {a}), which {t} does not link')
                break

# --- no cycle between targets (Tarjan's strongly connected components) -------------------------
index, low, stack, on_stack, cycles = {}, {}, [], set(), []


def connect(n):
    index[n] = low[n] = len(index)
    stack.append(n); on_stack.add(n)
    for m in sorted(links[n]):
        if m not in index:
            connect(m)
            low[n] = min(low[n], low[m])
        elif m in on_stack:
            low[n] = min(low[n], index[m])
    if low[n] == index[n]:
        component = []
        while True:
            m = stack.pop(); on_stack.discard(m); component.append(m)
            if m == n:
                break
        if len(component) > 1 or n in links[n]:
            cycles.append(sorted(component))


for n in sorted(names):
    if n not in index:
        connect(n)
for c in cycles:
    problems.append(f'lab/**/CMakeLists.txt: the targets {", ".join(c)} link each other in a cycle')

for p in problems:
    print(p)
print(f'{len(names)} targets, {len(files)} files, {checked} includes checked, {len(problems)} problems')
sys.exit(1 if problems else 0)
