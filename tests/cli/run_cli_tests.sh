#!/usr/bin/env bash
# run_cli_tests.sh LAB SOURCE_DIR — the `lab` command line as a user meets it: exit status,
# messages on stderr, files written (and not written). Run by CTest as the `cli` test.
set -u
source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh"

phong=$src/presets/05-full-phong.json

# --- flags -----------------------------------------------------------------------------
expect help 0 'render.*plot|Subcommands' -- "$lab" --help
expect version 0 '^lab [0-9]+\.[0-9]+\.[0-9]+' -- "$lab" --version
expect unknown-flag 2 'bogus' -- "$lab" --bogus
expect render-needs-out 2 '--out' -- "$lab" render "$phong"
expect bad-size 2 'WIDTHxHEIGHT' -- "$lab" render "$phong" --out "$tmp/x.png" --size 12by12
expect zero-size 2 'from 1 to' -- "$lab" render "$phong" --out "$tmp/x.png" --size 0x10
expect missing-preset 2 'no such file' -- "$lab" render "$tmp/none.json" --out "$tmp/x.png"
expect preset-is-folder 2 'folder' -- "$lab" render "$tmp" --out "$tmp/x.png"
check nothing-written test ! -e "$tmp/x.png"

# --- hostile names and values reach the terminal escaped (issue 14) ------------------------
esc=$'\e'
expect empty-out 2 '^--out: must not be empty' -- "$lab" render "$phong" --out ""
out=$("$lab" render "$tmp/${esc}]0;pwned"$'\a'".json" --out "$tmp/x.png" 2>&1)
check escaped-file-name grep -qF '\x1B]0;pwned\x07.json: no such file' <<<"$out"
check no-raw-escape-in-file-name test "$(printf '%s' "$out" | tr -d -c '\033\007' | wc -c)" -eq 0
out=$("$lab" "--bogus${esc}[2J" 2>&1)
check escaped-unknown-flag grep -qF -- '--bogus\x1B[2J' <<<"$out"
printf '{"format": "lighting-lab-preset", "version": 1, "material": {"shininess": 32, "\\u001b[31mred\\u0000": 1}}' >"$tmp/hostile.json"
out=$("$lab" render "$tmp/hostile.json" --out "$tmp/h.png" 2>&1)
rc=$?
check hostile-key-refused test $rc -eq 2
check hostile-key-escaped grep -qF 'material."\x1B[31mred\0": unknown key (it holds a NUL byte)' <<<"$out"
check hostile-key-no-raw-bytes test "$(printf '%s' "$out" | tr -d -c '\000\033' | wc -c)" -eq 0
printf '{"format": "lighting-lab-preset", "version": 1, "name": "caf\xe9"}' >"$tmp/latin1.json"
out=$("$lab" render "$tmp/latin1.json" --out "$tmp/h.png" 2>&1)
check invalid-utf8-escaped grep -qF 'invalid JSON: syntax error while parsing value - invalid string: ill-formed UTF-8 byte; last read: '"'"'"caf\xE9"'"'" <<<"$out"
check invalid-utf8-no-raw-byte test "$(printf '%s' "$out" | tr -d -c '\351' | wc -c)" -eq 0
touch "$tmp/a-file"
expect check-update-golden-is-a-file 2 '^lab check: --golden .*a-file: cannot be used as a folder' -- \
    "$lab" check "$phong" --golden "$tmp/a-file" --update
expect check-report-is-a-file 2 '^lab check: --report .*a-file: cannot be used as a folder' -- \
    "$lab" check "$phong" --golden "$src/tests/golden" --report "$tmp/a-file"

# --- bad presets: every problem, with file and JSON path --------------------------------
expect broken-preset 2 'broken\.json: material\.difuse: unknown key \(did you mean "diffuse"\?\)' -- \
    "$lab" render "$src/tests/data/broken.json" --out "$tmp/x.png"
expect broken-preset-all-problems 2 'material\.shininess: must be in \[0\.001, 1000000\].*' -- \
    "$lab" render "$src/tests/data/broken.json" --out "$tmp/x.png"
out=$("$lab" render "$src/tests/data/broken.json" --out "$tmp/x.png" 2>&1)
check broken-preset-three-lines test "$(grep -c 'broken\.json' <<<"$out")" -eq 3
expect not-a-preset 2 'not-a-preset\.json: format: missing' -- "$lab" render "$src/tests/data/not-a-preset.json" --out "$tmp/x.png"

# --- render -------------------------------------------------------------------------------
expect render-one 0 'a\.png' -- "$lab" render "$phong" --out "$tmp/a.png" --size 64x32
check render-size test "$(png_size "$tmp/a.png")" = "64 32"
cp "$tmp/a.png" "$tmp/keep.png"
expect render-broken-keeps-old-file 2 'difuse' -- "$lab" render "$src/tests/data/broken.json" --out "$tmp/a.png"
check old-file-intact cmp -s "$tmp/a.png" "$tmp/keep.png"
expect render-many 0 'many/05-full-phong\.png' -- "$lab" render "$phong" "$src/presets/01-ambient-only.json" --out "$tmp/many" --size 32x32
check render-many-files test -f "$tmp/many/05-full-phong.png" -a -f "$tmp/many/01-ambient-only.png"
expect render-many-partial 2 'difuse' -- "$lab" render "$phong" "$src/tests/data/broken.json" --out "$tmp/partial" --size 16x16
check render-many-partial-renders-the-good-one test -f "$tmp/partial/05-full-phong.png"
expect render-into-missing-folder 2 'no/such/folder' -- "$lab" render "$phong" --out "$tmp/no/such/folder/a.png"

