#!/usr/bin/env bash
# hostile_cli_tests.sh LAB SOURCE_DIR — the third round of hardening (issue 36): exercises, links, QR
# codes, views and report files as a hostile user would try them. Each case failed on the main of
# 2026-11-28; each must exit as the README says, name what is wrong, and leave every input as it was.
# Run by CTest as `cli.hostile` (and under ASan+UBSan with the other cli tests).
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"

phong=$src/presets/05-full-phong.json
shin=$src/presets/exercises/02-shininess.json
shin_sol=$src/tests/exercises/02-shininess.solution.json
base=https://example.org/lab/
# kept NAME FILE...: each FILE is byte for byte its copy FILE.keep (made by keep).
keep() { for f in "$@"; do cp "$f" "$f.keep"; done; }
kept() {
    local name=$1 f ok=true
    shift
    for f in "$@"; do cmp -s "$f" "$f.keep" || ok=false; done
    check "$name" $ok
}

# --- a float tolerance that is infinite as the lab keeps it ----------------------------------------
# 1e308 is a finite double and an infinite float: it was accepted, written into the link as "inf",
# and `lab share` aborted (exit 134).
for big in 1e308 3.5e38; do
    edit "$shin" "$tmp/tol-$big.json" 'p["tolerance"] = {"fields": {"material.shininess": float(sys.argv[4])}}' "$big"
    expect "exercise-tolerance-$big-refused" 2 "tol-$big\.json: tolerance\.fields\.material\.shininess: must be in \[0, 1000000\], got " -- \
        "$lab" share "$tmp/tol-$big.json" --base "$base"
    expect "exercise-tolerance-$big-check-refused" 2 'tolerance\.fields\.material\.shininess: must be in \[0, 1000000\]' -- \
        "$lab" exercise check "$tmp/tol-$big.json" "$shin_sol"
done

# --- no output may be one of the run's inputs (the same file once links are resolved) -------------
# Each of these replaced the student's attempt, the exercise, the preset or a golden.
mkdir -p "$tmp/io/g"
cd "$tmp/io" || exit 1
cp "$shin" ex.json
cp "$shin_sol" att.json
cp "$phong" p.json
"$lab" check p.json --golden g --update --size 32x32 >/dev/null
keep ex.json att.json p.json g/p.png g/p.sweep.png
ln -s att.json att-link.png
ln att.json att-hard.png
expect diff-is-the-attempt 2 '^lab exercise check: --diff att\.json: is the attempt att\.json, which this run reads \(nothing was written\)$' -- \
    "$lab" exercise check ex.json att.json --diff att.json
expect diff-is-the-exercise 2 '^lab exercise check: --diff \./ex\.json: is the exercise ex\.json, which this run reads' -- \
    "$lab" exercise check ex.json att.json --diff ./ex.json
expect diff-is-a-link-to-the-attempt 2 '^lab exercise check: --diff att-link\.png: is the attempt att\.json' -- \
    "$lab" exercise check ex.json att.json --diff att-link.png
expect diff-is-a-hard-link-to-the-attempt 2 '^lab exercise check: --diff att-hard\.png: is the attempt att\.json' -- \
    "$lab" exercise check ex.json att.json --diff att-hard.png
expect qr-is-the-preset 2 '^lab share: --qr p\.json: is the preset p\.json, which this run reads' -- \
    "$lab" share p.json --base "$base" --qr p.json
check qr-refused-prints-no-link test -z "$("$lab" share p.json --base "$base" --qr p.json 2>/dev/null)"
expect junit-is-the-preset 2 '^lab check: --junit p\.json: is the preset p\.json, which this run reads' -- \
    "$lab" check p.json --golden g --junit p.json --size 32x32
expect html-is-a-golden 2 '^lab check: --html g/p\.png: is the golden g/p\.png, which this run reads' -- \
    "$lab" check p.json --golden g --html g/p.png --size 32x32
expect junit-is-a-golden 2 '^lab check: --junit g/p\.sweep\.png: is the golden g/p\.sweep\.png' -- \
    "$lab" check p.json --golden g --junit g/p.sweep.png --size 32x32
expect junit-is-a-golden-with-update 2 '^lab check: --junit g/p\.png: is the golden g/p\.png' -- \
    "$lab" check p.json --golden g --junit g/p.png --update --size 32x32
expect render-out-is-the-preset 2 '^lab render: --out p\.json: is the preset p\.json' -- "$lab" render p.json --out p.json --size 8x8
expect sweep-out-is-the-preset 2 '^lab render: --out p\.json: is the preset p\.json' -- \
    "$lab" render p.json --sweep material.shininess=1,2 --out p.json --size 8x8
