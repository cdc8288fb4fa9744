#!/usr/bin/env python3
"""The README's "Where things are" and the tree agree.

Every folder under lab/ has a row of its own (its path in the first column); every other row's
first column names a folder that exists; every path or file name a row mentions in backticks
exists: a path from the repository's root as it is, a bare file or folder name in the row's folder
or below it (`preset.h` in the row of lab/core/scene/), names without an extension as a file of
that stem there (`workspace` for workspace.cpp/.h). CMake variables (`LAB_PLATFORM`), targets
(`lab_ui`) and types (`Side`) are not paths.

    readme_map_test.py <repository root>
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.').resolve()
readme = (root / 'README.md').read_text(encoding='utf-8')
match = re.search(r'^## Where things are\n(.*?)(?=^## )', readme, re.S | re.M)
if not match:
    sys.exit('README.md: no "## Where things are" section')
rows = [line for line in match.group(1).splitlines() if line.startswith('| `')]
problems = []
described = set()
for row in rows:
    cells = [c.strip() for c in row.strip('|').split('|')]
    folder = cells[0].strip('`').rstrip('/')
    base = root / folder
    if not base.is_dir():
        problems.append(f'the row for `{cells[0]}` names a folder that does not exist')
        continue
    described.add(folder)
    for name in re.findall(r'`([^`\s]+)`', ' '.join(cells[1:])):
        name = name.rstrip('/')
        if (not re.fullmatch(r'[\w.\-/]+', name) or name.startswith('-') or re.fullmatch(r'[\d.]+', name)
                or name.isupper() or name.startswith('lab_') or name[0].isupper() and '.' not in name):
            continue  # a value, a flag, a CMake variable or target, a type, not a path
        if '/' in name and (root / name).exists():
            continue
        stem_only = '.' not in pathlib.PurePath(name).name
        found = any(p for p in base.rglob('*')
                    if p.relative_to(base).as_posix().endswith(name)
                    or (stem_only and p.is_file() and p.relative_to(base).with_suffix('').as_posix().endswith(name)))
        if not found:
            problems.append(f'the row for `{folder}/` names `{name}`, which is not in {folder}/')
for folder in sorted(p for p in (root / 'lab').rglob('*') if p.is_dir()):
    rel = folder.relative_to(root).as_posix()
    if rel not in described:
        problems.append(f'{rel}/ has no row of its own')
for p in problems:
    print(f'README.md, "Where things are": {p}')
print(f'{len(rows)} rows, {len(problems)} problems')
sys.exit(1 if problems else 0)