# --- plot ---------------------------------------------------------------------------------
expect plot 0 'p\.csv' -- "$lab" plot "$phong" --out "$tmp/p.csv"
check plot-header test "$(head -1 "$tmp/p.csv")" = "theta_out_deg,diffuse,specular,total"
check plot-rows test "$(wc -l < "$tmp/p.csv")" -eq 182
check plot-first-row test "$(sed -n 2p "$tmp/p.csv" | cut -d, -f1)" = "-90"
# Full Phong's material: the lobe peaks at the mirror angle of the preset's 45 degrees.
peak=$(tail -n +2 "$tmp/p.csv" | sort -t, -k3 -g | tail -1 | cut -d, -f1)
check plot-peak-at-mirror-angle test "$peak" = "45"
"$lab" plot "$phong" --out "$tmp/p30.csv" --incident-deg 30 >/dev/null
peak=$(tail -n +2 "$tmp/p30.csv" | sort -t, -k3 -g | tail -1 | cut -d, -f1)
check plot-incident-flag test "$peak" = "30"
expect plot-bad-angle 2 'incident-deg' -- "$lab" plot "$phong" --out "$tmp/q.csv" --incident-deg 120
# The preset's term switches apply: a switched-off term is 0 in every row (column 2 diffuse,
# 3 specular), a switched-on one is not.
column_max() { tail -n +2 "$1" | cut -d, -f"$2" | sort -g | tail -1; }
"$lab" plot "$src/presets/01-ambient-only.json" --out "$tmp/ambient.csv" >/dev/null
check plot-ambient-only-diffuse-is-0 test "$(column_max "$tmp/ambient.csv" 2)" = "0"
check plot-ambient-only-specular-is-0 test "$(column_max "$tmp/ambient.csv" 3)" = "0"
check plot-ambient-only-total-is-0 test "$(column_max "$tmp/ambient.csv" 4)" = "0"
"$lab" plot "$src/presets/02-diffuse-only.json" --out "$tmp/diffuse.csv" >/dev/null
check plot-diffuse-only-specular-is-0 test "$(column_max "$tmp/diffuse.csv" 3)" = "0"
check plot-diffuse-only-diffuse-is-not-0 test "$(column_max "$tmp/diffuse.csv" 2)" != "0"
"$lab" plot "$src/presets/04-specular-only.json" --out "$tmp/specular.csv" >/dev/null
check plot-specular-only-diffuse-is-0 test "$(column_max "$tmp/specular.csv" 2)" = "0"
check plot-specular-only-specular-is-not-0 test "$(column_max "$tmp/specular.csv" 3)" != "0"

# --albedo: the albedo of each term against the incident angle, 0 to 89 degrees (90 is undefined).
expect plot-albedo 0 'a\.csv' -- "$lab" plot "$src/presets/02-diffuse-only.json" --albedo "$tmp/a.csv"
check plot-albedo-header test "$(head -1 "$tmp/a.csv")" = "theta_in_deg,diffuse,specular,total,total_r,total_g,total_b"
check plot-albedo-rows test "$(wc -l < "$tmp/a.csv")" -eq 91
check plot-albedo-last-angle test "$(tail -1 "$tmp/a.csv" | cut -d, -f1)" = "89"
# The diffuse-only preset reflects its Kd's luminance at every angle, nothing specular.
kd=$(tail -n +2 "$tmp/a.csv" | cut -d, -f2 | sort -u -g | awk 'NR == 1 { lo = $1 } { hi = $1 } END { print (hi - lo < 1e-5) }')
check plot-albedo-diffuse-constant test "$kd" = "1"
check plot-albedo-specular-is-0 test "$(column_max "$tmp/a.csv" 3)" = "0"
expect plot-both 0 'b\.csv' -- "$lab" plot "$phong" --out "$tmp/b.csv" --albedo "$tmp/c.csv"
check plot-both-writes-out test -s "$tmp/b.csv"
check plot-both-writes-albedo test -s "$tmp/c.csv"
expect plot-needs-a-file 2 'nothing to write.*--out.*--albedo' -- "$lab" plot "$phong"
expect plot-albedo-empty 2 '^--albedo: must not be empty' -- "$lab" plot "$phong" --albedo ""
expect plot-same-file 2 '^lab plot: --albedo .*d\.csv: --out writes that file too' -- "$lab" plot "$phong" --out "$tmp/d.csv" --albedo "$tmp/./d.csv"
check plot-same-file-nothing-written test ! -e "$tmp/d.csv"
expect plot-albedo-unwritable 2 'lab plot: ' -- "$lab" plot "$phong" --albedo "$tmp/none/x.csv"

# --- plot --figure: SVG, PNG and CSV of one figure (core/plots/figures.h) --------------------------
for fig in lobe overlay attenuation albedo slice; do
  expect "figure-$fig" 0 "f-$fig\.svg" -- "$lab" plot "$phong" --figure $fig --svg "$tmp/f-$fig.svg" --png "$tmp/f-$fig.png" --csv "$tmp/f-$fig.csv"
  check "figure-$fig-svg" grep -q '</svg>' "$tmp/f-$fig.svg"
  check "figure-$fig-png-width" test "$(png_size "$tmp/f-$fig.png" | cut -d' ' -f1)" = 720
  check "figure-$fig-csv" test "$(wc -l < "$tmp/f-$fig.csv")" -gt 50
done
"$lab" plot "$phong" --out "$tmp/lobe-out.csv" --incident-deg 30 --csv "$tmp/lobe-fig.csv" --png "$tmp/lobe2.png" --scale 2 --log >/dev/null
check figure-csv-is-plot-csv cmp -s "$tmp/lobe-out.csv" "$tmp/lobe-fig.csv"
check figure-png-scale-2 test "$(png_size "$tmp/lobe2.png")" = "1440 1000"
expect figure-unknown 2 '--figure: .*(lobe|not in)' -- "$lab" plot "$phong" --figure pie --svg "$tmp/x.svg"
expect figure-scale-range 2 '--scale' -- "$lab" plot "$phong" --png "$tmp/x.png" --scale 20
expect figure-scale-needs-png 2 'scale is the PNG' -- "$lab" plot "$phong" --svg "$tmp/x.svg" --scale 2
expect figure-needs-a-file 2 'choose a figure' -- "$lab" plot "$phong" --figure overlay
expect figure-theme-needs-a-file 2 'choose a figure' -- "$lab" plot "$phong" --theme dark --out "$tmp/x.csv"
expect figure-theme-unknown 2 "^--theme: unknown theme 'sepia': the themes are dark, light" -- "$lab" plot "$phong" --theme sepia --svg "$tmp/x.svg"
# The default theme is light (dark on white); --theme dark paints the dark theme's plot background.
expect figure-theme-dark 0 'f-dark\.svg' -- "$lab" plot "$phong" --theme dark --svg "$tmp/f-dark.svg"
check figure-theme-dark-background grep -q '<rect x="0" y="0" width="720.00" height="500.00" fill="#101014"/>' "$tmp/f-dark.svg"
check figure-theme-light-by-default grep -q '<rect x="0" y="0" width="720.00" height="500.00" fill="#ffffff"/>' "$tmp/f-lobe.svg"
check figure-dashed-curves grep -q 'id="lobe-diffuse".*stroke-dasharray="7.00 5.00"' "$tmp/f-lobe.svg"
expect figure-overlay-angles 0 'f-ov\.csv' -- "$lab" plot "$phong" --figure overlay --overlay-deg 70,40,0 --csv "$tmp/f-ov.csv"
check figure-overlay-angles-used grep -q '^theta_out_deg,total_at_70,total_at_40,total_at_0$' "$tmp/f-ov.csv"
expect figure-overlay-three-angles 2 '--overlay-deg: .*3' -- "$lab" plot "$phong" --figure overlay --overlay-deg 70,40 --csv "$tmp/x.csv"
expect figure-overlay-angle-range 2 '--overlay-deg: .*100' -- "$lab" plot "$phong" --figure overlay --overlay-deg 70,40,100 --csv "$tmp/x.csv"
# "nan" passes every range check (each comparison with NaN is false): refused by name first.
expect figure-overlay-nan 2 '^--overlay-deg: must be a finite number, got nan' -- "$lab" plot "$phong" --figure overlay \
    --overlay-deg nan,10,20 --svg "$tmp/x.svg"
