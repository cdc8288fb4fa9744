#!/usr/bin/env python3
"""compact_presets.py IN OUT — the bundled presets, exercises and decks as the browser build packs
them into lab.data: each .json file under IN (models/ left out: the site fetches those) written to
the same path under OUT as compact JSON, the same values in the same order without the indentation
(0.45 KB less gzip in the page's first load). Hidden files (an editor's) are left out; anything else
that is not a .json file, a file that is not JSON, a key twice in an object or a number JSON cannot
write (NaN, Infinity, 1e999) stops the build with the file's name: the page would otherwise carry a
file the lab reads differently from the source."""
import json
import os
import shutil
import sys

source, target = sys.argv[1], sys.argv[2]


def pairs(items):
    keys = [k for k, _ in items]
    twice = sorted({k for k in keys if keys.count(k) > 1})
    if twice:
        raise ValueError("the key " + ", ".join(repr(k) for k in twice) + " twice in one object")
    return dict(items)


def constant(name):
    raise ValueError(name + " is not JSON")


if os.path.exists(target):
    shutil.rmtree(target)
for folder, subfolders, files in os.walk(source):
    rel = os.path.relpath(folder, source)
    subfolders[:] = sorted(d for d in subfolders if not (rel == "." and d == "models") and not d.startswith("."))
    for name in sorted(f for f in files if not f.startswith(".")):
        path = os.path.join(folder, name)
        if not name.endswith(".json"):
            sys.exit(f"compact_presets.py: {path} is not a .json file; the page packs only presets, exercises and decks")
        try:
            with open(path, encoding="utf-8") as f:
                value = json.load(f, object_pairs_hook=pairs, parse_constant=constant)
            text = json.dumps(value, ensure_ascii=False, separators=(",", ":"), allow_nan=False) + "\n"
            out = os.path.join(target, rel, name)
            os.makedirs(os.path.dirname(out), exist_ok=True)
            with open(out, "w", encoding="utf-8") as f:
                f.write(text)
        except (ValueError, UnicodeError, OSError) as e:
            sys.exit(f"compact_presets.py: {path}: {e}")