expect plot-svg-is-the-preset 2 '^lab plot: --svg p\.json: is the preset p\.json' -- "$lab" plot p.json --svg p.json
expect plot-out-is-the-preset 2 '^lab plot: --out \./p\.json: is the preset p\.json' -- "$lab" plot p.json --out ./p.json
# A report folder that is the golden folder: a failing preset "q" would leave q.golden.png there,
# which is the golden of a preset named q.golden.
cp p.json q.json
cp p.json q.golden.json
"$lab" render p.json --out g/q.golden.png --size 32x32 >/dev/null
keep g/q.golden.png
expect report-file-is-a-golden 2 '^lab check: --report g/q\.golden\.png: is the golden g/q\.golden\.png' -- \
    "$lab" check q.json q.golden.json --golden g --report g --size 32x32
kept inputs-all-kept ex.json att.json p.json g/p.png g/p.sweep.png g/q.golden.png
# A model is an input too: a glTF preset's render written over its model.
mkdir -p model/models
cp "$src/presets/24-gltf-trefoil.json" model/
cp "$src/presets/models/"* model/models/
keep model/models/trefoil.glb
expect render-out-is-the-model 2 '^lab render: --out model/models/trefoil\.glb: is the model model/models/trefoil\.glb of model/24-gltf-trefoil\.json' -- \
    "$lab" render model/24-gltf-trefoil.json --out model/models/trefoil.glb --size 8x8
kept model-kept model/models/trefoil.glb
# ...and the preview, which writes into the temporary folder.
mkdir -p preview/lighting-lab
cp "$phong" preview/lighting-lab/x.png
keep preview/lighting-lab/x.png
expect preview-is-the-preset 2 'the preview .*/lighting-lab/x\.png: is the preset .*x\.png' -- \
    env -u DISPLAY -u WAYLAND_DISPLAY TMPDIR="$tmp/io/preview" "$lab" --preset preview/lighting-lab/x.png
kept preview-kept preview/lighting-lab/x.png
cd "$src" || exit 1

# --- every output is checked before anything is written; a bad one exits 2 in every command --------
mkdir -p "$tmp/out/folder"
mkfifo "$tmp/out/fifo"
for target in folder none/x.png fifo; do
    expect "diff-unwritable-$target" 2 "^lab exercise check: --diff .*out/$target: (is a folder|no such folder|is not a regular file)" -- \
        "$lab" exercise check "$shin" "$shin_sol" --diff "$tmp/out/$target"
    out=$("$lab" exercise check "$shin" "$shin_sol" --diff "$tmp/out/$target" 2>&1)
    check "diff-unwritable-$target-no-verdict" test "$(grep -c 'Solved\|Score [0-9]' <<<"$out")" -eq 0
    expect "qr-unwritable-$target" 2 "^lab share: --qr .*out/$target: (is a folder|no such folder|is not a regular file)" -- \
        "$lab" share "$phong" --base "$base" --qr "$tmp/out/$target"
    check "qr-unwritable-$target-no-link" test -z "$("$lab" share "$phong" --base "$base" --qr "$tmp/out/$target" 2>/dev/null)"
    expect "render-unwritable-$target" 2 "^lab render: --out .*out/$target: (is a folder|no such folder|is not a regular file)" -- \
        "$lab" render "$phong" --out "$tmp/out/$target" --size 8x8
    expect "plot-unwritable-$target" 2 "^lab plot: --png .*out/$target: (is a folder|no such folder|is not a regular file)" -- \
        "$lab" plot "$phong" --png "$tmp/out/$target"
    expect "check-junit-unwritable-$target" 2 "^lab check: --junit .*out/$target: (is a folder|no such folder|is not a regular file)" -- \
        "$lab" check "$phong" --golden "$src/tests/golden" --report "$tmp/out/r" --junit "$tmp/out/$target"
done
check unwritable-outputs-wrote-nothing test "$(find "$tmp/out" -mindepth 1 | sort | tr '\n' ' ')" = "$tmp/out/fifo $tmp/out/folder "

# Two presets of one file name into one folder: named, nothing written; one preset twice is fine.
mkdir -p "$tmp/two/a" "$tmp/two/b"
cp "$phong" "$tmp/two/a/x.json"
cp "$phong" "$tmp/two/b/x.json"
expect render-two-presets-one-name 2 '^lab render: .*a/x\.json and .*b/x\.json would both write x\.png$' -- \
    "$lab" render "$tmp/two/a/x.json" "$tmp/two/b/x.json" --out "$tmp/two/out" --size 8x8
