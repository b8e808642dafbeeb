#!/bin/sh
# Precision settings through a real GL program (docs/profiles.md, "Precision
# settings"): e2e-coverage's random flat triangles through fixpipe with
# FIXPIPE_PROFILE=NAME:KEY=VALUE,...  Checks:
#   a setting equal to the profile (seed:xy=12.12) is the profile: named
#     "fixpipe (seed)", the same bytes;
#   seed:xy=12.4 and the literal walk with a 4-bit slope take effect: named
#     after the setting, and their pictures differ from seed's;
#   each draws the same bytes on 1 and on 2 threads;
#   a bad setting is reported once, with the accepted values, and seed is
#     used: the same bytes as seed.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=precision
. "$(dirname "$0")/checks.sh"
. "$root/tools/fp-run-driver.sh"

prog=$build/tests/e2e/e2e-coverage

# draw NAME PROFILE THREADS: $out/NAME.png, its stdout and stderr in $out/NAME.log
draw() {
    FIXPIPE_PROFILE=$2 FIXPIPE_THREADS=$3 fp_run_driver fixpipe "$prog" -o "$out/$1.png" \
        > "$out/$1.log" 2>&1
}
renderer() { sed -n 's/^renderer: //p' "$out/$1.log"; }

if ! draw base seed 1; then
    fail "seed: $(tail -n 1 "$out/base.log")"
    checks_end
    exit
fi

if ! draw same seed:xy=12.12 1; then
    fail "seed:xy=12.12: $(tail -n 1 "$out/same.log")"
elif [ "$(renderer same)" = "fixpipe (seed)" ] && cmp -s "$out/base.png" "$out/same.png"; then
    pass "seed:xy=12.12 is seed: its name and the same bytes"
else
    fail "seed:xy=12.12 is named '$(renderer same)' or draws other bytes than seed"
fi

for cfg in "xy4 seed:xy=12.4" "literal4 seed:walk=literal,dxdy=12.4"; do
    set -- $cfg
    tag=$1 spec=$2
    if ! draw "$tag" "$spec" 1 || ! draw "$tag-2t" "$spec" 2; then
        fail "$spec: $(tail -n 1 "$out/$tag.log")"
        continue
    fi
    name=$(renderer "$tag")
    d=$("$build/tools/fp-compare" --format=kv "$out/base.png" "$out/$tag.png" 2>/dev/null |
        sed -n 's/^diff_pixels=//p')
    case $name in
    "fixpipe (seed:"*) ;;
    *) fail "$spec: GL_RENDERER is '$name'"; continue ;;
    esac
    if [ "${d:-0}" -gt 0 ]; then
        pass "$spec ($name) takes effect: $d pixels differ from seed"
    else
        fail "$spec draws what seed draws: the setting did nothing"
    fi
    if cmp -s "$out/$tag.png" "$out/$tag-2t.png"; then
        pass "$spec: the same bytes on 1 and 2 threads"
    else
        fail "$spec: 1 and 2 threads differ"
    fi
done

if ! draw bad seed:xy=99.1 1; then
    fail "a bad setting stopped the program: $(tail -n 1 "$out/bad.log")"
else
    n=$(grep -c "fixpipe: bad FIXPIPE_PROFILE" "$out/bad.log")
    if [ "$n" = 1 ] && grep -q "accepted: 12.N" "$out/bad.log" &&
       [ "$(renderer bad)" = "fixpipe (seed)" ] && cmp -s "$out/base.png" "$out/bad.png"; then
        pass "a bad setting is reported once with the accepted values, and seed is drawn"
    else
        fail "a bad setting: $n reports, renderer '$(renderer bad)', or other bytes than seed"
    fi
fi
checks_end
