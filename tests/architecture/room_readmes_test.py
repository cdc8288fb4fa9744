#!/usr/bin/env python3
"""Every room has a README.md that names its files, and names no file it does not have.

A room is a folder under lab/ that holds .h or .cpp files directly, and shaders/. For each:
  * its README.md exists;
  * every source file directly in the folder (.h, .cpp, .glsl, .vert, .frag; not those in its
    sub-folders, which are rooms of their own) is named in the README in backticks (`panel.h`);
  * every name in backticks that looks like a source file (ends in one of those extensions) is
    there: a bare name in the room's own folder, a path with a '/' from the repository's root or
    from lab/ (as the code includes it: `core/scene/field_table.h`).

    room_readmes_test.py <repository root>
"""
import pathlib
import re
import sys

EXTENSIONS = ('.h', '.cpp', '.glsl', '.vert', '.frag')
FILE_NAME = re.compile(r'[\w./-]+(' + '|'.join(re.escape(e) for e in EXTENSIONS) + ')')

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.').resolve()
lab = root / 'lab'
rooms = sorted({p.parent for p in lab.rglob('*') if p.is_file() and p.suffix in ('.h', '.cpp')})
rooms.append(root / 'shaders')
problems = []
for room in rooms:
    rel = room.relative_to(root).as_posix()
    readme = room / 'README.md'
    if not readme.is_file():
        problems.append(f'{rel}/: no README.md')
        continue
    named = set(re.findall(r'`([^`\n]+)`', readme.read_text(encoding='utf-8')))
    files = sorted(p.name for p in room.iterdir() if p.is_file() and p.suffix in EXTENSIONS)
    for name in files:
        if name not in named:
            problems.append(f'{rel}/README.md: does not name `{name}`')
    for name in sorted(n for n in named if FILE_NAME.fullmatch(n)):
        if '/' in name:
            if not ((root / name).is_file() or (lab / name).is_file()):
                problems.append(f'{rel}/README.md: names `{name}`, which is not a file')
        elif name not in files:
            problems.append(f'{rel}/README.md: names `{name}`, which is not in {rel}/')
for p in problems:
    print(p)
print(f'{len(rooms)} rooms, {len(problems)} problems')
sys.exit(1 if problems else 0)
