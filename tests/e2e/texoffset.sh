#!/bin/sh
# Large texture coordinates under REPEAT and MIRRORED_REPEAT (docs/texture-unit.md,
# "Coordinate rebase"): e2e-texoffset draws a NEAREST checkerboard of distinct
# texels with its coordinates offset by K whole repeats; GL's image is the same
# for every K.  Checks, through fixpipe (the seed profile and its dfx24
# texture path, the defaults):
#   K = 2^17, 2^20 and 10^7 draw the same bytes as K = 0, on 1 and on 2 threads
#     and on the scalar reference datapath;
#   the picture at K = 0 has more than 200 distinct colours (texels, not a
#     flat colour);
#   with FIXPIPE_DEBUG=norebase, K = 10^7 does not (the check can fail);
# and reports, without checking, how llvmpipe (binary32) does at each K.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=texoffset
. "$(dirname "$0")/checks.sh"
. "$root/tools/fp-run-driver.sh"

prog=$build/tests/e2e/e2e-texoffset
compare=$build/tools/fp-compare

# draw DRIVER NAME K [VAR=value...]: $out/NAME.png, its output in $out/NAME.log
draw() {
    drv=$1 name=$2 k=$3
    shift 3
    (
        [ $# = 0 ] || export "$@"
        fp_run_driver "$drv" "$prog" --offset "$k" -o "$out/$name.png"
    ) > "$out/$name.log" 2>&1
}

# differing A B: the pixels of A.png and B.png that differ
differing() {
    "$compare" --format=kv "$out/$1.png" "$out/$2.png" 2>/dev/null | sed -n 's/^diff_pixels=//p'
}

if ! draw fixpipe k0 0; then
    fail "fixpipe at K = 0: $(tail -n 1 "$out/k0.log")"
    checks_end
    exit
fi
colours=$(sed -n 's/^stat:.*colours=\([0-9]*\).*/\1/p' "$out/k0.log")
if [ "${colours:-0}" -gt 200 ]; then
    pass "K = 0: $colours distinct colours"
else
    fail "K = 0: ${colours:-no} distinct colours (a checkerboard of 256 texels a quad)"
fi

for k in 131072 1048576 10000000; do
    for cfg in "1thread FIXPIPE_THREADS=1" "2threads FIXPIPE_THREADS=2" \
               "scalar FIXPIPE_DEBUG=scalar,noskip FIXPIPE_THREADS=1"; do
        set -- $cfg
        tag=$1
        shift
        if ! draw fixpipe "k$k-$tag" "$k" "$@"; then
            fail "fixpipe $tag at K = $k: $(tail -n 1 "$out/k$k-$tag.log")"
        elif cmp -s "$out/k0.png" "$out/k$k-$tag.png"; then
            pass "fixpipe $tag at K = $k: the same bytes as K = 0"
        else
            fail "fixpipe $tag at K = $k: $(differing k0 "k$k-$tag") pixels differ from K = 0"
        fi
    done
done

if ! draw fixpipe k1e7-norebase 10000000 FIXPIPE_DEBUG=norebase; then
    fail "fixpipe norebase: $(tail -n 1 "$out/k1e7-norebase.log")"
else
    d=$(differing k0 k1e7-norebase)
    if [ "${d:-0}" -gt 0 ]; then
        pass "without the rebase, K = 10^7 differs from K = 0 on $d pixels"
    else
        fail "without the rebase, K = 10^7 draws the same as K = 0: the check cannot fail"
    fi
fi

if draw llvmpipe llvm-k0 0; then
    for k in 131072 1048576 10000000; do
        draw llvmpipe "llvm-k$k" "$k" &&
            echo "info: llvmpipe at K = $k: $(differing llvm-k0 "llvm-k$k") pixels differ from its K = 0"
    done
fi
checks_end