expect figure-scale-nan 2 '^--scale: must be a finite number, got nan' -- "$lab" plot "$phong" --png "$tmp/x.png" --scale nan
expect plot-incident-inf 2 '^--incident-deg: must be a finite number, got inf' -- "$lab" plot "$phong" --out "$tmp/x.csv" \
    --incident-deg inf
check figure-nan-nothing-written test ! -e "$tmp/x.svg" -a ! -e "$tmp/x.png" -a ! -e "$tmp/x.csv"
expect figure-no-such-light 2 'figure attenuation: light 3 does not exist' -- "$lab" plot "$phong" --figure attenuation --light 3 --svg "$tmp/x.svg"
check figure-no-such-light-nothing-written test ! -e "$tmp/x.svg"
expect figure-same-file 2 '^lab plot: --png .*y\.svg: --svg writes that file too \(as .*/y\.svg\) \(nothing was written\)' -- "$lab" plot "$phong" --svg "$tmp/y.svg" --png "$tmp/./y.svg"
expect figure-unwritable 2 'lab plot: .*none' -- "$lab" plot "$phong" --svg "$tmp/none/x.svg"
# The slice (core/plots/slice.h): 91 × 91 rows, θh fastest, for a unit white light (so no --light).
check figure-slice-header test "$(head -1 "$tmp/f-slice.csv")" = "theta_h_deg,theta_d_deg,diffuse,specular,total"
check figure-slice-rows test "$(wc -l < "$tmp/f-slice.csv")" -eq 8282
check figure-slice-order test "$(sed -n '3p;93p' "$tmp/f-slice.csv" | cut -d, -f1,2 | tr '\n' ' ')" = "1,0 0,1 "
check figure-slice-image grep -q '<image id="slice-a" .*href="data:image/png;base64,iVBORw0KGgo' "$tmp/f-slice.svg"
expect figure-slice-no-light 2 '^lab plot: --light is the attenuation figure' -- "$lab" plot "$phong" --figure slice --light 1 --csv "$tmp/x.csv"
expect figure-component-is-the-slices 2 '^lab plot: --component is the slice' -- "$lab" plot "$phong" --figure lobe --component total --svg "$tmp/x.svg"
expect figure-component-unknown 2 '--component: .*not in' -- "$lab" plot "$phong" --figure slice --component shiny --svg "$tmp/x.svg"
check figure-slice-refusals-wrote-nothing test ! -e "$tmp/x.csv" -a ! -e "$tmp/x.svg"

# --- fit: one model fitted to another's specular lobe (core/plots/fit.h) --------------------------
ct=$src/presets/13-cook-torrance-beckmann-schlick.json
expect fit-blinn-phong 0 '^Blinn-Phong: shininess 20\.[0-9]+, specular × [0-9.]+; remaining error' -- \
    "$lab" fit "$ct" --brdf blinn-phong --out "$tmp/fitted.json"
check fit-is-a-preset "$lab" plot "$tmp/fitted.json" --out "$tmp/fitted.csv"
check fit-model-written grep -q '"brdf": "blinn-phong"' "$tmp/fitted.json"
expect fit-says-bound 0 'bound: the ior ended on its largest value, 100' -- \
    "$lab" fit "$phong" --brdf cook-torrance --distribution ggx --out "$tmp/fitted-ct.json"
expect fit-distribution-needs-ct 2 '^lab fit: --distribution is Cook-Torrance' -- \
    "$lab" fit "$phong" --brdf phong --distribution ggx --out "$tmp/y.json"
expect fit-unknown-brdf 2 '^--brdf: .*not in' -- "$lab" fit "$phong" --brdf lambert --out "$tmp/y.json"
expect fit-needs-out 2 '--out' -- "$lab" fit "$phong" --brdf phong
expect fit-nothing-to-fit 2 "^lab fit: .*01-ambient-only\.json: nothing to fit: the preset's specular term is switched off" -- \
    "$lab" fit "$src/presets/01-ambient-only.json" --brdf phong --out "$tmp/y.json"
expect fit-broken-preset 2 'broken\.json: material\.difuse' -- "$lab" fit "$src/tests/data/broken.json" --brdf phong --out "$tmp/y.json"
check fit-refusals-wrote-nothing test ! -e "$tmp/y.json"
cp "$phong" "$tmp/mine.json"
expect fit-never-overwrites-its-input 2 '^lab fit: --out .*mine\.json: is the preset' -- \
    "$lab" fit "$tmp/mine.json" --brdf phong --out "$tmp/mine.json"
check fit-input-intact cmp -s "$phong" "$tmp/mine.json"
# --compare: the fit beside its target, as the lab's compare mode draws them
expect figure-compare-slice 0 'cmp\.svg' -- "$lab" plot "$ct" --compare "$tmp/fitted.json" --figure slice --svg "$tmp/cmp.svg"
check figure-compare-slice-has-b grep -q '<image id="slice-b" ' "$tmp/cmp.svg"
check fit-is-named-as-a-fit grep -q '"name": ".* (Blinn-Phong fit)"' "$tmp/fitted.json"
expect figure-compare-not-overlay 2 '^lab plot: --compare draws B in the lobe, albedo and slice figures, not in --figure overlay' -- \
    "$lab" plot "$ct" --compare "$tmp/fitted.json" --figure overlay --svg "$tmp/x.svg"
expect figure-compare-broken 2 'broken\.json: material\.difuse' -- "$lab" plot "$ct" --compare "$src/tests/data/broken.json" --svg "$tmp/x.svg"
check figure-compare-refusals-wrote-nothing test ! -e "$tmp/x.svg"

# --- render --sweep: one preset as a labelled grid (core/scene/sweep.h) ---------------------------
shin=$src/presets/06-shininess-10.json
expect sweep-grid 0 'grid\.png' -- "$lab" render "$shin" --sweep material.shininess=10,20,30,50 \
    --sweep material.specular=0.2,0.5,1 --size 48x40 --out "$tmp/grid.png"
read -r gw gh < <(png_size "$tmp/grid.png")
check sweep-grid-holds-the-cells test "$gw" -gt $((4 * 48)) -a "$gh" -gt $((3 * 40)) -a "$gw" -lt $((4 * 48 + 400))
expect sweep-no-equals 2 '^lab render: --sweep "shininess": expected KEY=V1,V2,\.\.\.' -- \
    "$lab" render "$shin" --sweep shininess --out "$tmp/s.png"
expect sweep-unknown-key 2 '^lab render: --sweep material\.shinyness: unknown key \(did you mean "material\.shininess"\?\)' -- \
    "$lab" render "$shin" --sweep material.shinyness=1,2 --out "$tmp/s.png"