check render-two-presets-one-name-nothing-written test ! -e "$tmp/two/out"
expect render-one-preset-twice 0 'out/x\.png' -- "$lab" render "$tmp/two/a/x.json" "$tmp/two/a/../a/x.json" --out "$tmp/two/out" --size 8x8

# A write that fails later (here: a file-size limit of 0, as a full disk would) exits 2 too, saying
# what was not written; the verdict and the link are still printed.
full() { (trap '' XFSZ; ulimit -f 0; exec "$@"); }
expect diff-full-disk 2 'Solved.*|lab exercise check: --diff .*d\.png was not written' -- \
    full "$lab" exercise check "$shin" "$shin_sol" --diff "$tmp/out/d.png"
out=$(full "$lab" exercise check "$shin" "$shin_sol" --diff "$tmp/out/d.png" 2>&1)
check diff-full-disk-verdict-and-why grep -q 'Solved' <<<"$out"
check diff-full-disk-says-what grep -q '^lab exercise check: --diff .*d\.png was not written: ' <<<"$out"
expect qr-full-disk 2 '^lab share: --qr .*q\.png was not written: ' -- full "$lab" share "$phong" --base "$base" --qr "$tmp/out/q.png"
expect render-full-disk 2 '^lab render: ' -- full "$lab" render "$phong" --out "$tmp/out/r.png" --size 8x8
expect plot-full-disk 2 '^lab plot: ' -- full "$lab" plot "$phong" --out "$tmp/out/p.csv"
expect check-update-full-disk 2 'ERROR +05-full-phong: the golden was not written: ' -- \
    full "$lab" check "$phong" --golden "$tmp/out/g" --update --size 8x8
check full-disk-wrote-nothing test ! -e "$tmp/out/d.png" -a ! -e "$tmp/out/q.png" -a ! -e "$tmp/out/r.png" -a ! -e "$tmp/out/p.csv" -a ! -e "$tmp/out/g/05-full-phong.png"

# --- lab share: the course page's address, and the models a link cannot carry -----------------------

# The address goes into the QR code as it is: what the teacher reads must be what the phone opens.
esc=$'\e'
bad_base() { # bad_base NAME BASE PATTERN: refused by lab share (no link, no PNG) and by lab --share-base
    expect "share-base-$1" 2 "^lab share: --base: $3" -- "$lab" share "$phong" --base "$2" --qr "$tmp/base-$1.png"
    check "share-base-$1-no-png" test ! -e "$tmp/base-$1.png"
    check "share-base-$1-no-link" test -z "$("$lab" share "$phong" --base "$2" 2>/dev/null)"
    expect "share-base-remembered-$1" 2 "^--share-base: " -- env XDG_CONFIG_HOME="$tmp/config" "$lab" --share-base "$2"
}
bad_base esc "https://x.org/${esc}[31m/" 'byte 0x1B at offset 14 is not allowed: an address is printable ASCII \(0x21 to 0x7E\)'
bad_base bel "https://x.org/"$'\a' 'byte 0x07 at offset 14 is not allowed'
bad_base del "https://x.org/"$'\x7f' 'byte 0x7F at offset 14 is not allowed'
bad_base latin1 "https://x.org/caf"$'\xe9' 'byte 0xE9 at offset 17 is not allowed'
bad_base utf8 "https://x.org/café" 'byte 0xC3 at offset 17 is not allowed'
bad_base space "https://x.org/a b" 'byte 0x20 at offset 15 is not allowed'
bad_base no-host "https://" 'no host after "https://"'
bad_base no-host-path "https:///lab/" 'no host after "https://"'
bad_base user "https://teacher@evil.example/" 'a user name in the address'
bad_base port "https://x.org:80a/" 'the port ":80a" is not a number'
bad_base quote 'https://x.org/"lab' '.". \(0x22\) at offset 14 is not allowed in an address'
check share-base-nothing-remembered test ! -e "$tmp/config/lighting-lab/settings.json"
expect share-base-upper-case-scheme 0 '^HTTPS://X\.ORG:8080/lab/#preset=05-full-phong$' -- "$lab" share "$phong" --base HTTPS://X.ORG:8080/lab/
expect share-base-percent-encoded 0 '^https://x\.org/caf%C3%A9/#preset=05-full-phong$' -- "$lab" share "$phong" --base https://x.org/caf%C3%A9/
# A settings file holding such an address (written by hand, or by an older lab) is ignored, said so.
mkdir -p "$tmp/config2/lighting-lab"
printf '{"share_base": "https://x.org/\\u001b[31m"}' >"$tmp/config2/lighting-lab/settings.json"
expect settings-share-base-refused 0 'settings\.json: share_base: byte 0x1B at offset 14 is not allowed.*\(ignored\)' -- \
    env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME="$tmp/config2" TMPDIR="$tmp" "$lab"

