#!/usr/bin/env bash
# hostile_fourth_round_tests.sh LAB SOURCE_DIR — the fourth round of hardening (issue 49): `lab fit`,
# outputs that are symbolic links, the settings file and JSON literals JSON does not have. Each case
# failed on the main of 2026-12-07 (3a3a56a); each must exit as the README says, name what is wrong,
# and leave every input, link and target as it should be. Run by CTest as `cli.hostile-fourth-round`
# (and under ASan+UBSan with the other cli tests).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"

phong=$src/presets/05-full-phong.json
shin=$src/presets/exercises/02-shininess.json
shin_sol=$src/tests/exercises/02-shininess.solution.json
base=https://example.org/lab/
# link_kept NAME LINK TARGET: LINK is still a symbolic link to TARGET (as written when it was made).
link_kept() { check "$1" test -L "$2" -a "$(readlink "$2" 2>/dev/null)" = "$3"; }

mkdir -p "$tmp/p/models"
cp "$src/presets/"*.json "$tmp/p/"
cp "$src/presets/models/"* "$tmp/p/models/"

# --- 1. lab fit aborted (SIGABRT) on a preset named without a folder, and in a removed folder -----------
cd "$tmp/p" || exit 1
expect fit-preset-without-folder 0 '^Phong: shininess [0-9.]+' -- "$lab" fit 24-gltf-trefoil.json --brdf phong --out fit.json
check fit-preset-without-folder-model-path grep -q '"gltf": "models/trefoil.glb"' fit.json
expect fit-preset-without-folder-builtin 0 '^Blinn-Phong: ' -- "$lab" fit 05-full-phong.json --brdf blinn-phong --out fit-b.json
mkdir -p "$tmp/gone"
cd "$tmp/gone" || exit 1
rmdir "$tmp/gone"
expect fit-removed-folder-gltf 2 '^lab fit: --out fit\.json: the folder \. has been removed \(nothing was written\)$' -- \
    "$lab" fit "$tmp/p/24-gltf-trefoil.json" --brdf phong --out fit.json
expect fit-removed-folder-builtin 2 '^lab fit: --out fit\.json: the folder \. has been removed' -- \
    "$lab" fit "$phong" --brdf blinn-phong --out fit.json
expect render-removed-folder 2 '^lab render: --out x\.png: the folder \. has been removed' -- "$lab" render "$phong" --out x.png --size 8x8
cd "$src" || exit 1

# --- 2. outputs that are symbolic links are written through, never replaced -----------------------------
# Each command's output named through a link: the link stays, its target gets the new bytes.
mkdir -p "$tmp/l/real" "$tmp/l/g-real"
cd "$tmp/l" || exit 1
cp "$phong" p.json
for name in render.png plot.csv plot.svg fit.json qr.png diff.png junit.xml; do
    echo old >"real/$name"
    ln -s "real/$name" "$name"
done
expect link-render 0 'render\.png' -- "$lab" render p.json --out render.png --size 16x16
expect link-plot-csv 0 'plot\.csv' -- "$lab" plot p.json --out plot.csv
expect link-plot-svg 0 'plot\.svg' -- "$lab" plot p.json --svg plot.svg
expect link-fit 0 'fit\.json' -- "$lab" fit p.json --brdf blinn-phong --out fit.json
expect link-share-qr 0 'qr\.png: QR code version' -- "$lab" share p.json --base "$base" --qr qr.png
expect link-exercise-diff 0 'Solved' -- "$lab" exercise check "$shin" "$shin_sol" --diff diff.png
mkdir -p g
ln -s ../g-real/p.png g/p.png
echo old >g-real/p.png
expect link-check-golden 0 '(CREATED|UPDATED) +p$' -- "$lab" check p.json --golden g --update --size 16x16
expect link-check-junit 0 'passed' -- "$lab" check p.json --golden g --junit junit.xml --size 16x16
for name in render.png plot.csv plot.svg fit.json qr.png diff.png junit.xml; do
    link_kept "link-$name-kept" "$name" "real/$name"
    check "link-$name-target-written" test "$(head -c 3 "real/$name")" != old