expect sweep-out-of-range 2 '^lab render: --sweep material\.shininess=-1: must be in \[0\.001, 1000000\], got -1$' -- \
    "$lab" render "$shin" --sweep material.shininess=10,-1 --out "$tmp/s.png"
expect sweep-triplet-out-of-range 2 'material\.specular=2: material\.specular\[0\]: must be in \[0, 1\], got 2' -- \
    "$lab" render "$shin" --sweep material.specular=2 --out "$tmp/s.png"
expect sweep-empty-value 2 'value 2 is empty' -- "$lab" render "$shin" --sweep material.shininess=1,,2 --out "$tmp/s.png"
expect sweep-too-many-values 2 'at most 10 values, got 11' -- \
    "$lab" render "$shin" --sweep material.shininess=1,2,3,4,5,6,7,8,9,10,11 --out "$tmp/s.png"
expect sweep-three-keys 2 'one or two keys.*got 3' -- "$lab" render "$shin" --sweep material.shininess=1 \
    --sweep material.specular=1 --sweep material.diffuse=1 --out "$tmp/s.png"
expect sweep-same-key 2 'material\.shininess: the same key twice' -- "$lab" render "$shin" \
    --sweep material.shininess=1 --sweep material.shininess=2 --out "$tmp/s.png"
expect sweep-model 2 'model\.scale: not a key a sweep varies' -- "$lab" render "$shin" --sweep model.scale=1,2 --out "$tmp/s.png"
expect sweep-needs-out 2 '--out' -- "$lab" render "$shin" --sweep material.shininess=1,2
expect sweep-one-preset 2 '--sweep renders one preset, got 2' -- "$lab" render "$shin" "$phong" \
    --sweep material.shininess=1,2 --out "$tmp/s.png"
expect sweep-key-without-flag 2 'got 2 \("material\.specular=1,2" looks like KEY=V1,V2,\.\.\.: give each its own --sweep\)' -- \
    "$lab" render "$shin" --sweep material.shininess=1,2 material.specular=1,2 --out "$tmp/s.png"
expect sweep-plot-key 2 'plot\.incident_deg: changes no render' -- "$lab" render "$shin" --sweep plot.incident_deg=10,80 --out "$tmp/s.png"
expect sweep-too-large 2 'the grid would be [0-9]+x[0-9]+ pixels' -- "$lab" render "$shin" \
    --sweep material.shininess=1,2,3 --size 8000x8000 --out "$tmp/s.png"
check sweep-nothing-written test ! -e "$tmp/s.png"
out=$("$lab" render "$shin" --sweep "material.${esc}[2J=1" --out "$tmp/s.png" 2>&1)
check sweep-escaped-key grep -qF 'material.\x1B[2J: not a preset key' <<<"$out"

# --- check --------------------------------------------------------------------------------
mkdir -p "$tmp/golden" "$tmp/plain"
# The shipped preset carries a sweep; these cases are about its render and plot alone.
python3 -c 'import json, sys; p = json.load(open(sys.argv[1])); del p["sweep"]; json.dump(p, open(sys.argv[2], "w"))' \
    "$phong" "$tmp/plain/05-full-phong.json"
cphong=$tmp/plain/05-full-phong.json
expect check-missing-golden 1 'MISSING +05-full-phong' -- "$lab" check "$cphong" --golden "$tmp/golden" --report "$tmp/report" --size 64x64
expect check-update 0 'CREATED +05-full-phong' -- "$lab" check "$cphong" --golden "$tmp/golden" --update --size 64x64
expect check-pass 0 'PASS +05-full-phong +max 0 +mean 0\.000' -- "$lab" check "$cphong" --golden "$tmp/golden" --report "$tmp/report" --size 64x64
expect check-max-mean-nan 2 '^--max-mean: must be a finite number, got nan' -- "$lab" check "$cphong" --golden "$tmp/golden" \
    --max-mean nan --size 64x64
expect check-max-failing-nan 2 '^--max-failing: must be a finite number, got -nan' -- "$lab" check "$cphong" \
    --golden "$tmp/golden" --max-failing -nan --size 64x64
expect check-summary 0 '^1 passed, 0 failed$' -- "$lab" check "$cphong" --golden "$tmp/golden" --report "$tmp/report" --size 64x64
# A golden of another picture under this name: the check fails and leaves actual and diff images.
"$lab" render "$src/presets/01-ambient-only.json" --out "$tmp/golden/05-full-phong.png" --size 64x64 >/dev/null
expect check-differs 1 'FAIL +05-full-phong' -- "$lab" check "$cphong" --golden "$tmp/golden" --report "$tmp/report" --size 64x64
check check-writes-actual test -f "$tmp/report/05-full-phong.actual.png"
check check-writes-diff test -f "$tmp/report/05-full-phong.diff.png"
check check-writes-report grep -q 'FAIL' "$tmp/report/report.txt"
expect check-size-mismatch 1 'size 32x32 vs golden 64x64' -- "$lab" check "$cphong" --golden "$tmp/golden" --report "$tmp/report" --size 32x32
expect check-no-golden-folder 2 'no such folder' -- "$lab" check "$cphong" --golden "$tmp/none"
expect check-broken-preset 2 'ERROR +broken' -- "$lab" check "$src/tests/data/broken.json" --golden "$tmp/golden" --report "$tmp/report"

# --- check: reports, per-preset tolerances, plot and sweep goldens (issue 23) ---------------
# JSON edits with Python's json module (cli_lib.sh): edit FILE OUT 'p["material"]["shininess"] = 33'
g=$tmp/g23
r=$tmp/r23
mkdir -p "$g" "$tmp/page"
weird="$tmp/a<b & \"c\" 'd'.json" # a name that XML and HTML must escape
cp "$cphong" "$weird"
expect check-update-plots 0 'CREATED +05-full-phong\.plot' -- "$lab" check "$cphong" "$weird" --golden "$g" --update --plots --size 64x64
check check-plot-golden-is-plot-csv test "$(head -1 "$g/05-full-phong.plot.csv")" = "theta_out_deg,diffuse,specular,total"
"$lab" render "$src/presets/01-ambient-only.json" --out "$g/05-full-phong.png" --size 64x64 >/dev/null
expect check-report-run 1 '^3 passed, 1 failed$' -- "$lab" check "$cphong" "$weird" --golden "$g" --report "$r" \
    --junit "$tmp/j.xml" --html "$tmp/page/p.html" --size 64x64
