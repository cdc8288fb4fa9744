#!/usr/bin/env bash
# run_package_test.sh BUILD_DIR SOURCE_DIR [DEB] — the Debian package as a course's CI meets it.
#
# Builds lighting-lab_*.deb from BUILD_DIR with CPack into a temporary folder (or takes DEB), then:
# its control fields and Depends (which apt must be able to resolve here: `apt-get -s install`),
# unpacks it into a clean root (dpkg-deb -x), and runs the *installed* `lab check` on the *installed*
# presets against SOURCE_DIR/tests/golden, which must pass. It must also be able to fail: an install
# with a preset missing, and one with presets/models missing, are checked the same way and must fail.
# Run by CTest as the `package` test; by hand: tests/package/run_package_test.sh build .
set -u
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
deb=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0
failed=0

check() { # check NAME CONDITION...
    local name=$1
    shift
    if "$@"; then echo "ok   $name"; passed=$((passed + 1)); else echo "FAIL $name"; failed=$((failed + 1)); fi
}

if [[ -z $deb ]]; then
    if ! cpack --config "$build/CPackConfig.cmake" -B "$tmp/cpack" >"$tmp/cpack.log" 2>&1; then
        echo "FAIL cpack"; sed 's/^/    /' "$tmp/cpack.log"; exit 1
    fi
    deb=$(ls "$tmp"/cpack/lighting-lab_*_amd64.deb 2>/dev/null | head -n 1)
fi
check "the package exists: ${deb##*/}" test -f "$deb"
[[ -f $deb ]] || exit 1

# --- control fields ---------------------------------------------------------------------
field() { dpkg-deb -f "$deb" "$1"; }
check "Package is lighting-lab" test "$(field Package)" = lighting-lab
check "Section is set" test -n "$(field Section)"
check "Maintainer has an address" grep -q '<.*@.*>' <<<"$(field Maintainer)"
check "Description has a long part" test "$(field Description | wc -l)" -gt 2
depends=$(field Depends)
echo "     Depends: $depends"
names=$(tr ',|' '\n\n' <<<"$depends" | sed 's/(.*)//; s/ //g' | sort -u)
# What `lab` links (dpkg-shlibdeps), and Mesa's EGL and software rasterizer for a headless `lab check`.
for needed in libegl-mesa0 libgl1-mesa-dri libegl1 libgles2 libglfw3 libdraco7 libmeshoptimizer2d libstb0 libstdc++6 libc6; do
    check "Depends names $needed" grep -Fqx "$needed" <<<"$names"
done
# Every name in Depends is a package apt knows here (Debian 12), and the whole package resolves.
for name in $names; do
    check "apt knows $name" test -n "$(apt-cache policy "$name" 2>/dev/null | grep -E 'Installed: [^(]|Candidate: [^(]')"
done
resolves() { apt-get -s -q install "$deb" >"$tmp/apt.log" 2>&1 || { sed 's/^/    /' "$tmp/apt.log"; false; }; }
check "apt-get -s install resolves the package" resolves

# --- the installed files ----------------------------------------------------------------
root=$tmp/root
dpkg-deb -x "$deb" "$root"
lab=$root/usr/bin/lab
presets=$root/usr/share/lighting-lab/presets
check "usr/bin/lab is installed" test -x "$lab"
check "the presets are installed" test -f "$presets/05-full-phong.json"
check "the models are installed" test -f "$presets/models/trefoil.glb"
check "the README is installed" test -f "$root/usr/share/doc/lighting-lab/README.md"
check "the exercises are installed" test -f "$presets/exercises/02-shininess.json"
# The installed program knows its shipped exercises: it links them by name, and checks an attempt.
check "lab share links an installed exercise by name" test \
    "$("$lab" share "$presets/exercises/02-shininess.json" --base https://course.example.org/lab/ 2>/dev/null)" \
    = "https://course.example.org/lab/#exercise=02-shininess"
check "lab exercise check solves an installed exercise with its solution" \
    "$lab" exercise check "$presets/exercises/02-shininess.json" "$src/tests/exercises/02-shininess.solution.json"
check "nothing outside /usr" test -z "$(cd "$root" && ls -A | grep -vx usr)"
check "the program carries no debug information" bash -c "! readelf -S '$lab' | grep -q '\.debug_info'"
check "lab --version runs" "$lab" --version

# verify PRESETS_DIR LAB: the installed presets are exactly the goldens' ones, and `lab check`
# passes on them. Its status is what a course's CI would see.
verify() {
    local dir=$1 status=0
    local have want
    have=$(cd "$dir" && ls *.json 2>/dev/null | sed 's/\.json$//' | sort)
    want=$(cd "$src/tests/golden" && ls *.png | sed 's/\.png$//' | grep -v '\.' | sort) # renders, not <name>.sweep.png
    if [[ "$have" != "$want" ]]; then
        echo "     installed presets and goldens differ:"; diff <(echo "$want") <(echo "$have") | sed 's/^/       /'
        return 1
    fi
    (cd "$tmp" && "$lab" check "$dir"/*.json --golden "$src/tests/golden" --report "$tmp/report-${dir##*/}") \
        >"$tmp/check.log" 2>&1 || status=$?
    [[ $status -eq 0 ]] || sed 's/^/       /' "$tmp/check.log" | tail -n 20
    return $status
}
check "the installed lab check passes on the installed presets" verify "$presets"

# --- it can fail ------------------------------------------------------------------------
fails() { ! "$@" >"$tmp/fails.log" 2>&1; }
# An install that lacks a preset: the presets no longer match the goldens.
cp -r "$presets" "$tmp/no-preset"
rm "$tmp/no-preset/05-full-phong.json"
check "an install without 05-full-phong.json fails" fails verify "$tmp/no-preset"
# An install without presets/models: the glTF preset no longer loads, and lab check says so.
cp -r "$presets" "$tmp/no-models"
rm -r "$tmp/no-models/models"
check "an install without presets/models fails lab check" fails "$lab" check "$tmp/no-models/24-gltf-trefoil.json" \
    --golden "$src/tests/golden" --report "$tmp/report-no-models"

echo "package: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