# --theme: remembered beside share_base; a bad name refused with the names; a bad remembered one ignored, said so.
mkdir -p "$tmp/config3/lighting-lab"
printf '{"share_base": "https://x.org/lab/"}' >"$tmp/config3/lighting-lab/settings.json"
expect theme-remembered 0 'rendering a preview' -- \
    env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME="$tmp/config3" TMPDIR="$tmp" "$lab" --theme light
check theme-in-settings grep -q '"theme": "light"' "$tmp/config3/lighting-lab/settings.json"
check theme-keeps-share-base grep -q '"share_base": "https://x.org/lab/"' "$tmp/config3/lighting-lab/settings.json"
expect theme-unknown 2 "^--theme: unknown theme 'blue': the themes are dark, light" -- \
    env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME="$tmp/config3" "$lab" --theme blue
check theme-unknown-not-remembered grep -q '"theme": "light"' "$tmp/config3/lighting-lab/settings.json"
printf '{"theme": "purple"}' >"$tmp/config3/lighting-lab/settings.json"
expect settings-theme-refused 0 'settings\.json: theme: expected one of dark, light \(ignored\)' -- \
    env -u DISPLAY -u WAYLAND_DISPLAY XDG_CONFIG_HOME="$tmp/config3" TMPDIR="$tmp" "$lab"

# An exercise whose start names its own glTF model: the page has no such model, so no link (as for
# a preset with one).
mkdir -p "$tmp/own-model/models"
cp "$src/presets/models/"* "$tmp/own-model/models/"
edit "$shin" "$tmp/own-model/ex.json" 'p["start"]["model"] = {"gltf": "models/trefoil.glb"}'
expect share-exercise-own-model 2 'ex\.json: start\.model\.gltf: a link carries the scene, not its model file' -- \
    "$lab" share "$tmp/own-model/ex.json" --base "$base"
check share-exercise-own-model-no-link test -z "$("$lab" share "$tmp/own-model/ex.json" --base "$base" 2>/dev/null)"
edit "$phong" "$tmp/own-model/p.json" 'p["model"] = {"gltf": "models/trefoil.glb"}'
expect share-preset-own-model 2 'p\.json: model\.gltf: a link carries the scene, not its model file' -- \
    "$lab" share "$tmp/own-model/p.json" --base "$base"

# --- lab check: report.txt as safe as the terminal; goldens that would share a name ----------------
mkdir -p "$tmp/names/g"
hostile="$tmp/names/a${esc}[2J"$'\xff'"b.json"
cp "$phong" "$hostile"
"$lab" check "$hostile" --golden "$tmp/names/g" --report "$tmp/names/r" --size 16x16 >/dev/null 2>&1
check report-txt-written test -s "$tmp/names/r/report.txt"
check report-txt-escaped grep -qF 'a\x1B[2J\xFFb' "$tmp/names/r/report.txt"
check report-txt-no-raw-bytes test "$(tr -d -c '\033\377' <"$tmp/names/r/report.txt" | wc -c)" -eq 0
# x.json checks its view d against x.d.png, which is also the render golden of x.d.json.
edit "$src/presets/13-cook-torrance-beckmann-schlick.json" "$tmp/names/x.json" 'p["check"] = {"views": ["d"]}'
cp "$phong" "$tmp/names/x.d.json"
expect golden-names-collide 2 '^lab check: .*x\.json and .*x\.d\.json would both be checked against x\.d\.png$' -- \
    "$lab" check "$tmp/names/x.json" "$tmp/names/x.d.json" --golden "$tmp/names/g" --update --size 16x16
check golden-names-collide-nothing-written test ! -e "$tmp/names/g/x.d.png" -a ! -e "$tmp/names/g/x.png"
edit "$src/presets/23-spot-light.json" "$tmp/names/s.json" 'p["check"] = {"views": [{"view": "spot", "light": 1}, "spot"]}'
expect check-view-listed-twice 2 's\.json: check\.views\[1\]: "spot" is listed twice$' -- \
    "$lab" check "$tmp/names/s.json" --golden "$tmp/names/g" --update --size 16x16