# The JUnit file, read by a real XML parser: four cases, the one failure with its figures.
junit_py='
import sys, xml.etree.ElementTree as ET
suite = ET.parse(sys.argv[1]).getroot().find("testsuite")
cases = suite.findall("testcase")
assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("4", "1", "0"), suite.attrib
names = [c.get("name") for c in cases]
assert names == ["05-full-phong", "05-full-phong.plot", "a<b & \"c\" \x27d\x27", "a<b & \"c\" \x27d\x27.plot"], names
failed = [c for c in cases if c.find("failure") is not None]
assert [c.get("name") for c in failed] == ["05-full-phong"], [c.get("name") for c in failed]
failure = failed[0].find("failure")
assert "over tolerance" in failure.get("message") and "max_mean 0.5 [command line]" in failure.get("message"), failure.get("message")
assert "max_mean 0.5 [command line]" in failure.text, failure.text
'
check check-junit-parses python3 -c "$junit_py" "$tmp/j.xml"
# The pages: every image and link names a file that exists; the name is escaped, never raw.
html_py='
import os, sys, urllib.parse
from html.parser import HTMLParser
page = sys.argv[1]
class Links(HTMLParser):
    def __init__(self):
        super().__init__(); self.files = []
    def handle_starttag(self, tag, attrs):
        for k, v in attrs:
            if k in ("src", "href"): self.files.append(v)
links = Links(); text = open(page).read(); links.feed(text)
assert len(links.files) >= 6, links.files
for f in links.files:
    # resolved as a browser resolves a relative link: lexically, from the path the page was opened by
    path = os.path.normpath(os.path.join(os.path.dirname(page), urllib.parse.unquote(f)))
    assert os.path.isfile(path), path
assert "a&lt;b &amp; &quot;c&quot; &apos;d&apos;" in text and "a<b" not in text
assert text.index("05-full-phong.golden.png") < text.index("a&lt;b")  # failures first
'
check check-html-in-report python3 -c "$html_py" "$r/index.html"
check check-html-elsewhere python3 -c "$html_py" "$tmp/page/p.html"
check check-report-keeps-golden test -f "$r/05-full-phong.golden.png" -a -f "$r/05-full-phong.diff.png"

# Per-preset tolerances change the verdict both ways. tol.json's golden is the same sphere with
# shininess 33: within the default tolerance, not within a strict one the preset sets.
edit "$cphong" "$tmp/tol-golden.json" 'p["material"]["shininess"] = 33'
"$lab" render "$tmp/tol-golden.json" --out "$g/tol.png" --size 64x64 >/dev/null
cp "$cphong" "$tmp/tol.json"
expect check-default-tolerance-passes 0 'PASS +tol ' -- "$lab" check "$tmp/tol.json" --golden "$g" --report "$r" --size 64x64
edit "$cphong" "$tmp/tol.json" 'p["check"] = {"pixel_tolerance": 0, "max_failing": 0, "max_mean": 0}'
expect check-preset-tolerance-fails 1 'FAIL +tol .*' -- "$lab" check "$tmp/tol.json" --golden "$g" --report "$r" --size 64x64
check check-report-names-preset-tolerance grep -q 'pixel_tolerance 0 \[preset\]' "$r/index.html"
# ...and the other way: a golden of another picture passes where the preset allows anything.
"$lab" render "$src/presets/01-ambient-only.json" --out "$g/tol.png" --size 64x64 >/dev/null
expect check-default-tolerance-fails 1 'FAIL +tol ' -- "$lab" check "$cphong" "$tmp/tol.json" --golden "$g" --report "$r" --size 64x64
edit "$cphong" "$tmp/tol.json" 'p["check"] = {"pixel_tolerance": 255, "max_mean": 255}'
expect check-preset-tolerance-passes 0 'PASS +tol ' -- "$lab" check "$tmp/tol.json" --golden "$g" --report "$r" --size 64x64
edit "$cphong" "$tmp/tol.json" 'p["check"] = {"pixel_tolerance": -1}'
expect check-negative-tolerance 2 'tol\.json: check\.pixel_tolerance: must be from 0 to 255, got -1' -- \
    "$lab" check "$tmp/tol.json" --golden "$g" --report "$r" --size 64x64

# Plot goldens: one value changed fails, naming its line and column; a looser tolerance passes.
cp "$g/05-full-phong.plot.csv" "$tmp/plot.keep"
awk -F, -v OFS=, 'NR == 50 { $3 = $3 + 0.001 } { print }' "$tmp/plot.keep" >"$g/05-full-phong.plot.csv"
expect check-plot-differs 1 'FAIL +05-full-phong\.plot +line 50 \(theta_out_deg -42\), column specular' -- \
    "$lab" check "$cphong" --golden "$g" --report "$r" --size 64x64
expect check-plot-tolerance 0 'PASS +05-full-phong\.plot' -- \
    "$lab" check "$cphong" --golden "$g" --report "$r" --size 64x64 --plot-tolerance 0.01 --pixel-tolerance 255 --max-mean 255
printf 'theta_out_deg,diffuse\n-90,zero\n' >"$g/05-full-phong.plot.csv"
expect check-plot-not-csv 2 'ERROR +05-full-phong\.plot: golden .*05-full-phong\.plot\.csv is not a CSV of numbers: line 2, column 2: "zero" is not a number' -- \
    "$lab" check "$cphong" --golden "$g" --report "$r" --size 64x64
cp "$tmp/plot.keep" "$g/05-full-phong.plot.csv"

# Sweep goldens: written by --update, compared cell by cell; one changed value fails its cell only.
edit "$cphong" "$tmp/sw.json" 'p["sweep"] = ["material.shininess=8,32,128"]'
expect check-sweep-update 0 'CREATED +sw\.sweep' -- "$lab" check "$tmp/sw.json" --golden "$g" --update --size 64x64 --sweep-size 48x48
expect check-sweep-passes 0 'PASS +sw\.sweep\[material\.shininess=128\]' -- \
    "$lab" check "$tmp/sw.json" --golden "$g" --report "$r" --size 64x64 --sweep-size 48x48
edit "$cphong" "$tmp/sw.json" 'p["sweep"] = ["material.shininess=8,32,2"]'
out=$("$lab" check "$tmp/sw.json" --golden "$g" --report "$r" --size 64x64 --sweep-size 48x48 2>&1)
rc=$?
check check-sweep-cell-fails test $rc -eq 1
check check-sweep-failing-cell grep -q '^FAIL  *sw\.sweep\[material\.shininess=2\]' <<<"$out"
check check-sweep-other-cells-pass test "$(grep -c '^PASS  *sw\.sweep\[' <<<"$out")" -eq 2
check check-sweep-cell-images test -f "$r/sw.sweep.r0c2.actual.png" -a -f "$r/sw.sweep.r0c2.golden.png"
check check-sweep-cell-size test "$(png_size "$r/sw.sweep.r0c2.actual.png")" = "48 48"
edit "$cphong" "$tmp/sw.json" 'p["sweep"] = ["material.shinines=8"]'
expect check-sweep-bad-key 2 'sw\.json: sweep: material\.shinines: unknown key \(did you mean "material\.shininess"\?\)' -- \
    "$lab" check "$tmp/sw.json" --golden "$g" --report "$r" --size 64x64
