#!/usr/bin/env bash
# run_cli_tests.sh LAB SOURCE_DIR — the `lab` command line as a user meets it: exit status,
# messages on stderr, files written (and not written). Run by CTest as the `cli` test.
set -u
lab=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

# expect NAME STATUS PATTERN -- COMMAND...: runs COMMAND, checks its exit status and that its
# output (stdout and stderr together) matches the extended regular expression PATTERN.
expect() {
    local name=$1 status=$2 pattern=$3
    shift 4
    local out rc
    out=$("$@" 2>&1)
    rc=$?
    if [[ $rc -ne $status ]]; then
        echo "FAIL $name: exit status $rc, expected $status"; echo "$out" | sed 's/^/    /'; failed=$((failed + 1)); return
    fi
    if ! grep -Eq -- "$pattern" <<<"$out"; then
        echo "FAIL $name: output does not match /$pattern/"; echo "$out" | sed 's/^/    /'; failed=$((failed + 1)); return
    fi
    echo "ok   $name"
    passed=$((passed + 1))
}

check() { # check NAME CONDITION...: a plain assertion
    local name=$1
    shift
    if "$@"; then echo "ok   $name"; passed=$((passed + 1)); else echo "FAIL $name"; failed=$((failed + 1)); fi
}

png_size() { # prints "W H" from a PNG's IHDR
    od -An -tu1 -j16 -N8 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'
}

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
check invalid-utf8-escaped grep -qF 'invalid JSON: '"'"'"caf\xE9"'"'" <<<"$out"
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
expect plot-same-file 2 'same file' -- "$lab" plot "$phong" --out "$tmp/d.csv" --albedo "$tmp/./d.csv"
check plot-same-file-nothing-written test ! -e "$tmp/d.csv"
expect plot-albedo-unwritable 2 'lab plot: ' -- "$lab" plot "$phong" --albedo "$tmp/none/x.csv"

# --- check --------------------------------------------------------------------------------
mkdir -p "$tmp/golden"
expect check-missing-golden 1 'MISSING +05-full-phong' -- "$lab" check "$phong" --golden "$tmp/golden" --report "$tmp/report" --size 64x64
expect check-update 0 'CREATED +05-full-phong' -- "$lab" check "$phong" --golden "$tmp/golden" --update --size 64x64
expect check-pass 0 'PASS +05-full-phong +max 0 +mean 0\.000' -- "$lab" check "$phong" --golden "$tmp/golden" --report "$tmp/report" --size 64x64
expect check-summary 0 '^1 passed, 0 failed$' -- "$lab" check "$phong" --golden "$tmp/golden" --report "$tmp/report" --size 64x64
# A golden of another picture under this name: the check fails and leaves actual and diff images.
"$lab" render "$src/presets/01-ambient-only.json" --out "$tmp/golden/05-full-phong.png" --size 64x64 >/dev/null
expect check-differs 1 'FAIL +05-full-phong' -- "$lab" check "$phong" --golden "$tmp/golden" --report "$tmp/report" --size 64x64
check check-writes-actual test -f "$tmp/report/05-full-phong.actual.png"
check check-writes-diff test -f "$tmp/report/05-full-phong.diff.png"
check check-writes-report grep -q 'FAIL' "$tmp/report/report.txt"
expect check-size-mismatch 1 'size 32x32 vs golden 64x64' -- "$lab" check "$phong" --golden "$tmp/golden" --report "$tmp/report" --size 32x32
expect check-no-golden-folder 2 'no such folder' -- "$lab" check "$phong" --golden "$tmp/none"
expect check-broken-preset 2 'ERROR +broken' -- "$lab" check "$src/tests/data/broken.json" --golden "$tmp/golden" --report "$tmp/report"

echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