# --- sweeps: a value is parsed whole or refused -------------------------------------------------------
expect sweep-unclosed-bracket 2 '^lab render: --sweep material\.specular: value 2 "\[0,0,0" leaves a .\[. open$' -- \
    "$lab" render "$phong" --sweep 'material.specular=[1,1,1],[0,0,0' --out "$tmp/s.png" --size 8x8
expect sweep-stray-bracket 2 "^lab render: --sweep material\.specular: value 1 \"1\]\" closes a '\]' it did not open$" -- \
    "$lab" render "$phong" --sweep 'material.specular=1],[0,0,0]' --out "$tmp/s.png" --size 8x8
check sweep-brackets-nothing-written test ! -e "$tmp/s.png"
edit "$phong" "$tmp/sweep-preset.json" 'p["sweep"] = ["material.specular=[1,1,1],[0,0,0"]'
expect sweep-in-a-preset-unclosed 2 'sweep-preset\.json: sweep\[0\]: .*leaves a .\[. open' -- \
    "$lab" render "$tmp/sweep-preset.json" --out "$tmp/s.png" --size 8x8

# --- the preview (no display) opens an exercise at its start, as the lab's window does --------------
expect preview-exercise 0 'rendered the start of the exercise "Find the shininess" to .*/02-shininess\.png' -- env -u DISPLAY -u WAYLAND_DISPLAY TMPDIR="$tmp" "$lab" --preset "$shin"
check preview-exercise-png is_png "$tmp/lighting-lab/02-shininess.png"

# --- a golden is judged by its header before it is decoded -----------------------------------------
# A PNG header claiming W x H followed by data that does not decode: what lab check says shows
# whether it decoded (a decoder would fail on the data; the header alone gives the size). A real
# 16384 x 16384 golden of 780 KB took 41 s and 1.6 GB to be found of another size.
png_header() { # png_header W H FILE
    python3 -c 'import struct, sys, zlib
w, h = int(sys.argv[1]), int(sys.argv[2])
def chunk(t, d): return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
ihdr = chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
open(sys.argv[3], "wb").write(b"\x89PNG\r\n\x1a\n" + ihdr + chunk(b"IDAT", b"not deflate data") + chunk(b"IEND", b""))' "$@"
}
mkdir -p "$tmp/bomb"
cp "$phong" "$tmp/bomb/p.json"
png_header 8192 8192 "$tmp/bomb/p.png"
expect golden-other-size-fails-undecoded 1 'FAIL +p  size 32x32 vs golden 8192x8192' -- \
    "$lab" check "$tmp/bomb/p.json" --golden "$tmp/bomb" --report "$tmp/bomb/r" --size 32x32
check golden-other-size-copied-as-is cmp -s "$tmp/bomb/p.png" "$tmp/bomb/r/p.golden.png"
png_header 16384 16384 "$tmp/bomb/p.sweep.png"
expect golden-larger-than-renders-is-an-error 2 'ERROR +p\.sweep: golden .*p\.sweep\.png: its header claims 16384x16384, larger than the lab renders \(8192 a side\)' -- \
    "$lab" check "$tmp/bomb/p.json" --golden "$tmp/bomb" --report "$tmp/bomb/r" --size 32x32
expect golden-same-size-is-decoded 2 'ERROR +p: golden .*p\.png: cannot decode PNG' -- \
    "$lab" check "$tmp/bomb/p.json" --golden "$tmp/bomb" --report "$tmp/bomb/r" --size 8192x8192
expect golden-other-size-updated-undecoded 0 'UPDATED +p  \(size 8192x8192 before\)' -- \
    "$lab" check "$tmp/bomb/p.json" --golden "$tmp/bomb" --update --size 32x32
check golden-updated-to-the-render test "$(png_size "$tmp/bomb/p.png")" = "32 32"

# --- links: never longer than a link may be (16384 characters) ---------------------------------------
edit "$phong" "$tmp/long-link.json" 'p["description"] = " ".join(str(i * 2654435761 % 10**9) for i in range(4000))'
expect share-link-too-long 2 'long-link\.json: the link would be [0-9]+ characters, more than the 16384 a link may have' -- \
    "$lab" share "$tmp/long-link.json" --base "$base"
check share-link-too-long-no-link test -z "$("$lab" share "$tmp/long-link.json" --base "$base" 2>/dev/null)"

finish