check check-sweep-bad-key-is-an-error-case grep -q '^ERROR  *sw\.sweep: sweep: material\.shinines' "$r/report.txt"

# The README's CI line: --junit inside a report folder that does not exist yet.
rm -rf "$tmp/r-new"
expect check-junit-in-new-report 1 '^1 passed, 1 failed$' -- \
    "$lab" check "$cphong" --golden "$g" --report "$tmp/r-new" --junit "$tmp/r-new/junit.xml" --size 64x64
check check-junit-in-new-report-written test -s "$tmp/r-new/junit.xml" -a -s "$tmp/r-new/index.html"
# --html in a folder reached through a symbolic link: its links are relative to the path as opened.
mkdir -p "$tmp/real/a/b"
ln -s "$tmp/real/a/b" "$tmp/link"
"$lab" render "$src/presets/01-ambient-only.json" --out "$g/05-full-phong.png" --size 64x64 >/dev/null
"$lab" check "$cphong" "$weird" --golden "$g" --report "$tmp/r-link" --html "$tmp/link/p.html" --size 64x64 >/dev/null 2>&1
check check-html-through-a-link python3 -c "$html_py" "$tmp/link/p.html"
"$lab" check "$cphong" --golden "$g" --update --size 64x64 >/dev/null
expect check-junit-is-report-txt 2 '^lab check: --junit .*report\.txt: --report writes that file too' -- \
    "$lab" check "$cphong" --golden "$g" --report "$r" --junit "$r/report.txt"
mkdir -p "$tmp/dup"
cp "$cphong" "$tmp/dup/05-full-phong.json"
expect check-two-presets-one-name 2 'would both be checked against 05-full-phong\.png' -- \
    "$lab" check "$cphong" "$tmp/dup/05-full-phong.json" --golden "$g" --report "$r"
cp "$cphong" "$tmp/dup/x.sweep.json"
expect check-preset-named-like-a-sweep-golden 2 'x\.sweep\.json: a preset named \*\.sweep\.json would share its golden' -- \
    "$lab" check "$tmp/dup/x.sweep.json" --golden "$g" --report "$r"

# The orphan-golden check knows every golden name.
mkdir -p "$tmp/orphans"
touch "$tmp/orphans/12-blinn-phong.sweep.png"
expect orphan-sweep-golden 1 '12-blinn-phong\.sweep\.png \(12-blinn-phong\.json has no "sweep"\)' -- \
    cmake -DGOLDEN="$tmp/orphans" -DPRESETS="$src/presets" -P "$src/tests/check_goldens.cmake"
rm "$tmp/orphans/12-blinn-phong.sweep.png"
touch "$tmp/orphans/05-full-phong.plot.csv" "$tmp/orphans/05-full-phong.png"
expect goldens-with-presets 0 '2 goldens, each with its preset' -- \
    cmake -DGOLDEN="$tmp/orphans" -DPRESETS="$src/presets" -P "$src/tests/check_goldens.cmake"
touch "$tmp/orphans/off.png" "$tmp/orphans/no.plot.csv" # names CMake reads as false
expect orphans-named-false 1 'off\.png \(no preset off\.json\)' -- \
    cmake -DGOLDEN="$tmp/orphans" -DPRESETS="$src/presets" -P "$src/tests/check_goldens.cmake"

# Report files that could not be written are refused first; nothing is written.
rm -rf "$tmp/r-none"
expect check-junit-no-folder 2 '^lab check: --junit .*/none/j\.xml: no such folder' -- \
    "$lab" check "$cphong" --golden "$g" --report "$tmp/r-none" --junit "$tmp/none/j.xml"
check check-junit-nothing-written test ! -e "$tmp/r-none"
expect check-html-is-folder 2 '^lab check: --html .*: is a folder' -- "$lab" check "$cphong" --golden "$g" --html "$tmp"
expect check-html-same-as-junit 2 '^lab check: --html .*x\.xml: --junit writes that file too' -- \
    "$lab" check "$cphong" --golden "$g" --junit "$tmp/x.xml" --html "$tmp/x.xml"
check check-same-file-nothing-written test ! -e "$tmp/x.xml"

# --- views (issue 26): lab render --view, its options, a preset's check.views -----------------
ct=$src/presets/13-cook-torrance-beckmann-schlick.json
expect view-unknown 2 '^lab render: --view: no view "dd" \(did you mean "d"\?\); the views are lit, ' -- \
    "$lab" render "$ct" --out "$tmp/v.png" --view dd
expect view-not-for-phong 2 '05-full-phong\.json: --view d: d is a Cook-Torrance factor; this preset.s BRDF is phong' -- \
    "$lab" render "$phong" --out "$tmp/v.png" --view d
check view-not-for-phong-nothing-written test ! -e "$tmp/v.png"
expect view-range-order 2 '^lab render: --range: LO must be less than HI, got "1,0"' -- \
    "$lab" render "$ct" --out "$tmp/v.png" --view d --range 1,0
expect view-range-syntax 2 '^lab render: --range: expected LO,HI \(two numbers\), got "1"' -- \
    "$lab" render "$ct" --out "$tmp/v.png" --view d --range 1
expect view-range-nan 2 '--range: expected LO,HI' -- "$lab" render "$ct" --out "$tmp/v.png" --view d --range nan,1
expect view-palette 2 '^lab render: --palette: expected viridis or grey, got "jet"' -- \
    "$lab" render "$ct" --out "$tmp/v.png" --view d --palette jet
expect view-light-zero 2 '--light' -- "$lab" render "$ct" --out "$tmp/v.png" --view d --light 0
expect view-light-missing 2 '--view d: there is no light 3 \(the preset has 1 light\)' -- \
    "$lab" render "$ct" --out "$tmp/v.png" --view d --light 3
expect view-light-on-lit 2 '^lab render: --light applies to a factor view .*not to --view lit' -- \
    "$lab" render "$ct" --out "$tmp/v.png" --light 1
expect view-range-on-normals 2 '^lab render: --palette, --range and --legend apply to a value view .*not to --view normals' -- \
    "$lab" render "$ct" --out "$tmp/v.png" --view normals --range 0,1
check view-refused-nothing-written test ! -e "$tmp/v.png"
expect view-distance-directional 2 '--view distance: light 1 is directional: it has no distance' -- \
    "$lab" render "$src/presets/22-sunlight.json" --out "$tmp/v.png" --view distance
