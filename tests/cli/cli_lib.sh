# cli_lib.sh — what the command-line tests share (sourced by run_cli_tests.sh and
# hostile_cli_tests.sh, each run as LAB SOURCE_DIR): a scratch folder, the assertions and their
# count, a few readers of files. `finish` prints the count and returns the suite's status.
lab=$(realpath "$1") # absolute: a test may change folders
src=$(realpath "$2")
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

# edit IN OUT 'python': OUT is the JSON of IN after the python statements run on it as p.
edit() { python3 -c 'import json, sys; p = json.load(open(sys.argv[1], encoding="utf-8")); exec(sys.argv[3]); json.dump(p, open(sys.argv[2], "w", encoding="utf-8"))' "$@"; }

png_size() { # prints "W H" from a PNG's IHDR
    od -An -tu1 -j16 -N8 "$1" | awk '{print $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'
}
matches() { [[ $1 =~ ^($2)$ ]]; } # matches TEXT REGEX: the whole of TEXT
is_png() { test "$(od -An -tx1 -N8 "$1" | tr -d ' \n')" = 89504e470d0a1a0a; }

finish() {
    echo "$passed passed, $failed failed"
    [[ $failed -eq 0 ]]
}