done
link_kept link-golden-kept g/p.png ../g-real/p.png
check link-golden-target-is-the-render is_png g-real/p.png
check link-nothing-left-beside test "$(find . -name '.*tmp*' | wc -l)" -eq 0
# A link to a file not made yet makes it; a link into a missing folder is named with where it leads.
ln -s real/later.png later.png
expect link-to-a-file-to-come 0 'later\.png' -- "$lab" render p.json --out later.png --size 8x8
check link-to-a-file-to-come-made is_png real/later.png
ln -s none/x.png lost.png
expect link-into-a-missing-folder 2 '^lab render: --out lost\.png: leads to none/x\.png: no such folder none \(nothing was written\)$' -- \
    "$lab" render p.json --out lost.png --size 8x8
ln -s loop-b.png loop-a.png
ln -s loop-a.png loop-b.png
expect link-loop 2 '^lab render: --out loop-a\.png: is a symbolic link that leads round in a loop' -- \
    "$lab" render p.json --out loop-a.png --size 8x8
# An output through a link that is one of the run's inputs is still refused.
ln -s p.json p-link.png
expect link-to-the-preset 2 '^lab render: --out p-link\.png: is the preset p\.json, which this run reads' -- \
    "$lab" render p.json --out p-link.png --size 8x8
link_kept link-to-the-preset-kept p-link.png p.json
# Two outputs, one through a link to the other (a file still to come): one file, refused.
ln -s csv-b.csv csv-a.csv
expect link-two-outputs-one-file 2 '^lab plot: --albedo csv-b\.csv: --out writes that file too \(as csv-a\.csv\)' -- \
    "$lab" plot p.json --out csv-a.csv --albedo csv-b.csv
check link-two-outputs-nothing-written test ! -e csv-b.csv

# /dev/stdout leads to /proc/self/fd/1, a process's open file: refused whatever fd 1 is, and (as root,
# as in CI's containers) the system's link is not replaced. A link of our own into /proc likewise.
ln -s /proc/self/fd/1 my-stdout.json
for out in /dev/stdout my-stdout.json; do
    expect "fit-out-$out-refused" 2 "^lab fit: --out $out: (leads to /proc/self/fd/1, )?a process's open file" -- \
        "$lab" fit p.json --brdf phong --out "$out"
    "$lab" fit p.json --brdf phong --out "$out" >"$tmp/fit-stdout.log" 2>&1
    check "fit-out-$out-refused-with-stdout-a-file" grep -q "a process's open file" "$tmp/fit-stdout.log"
done
check dev-stdout-still-a-link test -L /dev/stdout
link_kept my-stdout-kept my-stdout.json /proc/self/fd/1
if [[ ! -L /dev/stdout && $(id -u) -eq 0 ]]; then
    rm -f /dev/stdout && ln -s /proc/self/fd/1 /dev/stdout # (a failing run must not leave the machine without it)
fi

# settings.json linked into a dotfiles folder: the dotfile gets the theme, the link stays.
mkdir -p "$tmp/dotfiles" "$tmp/cfg/lighting-lab"
printf '{"share_base": "https://x.org/lab/"}\n' >"$tmp/dotfiles/lab-settings.json"
ln -s "$tmp/dotfiles/lab-settings.json" "$tmp/cfg/lighting-lab/settings.json"
expect settings-through-link 0 'rendering a preview' -- \
    env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME="$tmp/cfg" TMPDIR="$tmp" "$lab" --theme dark
