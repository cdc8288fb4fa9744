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
# edit IN OUT 'python': OUT is the JSON of IN after the python statements run on it as p.
edit() { python3 -c 'import json, sys; p = json.load(open(sys.argv[1], encoding="utf-8")); exec(sys.argv[3]); json.dump(p, open(sys.argv[2], "w", encoding="utf-8"))' "$@"; }
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

finish