# The automatic range is printed, and giving it back as --range draws the same picture.
out=$("$lab" render "$ct" --out "$tmp/d.png" --size 96x96 --view d --palette grey 2>&1)
check view-auto-range-printed grep -Eq 'd\.png: D: microfacet distribution, light 1: automatic range [0-9.e+-]+,[0-9.e+-]+$' <<<"$out"
range=$(sed -nE 's/.*automatic range ([^ ]+)$/\1/p' <<<"$out")
expect view-fixed-range 0 'd2\.png' -- "$lab" render "$ct" --out "$tmp/d2.png" --size 96x96 --view d --palette grey --range "$range"
check view-fixed-range-same-picture cmp -s "$tmp/d.png" "$tmp/d2.png"
expect view-legend 0 'dl\.png' -- "$lab" render "$ct" --out "$tmp/dl.png" --size 256x256 --view d --legend
check view-legend-adds-a-band test "$(png_size "$tmp/dl.png")" = "256 304"
expect view-sweep 0 'all cells' -- "$lab" render "$ct" --out "$tmp/ds.png" --size 64x64 --view d \
    --sweep cook_torrance.roughness=0.2,0.4
expect view-sweep-not-for-a-cell 2 'cell .*--view d: d is a Cook-Torrance factor' -- \
    "$lab" render "$ct" --out "$tmp/ds2.png" --size 64x64 --view d --sweep brdf=cook-torrance,phong
# check.views: read, refused with their JSON path, compared with <name>.<view>.png.
mkdir -p "$tmp/views"
sed 's/"format": "lighting-lab-preset"/"check": {"views": ["dd"]}, "format": "lighting-lab-preset"/' "$phong" >"$tmp/views/bad.json"
expect check-views-unknown 2 'bad\.json: check\.views\[0\]: no view "dd" \(did you mean "d"\?\)' -- \
    "$lab" render "$tmp/views/bad.json" --out "$tmp/v.png"
sed 's/"format": "lighting-lab-preset"/"check": {"views": ["n-dot-l", {"view": "d"}]}, "format": "lighting-lab-preset"/' "$phong" >"$tmp/views/p.json"
expect check-views-not-for-phong 2 'p\.json: check\.views\[1\]: d is a Cook-Torrance factor' -- \
    "$lab" check "$tmp/views/p.json" --golden "$tmp/views/g" --report "$tmp/views/r" --update --size 64x64
check check-views-the-others-still-written test -s "$tmp/views/g/p.n-dot-l.png"
# 13 lists d, f and g: each is written, then compared.
expect check-views-update 0 '' -- "$lab" check "$ct" --golden "$tmp/views/g" --report "$tmp/views/r" --update --size 64x64
check check-views-golden-written test -s "$tmp/views/g/13-cook-torrance-beckmann-schlick.d.png" -a \
    -s "$tmp/views/g/13-cook-torrance-beckmann-schlick.g.png"
expect check-views-pass 0 '4 passed, 0 failed' -- "$lab" check "$ct" --golden "$tmp/views/g" --report "$tmp/views/r" --size 64x64
cp "$tmp/views/g/13-cook-torrance-beckmann-schlick.png" "$tmp/views/g/13-cook-torrance-beckmann-schlick.d.png"
expect check-views-fail 1 'FAIL +13-cook-torrance-beckmann-schlick\.d ' -- \
    "$lab" check "$ct" --golden "$tmp/views/g" --report "$tmp/views/r" --size 64x64