link_kept settings-link-kept "$tmp/cfg/lighting-lab/settings.json" "$tmp/dotfiles/lab-settings.json"
check settings-dotfile-has-the-theme grep -q '"theme": "dark"' "$tmp/dotfiles/lab-settings.json"
check settings-dotfile-keeps-share-base grep -q '"share_base": "https://x.org/lab/"' "$tmp/dotfiles/lab-settings.json"
cd "$src" || exit 1

# --- 8. lab fit writes a preset that carries the scene and reads and checks ----------------------------
# A glTF preset without a camera is framed before the fit, as lab render and the GUI frame it: the
# fit's render shows the model (it was out of view, 0% of the image).
edit "$tmp/p/24-gltf-trefoil.json" "$tmp/p/nocam.json" 'del p["camera"]'
expect fit-frames-a-model-without-camera 0 'nocam-fit\.json' -- "$lab" fit "$tmp/p/nocam.json" --brdf phong --out "$tmp/p/nocam-fit.json"
check fit-frames-writes-the-framed-camera test "$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["camera"]["eye"] != [0, 0, 4])' "$tmp/p/nocam-fit.json")" = True
"$lab" render "$tmp/p/nocam.json" --out "$tmp/p/nocam-a.png" --size 64x64 >/dev/null 2>&1
"$lab" render "$tmp/p/nocam-fit.json" --out "$tmp/p/nocam-b.png" --size 64x64 >/dev/null 2>&1
covered() { # the share of pixels that are not the background, in percent
    python3 -c 'import sys, zlib, struct
d = open(sys.argv[1], "rb").read(); i = 8; raw = b""; w = h = 0
while i < len(d):
    n, t = struct.unpack(">I4s", d[i:i + 8]); c = d[i + 8:i + 8 + n]; i += 12 + n
    if t == b"IHDR": w, h = struct.unpack(">II", c[:8])
    if t == b"IDAT": raw += c
raw = zlib.decompress(raw); stride = 1 + 3 * w; bg = None; lit = 0; prev = bytearray(stride - 1)
for y in range(h):
    f = raw[y * stride]; row = bytearray(raw[y * stride + 1:(y + 1) * stride])
    for x in range(len(row)):
        a = row[x - 3] if x >= 3 else 0; b = prev[x]; c = prev[x - 3] if x >= 3 else 0
        p = a + b - c; pr = a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c) else b if abs(p - b) <= abs(p - c) else c
        row[x] = (row[x] + [0, a, b, (a + b) // 2, pr][f]) & 255
    prev = row
    for x in range(w):
        px = tuple(row[3 * x:3 * x + 3]); bg = bg or px; lit += px != bg
print(100 * lit // (w * h))' "$1"
}
check fit-render-shows-the-model test "$(covered "$tmp/p/nocam-b.png")" -ge 20
check fit-render-as-the-preset test "$(covered "$tmp/p/nocam-b.png")" -ge $(($(covered "$tmp/p/nocam-a.png") - 5))
# A preset that loads, just under the size limit: its fit would be over it, and is not written.
python3 - "$phong" "$tmp/big.json" <<'EOF'
import json, sys
p = json.load(open(sys.argv[1]))
p["description"] = ""
n = 1048550 - len(json.dumps(p))
p["description"] = "x" * n
open(sys.argv[2], "w").write(json.dumps(p))
EOF
quiet() { "$@" >/dev/null 2>&1; }
check big-preset-loads quiet "$lab" plot "$tmp/big.json" --out "$tmp/big.csv"
expect fit-over-the-size-limit 2 'refusing to save a preset of 10[0-9]{5} bytes, more than the 1048576 a preset may have.*shorten its description' -- \
    "$lab" fit "$tmp/big.json" --brdf phong --out "$tmp/big-fit.json"
check fit-over-the-size-limit-nothing-written test ! -e "$tmp/big-fit.json"
# Cook-Torrance's views D, F and G are not the fitted Phong's: the fit's check keeps the views it has.
edit "$src/presets/13-cook-torrance-beckmann-schlick.json" "$tmp/ct-views.json" 'p["check"] = {"views": ["d", "f", "g", "n-dot-l"], "max_mean": 0.4}'
expect fit-check-views 0 'ct-views-fit\.json' -- "$lab" fit "$tmp/ct-views.json" --brdf phong --out "$tmp/ct-views-fit.json"
check fit-check-views-kept test "$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["check"])' "$tmp/ct-views-fit.json")" = "{'max_mean': 0.4, 'views': ['n-dot-l']}"
expect fit-check-runs 0 '2 passed, 0 failed' -- "$lab" check "$tmp/ct-views-fit.json" --golden "$tmp/ct-g" --update --size 16x16

# --- 9. lab fit names the term that reflects nothing ---------------------------------------------------
edit "$src/presets/13-cook-torrance-beckmann-schlick.json" "$tmp/ior1.json" 'p["cook_torrance"]["ior"] = 1; p["cook_torrance"]["fresnel"] = "full"; p["material"]["specular"] = [1, 1, 1]'
expect fit-fresnel-zero 2 "^lab fit: .*ior1\.json: nothing to fit: the preset reflects no specular light \(Cook-Torrance's Fresnel term F is 0 at every angle: the full Fresnel equations with ior 1" -- \
    "$lab" fit "$tmp/ior1.json" --brdf phong --out "$tmp/ior1-fit.json"
check fit-fresnel-zero-not-the-colour test -z "$("$lab" fit "$tmp/ior1.json" --brdf phong --out "$tmp/ior1-fit.json" 2>&1 | grep 'specular colour')"

# --- 10. the settings file: no empty share_base, and none in the working folder ------------------------
mkdir -p "$tmp/cfg10"
expect settings-theme-alone 0 'rendering a preview' -- \
    env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME="$tmp/cfg10" TMPDIR="$tmp" "$lab" --theme dark
check settings-no-empty-share-base test -z "$(grep share_base "$tmp/cfg10/lighting-lab/settings.json")"
out=$(env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME="$tmp/cfg10" TMPDIR="$tmp" "$lab" 2>&1)
check settings-next-start-without-warning test -z "$(grep -i 'share_base' <<<"$out")"
# One an older lab wrote ("share_base": "") reads as never given, without a warning.
printf '{\n  "share_base": "",\n  "theme": "dark"\n}\n' >"$tmp/cfg10/lighting-lab/settings.json"
out=$(env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME="$tmp/cfg10" TMPDIR="$tmp" "$lab" 2>&1)
check settings-old-empty-share-base-quiet test -z "$(grep -i 'share_base' <<<"$out")"
mkdir -p "$tmp/nohome"
cd "$tmp/nohome" || exit 1
expect settings-nowhere 0 'cannot remember --theme: neither XDG_CONFIG_HOME nor HOME is set' -- \
    env -u DISPLAY -u WAYLAND_DISPLAY -u HOME -u XDG_CONFIG_HOME TMPDIR="$tmp" "$lab" --theme dark
check settings-not-in-the-working-folder test -z "$(ls -A "$tmp/nohome")"
cd "$src" || exit 1

# --- 11. JSON's missing literals: the message keeps what the parser said -------------------------------
sed 's/"shininess": [0-9.]*/"shininess": NaN/' "$shin_sol" >"$tmp/nan.json"
expect attempt-nan 2 "nan\.json: line [0-9]+, column [0-9]+: invalid JSON: syntax error while parsing value - invalid literal; last read: '\"shininess\": N'$" -- \
    "$lab" exercise check "$shin" "$tmp/nan.json"
sed 's/"shininess": [0-9.]*/"shininess": Infinity/' "$phong" >"$tmp/inf.json"
expect preset-infinity 2 "inf\.json: line [0-9]+, column [0-9]+: invalid JSON: .*last read: '\"shininess\": I'$" -- \
    "$lab" render "$tmp/inf.json" --out "$tmp/inf.png" --size 8x8

finish
