#!/usr/bin/env python3
"""compact_presets_test.py ROOT — tools/compact_presets.py packs what the lab reads: every bundled
preset, exercise and deck under the same path with the same values in the same order, smaller; the
models and hidden files left out; a duplicate key, a number JSON cannot write and a file that is
not JSON refused with the file's name."""
import json
import os
import subprocess
import sys
import tempfile

root = sys.argv[1]
script = os.path.join(root, "tools", "compact_presets.py")
failures = []


def run(source, target):
    return subprocess.run([sys.executable, script, source, target], capture_output=True, text=True)


with tempfile.TemporaryDirectory() as tmp:
    presets, out = os.path.join(root, "presets"), os.path.join(tmp, "out")
    r = run(presets, out)
    if r.returncode != 0:
        failures.append(f"the bundled presets were refused: {r.stderr}")
    wanted = []
    for folder, subfolders, files in os.walk(presets):
        subfolders[:] = [d for d in subfolders if os.path.relpath(os.path.join(folder, d), presets) != "models"]
        wanted += [os.path.relpath(os.path.join(folder, f), presets) for f in files if f.endswith(".json")]
    packed = [os.path.relpath(os.path.join(d, f), out) for d, _, fs in os.walk(out) for f in fs]
    if sorted(packed) != sorted(wanted):
        failures.append(f"packed {sorted(set(packed) ^ set(wanted))} differently from the source")
    for rel in wanted:
        if rel not in packed:
            continue
        a = open(os.path.join(presets, rel), encoding="utf-8").read()
        b = open(os.path.join(out, rel), encoding="utf-8").read()
        if json.loads(a, object_pairs_hook=list) != json.loads(b, object_pairs_hook=list):
            failures.append(f"{rel}: its values or their order changed")
        if len(b) >= len(a):
            failures.append(f"{rel}: not smaller ({len(b)} bytes, {len(a)} before)")

    bad = os.path.join(tmp, "bad")
    for name, text, words in [("twice.json", '{"name": 1, "name": 2}', "'name' twice"),
                              ("huge.json", '{"shininess": 1e999}', "huge.json"),
                              ("broken.json", '{"name": 1,}', "broken.json"),
                              ("notes.txt", "hello", "not a .json file")]:
        os.makedirs(bad, exist_ok=True)
        for f in os.listdir(bad):
            os.remove(os.path.join(bad, f))
        with open(os.path.join(bad, name), "w", encoding="utf-8") as f:
            f.write(text)
        with open(os.path.join(bad, ".swap.json.swp"), "w") as f:
            f.write("an editor's")
        r = run(bad, os.path.join(tmp, "bad-out"))
        if r.returncode == 0 or name not in r.stderr or words not in r.stderr:
            failures.append(f"{name}: exit {r.returncode}, said {r.stderr.strip()!r} (wanted the file and {words!r})")

    hidden = os.path.join(tmp, "hidden")
    os.makedirs(hidden)
    with open(os.path.join(hidden, "one.json"), "w", encoding="utf-8") as f:
        f.write('{"name": "\u03b8"}')
    with open(os.path.join(hidden, ".one.json.swp"), "w") as f:
        f.write("an editor's")
    r = run(hidden, os.path.join(tmp, "hidden-out"))
    if r.returncode != 0 or os.listdir(os.path.join(tmp, "hidden-out")) != ["one.json"]:
        failures.append(f"a hidden file beside a preset: exit {r.returncode}, {r.stderr.strip()!r}")

for f in failures:
    print("FAIL:", f)
print(f"compact_presets: {len(failures)} failures")
sys.exit(1 if failures else 0)