# --- exercises (presets/exercises/, tests/exercises/) and lab share --------------------------
# Every bundled exercise: its worked solution (tests/exercises/<name>.solution.json) solves it,
# its start does not, and it is linked by name. json_start writes an exercise's start as a preset.
json_start() {
    python3 -c 'import json, sys
e = json.load(open(sys.argv[1], encoding="utf-8"))
p = {"format": "lighting-lab-preset", "version": 1}
p.update({k: v for k, v in e["start"].items() if k not in ("format", "version")})
json.dump(p, open(sys.argv[2], "w", encoding="utf-8"))' "$@"
}
exercises=$src/presets/exercises
solutions=$src/tests/exercises
base=https://example.org/lab/
count=0
for ex in "$exercises"/*.json; do
    [[ -e $ex ]] || continue
    n=$(basename "$ex" .json)
    count=$((count + 1))
    if [[ -f $solutions/$n.solution.json ]]; then
        expect "exercise-$n-solved" 0 "$n\.solution\.json: Solved: score 100%$" -- "$lab" exercise check "$ex" "$solutions/$n.solution.json"
    else
        echo "FAIL exercise-$n-has-a-solution: no tests/exercises/$n.solution.json"; failed=$((failed + 1))
    fi
    json_start "$ex" "$tmp/$n.start.json"
    expect "exercise-$n-start-scores-0" 1 "$n\.start\.json: Score 0%: not solved yet" -- \
        "$lab" exercise check "$ex" "$tmp/$n.start.json"
    link=$("$lab" share "$ex" --base "$base" 2>/dev/null)
    check "exercise-$n-linked-by-name" test "$link" = "$base#exercise=$n"
done
check exercises-at-least-8 test "$count" -ge 8
for sol in "$solutions"/*.solution.json; do
    [[ -e $sol ]] || continue
    n=$(basename "$sol" .solution.json)
    check "exercise-solution-$n-has-its-exercise" test -f "$exercises/$n.json"
done

# Near misses stay unsolved: the exercises' own tolerances are not so loose that a visibly
# different answer passes (the image, or a field tolerance where the image cannot tell).
near() { # near NAME PATTERN EXERCISE PYTHON: the exercise's solution edited by PYTHON scores exit 1
    edit "$solutions/$3.solution.json" "$tmp/near.json" "$4"
    expect "exercise-near-miss-$1" 1 "$2" -- "$lab" exercise check "$exercises/$3.json" "$tmp/near.json"
}
unsolved='Score [0-9]{1,2}%: not solved yet'
near shininess-50 "$unsolved" 02-shininess 'p["material"]["shininess"] = 50'
near attenuation-field 'lights\[0\]\.attenuation is 0\.1 away \(at most 0\.05\)' 05-attenuation \
    'p["lights"][0]["attenuation"] = [0, 0.1, 0.9]'
near spot-cutoff-32 "$unsolved" 06-spot-light 'p["lights"][0]["cutoff_deg"] = 32'
near roughness-0.2 "$unsolved" 07-cook-torrance-roughness 'p["cook_torrance"]["roughness"] = 0.2'
near ior-1.8 "$unsolved" 08-fresnel 'p["cook_torrance"]["ior"] = 1.8'
near fitted-shininess-27 "$unsolved" 09-blinn-phong-for-beckmann 'p["material"]["shininess"] = 27'
near slice-roughness-0.3 "$unsolved" 10-roughness-from-the-slice 'p["cook_torrance"]["roughness"] = 0.3'
# The score is a progress (core/exercise/score.h): part of the way from the start (n = 8) to the
# target (n = 80) scores between the two, neither 0% nor 100%.
near shininess-30-part-way 'Score ([1-9]|[1-9][0-9])%: not solved yet' 02-shininess 'p["material"]["shininess"] = 30'

# A field the exercise does not open, changed: refused with its JSON path. The camera is always free.
shin=$exercises/02-shininess.json
shin_sol=$solutions/02-shininess.solution.json
edit "$shin_sol" "$tmp/locked.json" 'p["background"] = [1, 1, 1]'
expect exercise-locked-field 2 'locked\.json: background: changed from the exercise.s start, but the exercise does not open this field \(open: material\.shininess\)' -- \
    "$lab" exercise check "$shin" "$tmp/locked.json"
edit "$shin_sol" "$tmp/camera.json" 'p["camera"] = {"eye": [1.5, 0.5, 6], "fovy_deg": 30}'
expect exercise-camera-is-free 0 'camera\.json: Solved' -- "$lab" exercise check "$shin" "$tmp/camera.json"

# Bad exercise files: refused with the JSON path of the problem.
edit "$shin" "$tmp/open.json" 'p["open"] = ["material.shinyness"]'
expect exercise-unknown-open 2 'open\.json: open\[0\]: no field "material\.shinyness" in a preset \(did you mean "material\.shininess"\?\)' -- \
    "$lab" exercise check "$tmp/open.json" "$shin_sol"
edit "$shin" "$tmp/locked-target.json" 'p["target"]["material"]["diffuse"] = [1, 0, 0]'
expect exercise-target-differs-in-locked-field 2 'locked-target\.json: target\.material\.diffuse: differs from start, but the field is not open' -- \
    "$lab" exercise check "$tmp/locked-target.json" "$shin_sol"
edit "$shin" "$tmp/tolerance.json" 'p["tolerance"] = {"max_failing": 2}'
expect exercise-bad-tolerance 2 'tolerance\.json: tolerance\.max_failing: expected a share from 0 to 1' -- \
    "$lab" exercise check "$tmp/tolerance.json" "$shin_sol"
expect exercise-preset-as-exercise 2 '05-full-phong\.json: format: .*\(this is a preset, not an exercise\)' -- \
    "$lab" exercise check "$phong" "$shin_sol"
edit "$shin" "$tmp/untitled.json" 'del p["title"]'
expect exercise-missing-title 2 'untitled\.json: title: missing' -- "$lab" exercise check "$tmp/untitled.json" "$shin_sol"

# lab share: the printed link, and the same text in its QR code (zbarimg reads it back; CI installs
# zbar-tools). Bundled files are linked by name, others carry the scene (z=, x=).
has_zbarimg() { command -v zbarimg >/dev/null; }
check zbarimg-installed has_zbarimg
qr_text() { zbarimg --raw -q "$1" 2>/dev/null; }
share_case() { # share_case NAME FILE EXPECTED_LINK_REGEX: link printed, QR written and read back
    local link
    link=$("$lab" share "$2" --base "$base" --qr "$tmp/$1.png" 2>/dev/null)
    check "share-$1-status" test $? -eq 0
    check "share-$1-link" matches "$link" "$3"
    check "share-$1-qr-png" is_png "$tmp/$1.png"
    check "share-$1-qr-reads-back" test "$(qr_text "$tmp/$1.png")" = "$link"
}
share_case exercise "$shin" 'https://example\.org/lab/#exercise=02-shininess'
share_case preset "$phong" 'https://example\.org/lab/#preset=05-full-phong'
cp "$phong" "$tmp/mine.json"
share_case own-preset "$tmp/mine.json" 'https://example\.org/lab/#z=[A-Za-z0-9_-]+'
cp "$shin" "$tmp/own-exercise.json"
expect share-own-exercise 0 '^https://example\.org/lab/#x=[A-Za-z0-9_-]+$' -- "$lab" share "$tmp/own-exercise.json" --base "$base"
expect share-bad-base 2 '^lab share: --base: expected the course page.s address' -- \
    "$lab" share "$phong" --base ftp://x --qr "$tmp/ftp.png"
check share-bad-base-no-png test ! -e "$tmp/ftp.png"
# 3000 characters of varied text do not deflate away: too long for a QR code, and no PNG.
python3 -c 'import json, random, sys
r = random.Random(7)
words = ["".join(r.choice("abcdefghijklmnopqrstuvwxyz") for _ in range(r.randint(2, 9))) for _ in range(400)]
text = " ".join(r.choice(words) for _ in range(600))[:3000]
p = json.load(open(sys.argv[1])); p["description"] = text; json.dump(p, open(sys.argv[2], "w"))' "$phong" "$tmp/long.json"
check share-long-description-is-3000 python3 -c 'import json, sys; assert len(json.load(open(sys.argv[1]))["description"]) == 3000' "$tmp/long.json"
expect share-too-long 2 'long\.json: the link is too long for a QR code' -- "$lab" share "$tmp/long.json" --base "$base" --qr "$tmp/long.png"
check share-too-long-no-png test ! -e "$tmp/long.png"

differ() { ! cmp -s "$1" "$2"; } # two files that are not the same bytes
# --- the lecture (issue 50): a prepared comparison renders as compare mode, decks are not presets ----
wrong=$src/presets/19-normal-matrix-wrong.json
edit "$wrong" "$tmp/prepared.json" 'p["compare"] = {"normal_matrix": "inverse-transpose"}'
expect render-prepared-comparison 0 'prepared\.png' -- "$lab" render "$tmp/prepared.json" --out "$tmp/prepared.png" --size 400x240
check prepared-comparison-size test "$(png_size "$tmp/prepared.png")" = "400 240"
edit "$wrong" "$tmp/same.json" 'p["compare"] = {}'
"$lab" render "$tmp/same.json" --out "$tmp/same.png" --size 400x240 >/dev/null
check prepared-comparison-b-differs differ "$tmp/prepared.png" "$tmp/same.png"
"$lab" render "$wrong" --out "$tmp/alone.png" --size 400x240 >/dev/null
check a-preset-without-compare-is-one-render differ "$tmp/alone.png" "$tmp/same.png"
edit "$wrong" "$tmp/bad-compare.json" 'p["compare"] = {"normal_matrix": "inverse", "shinyness": 3}'
expect render-bad-compare 2 'bad-compare\.json: compare\.normal_matrix: .*inverse' -- "$lab" render "$tmp/bad-compare.json" --out "$tmp/bad.png"
expect render-bad-compare-every-problem 2 'compare\.shinyness: unknown key' -- "$lab" render "$tmp/bad-compare.json" --out "$tmp/bad.png"
check bad-compare-nothing-written test ! -e "$tmp/bad.png"
expect render-a-deck 2 'format: expected "lighting-lab-preset", got "lighting-lab-deck" \(this is a deck, not a preset\)' -- \
    "$lab" render "$src/presets/decks/lecture.json" --out "$tmp/deck.png"
edit "$phong" "$tmp/display.json" 'p["display"] = {"view": "n-dot-q"}'
expect render-bad-display 2 'display\.view: no view "n-dot-q"' -- "$lab" render "$tmp/display.json" --out "$tmp/d.png"
expect deck-and-preset 2 'excludes' -- "$lab" --deck "$src/presets/decks/lecture.json" --preset "$phong"

finish
