#!/bin/sh
# End-to-end GL ES 2 tests: each test program renders once through driver A
# and once through driver B; fp-compare compares the two images under the
# limits in tests/e2e/tolerances.txt.  One line per test, then "N passed,
# N failed"; exit 1 if any failed, 2 on a usage or set-up error.
#
#   tests/e2e/run.sh [--driver-a fixpipe] [--driver-b llvmpipe]
#                    [--build-dir build/std] [--out DIR] [--only REGEX]
#                    [--tolerances FILE]   (default tests/e2e/tolerances.txt)
set -u

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
driver_a=fixpipe
driver_b=llvmpipe
build=${FP_BUILD_DIR:-$root/build/std}
out=""
only=""
tolerances=$here/tolerances.txt

usage() {
    awk 'NR > 1 && !/^#/ { exit } NR > 1' "$0" | sed 's/^# \{0,1\}//'
    exit 2
}
while [ $# -gt 0 ]; do
    case $1 in
    --driver-a) driver_a=$2; shift 2 ;;
    --driver-b) driver_b=$2; shift 2 ;;
    --build-dir) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --tolerances) tolerances=$2; shift 2 ;;
    -h|--help) usage ;;
    *) echo "run.sh: unknown argument '$1'" >&2; usage ;;
    esac
done

. "$here/../../tools/fp-run-driver.sh"

compare=$build/tools/fp-compare
bindir=$build/tests/e2e
if [ ! -x "$compare" ] || [ ! -d "$bindir" ]; then
    echo "run.sh: no built tools in $build (expected tools/fp-compare and tests/e2e/);" \
         "build with meson first or pass --build-dir" >&2
    exit 2
fi
[ -n "$out" ] || out=$build/e2e-results/$driver_a-vs-$driver_b
mkdir -p "$out/$driver_a" "$out/$driver_b" || exit 2
[ -r "$tolerances" ] || { echo "run.sh: cannot read $tolerances" >&2; exit 2; }
[ "$driver_a" != "$driver_b" ] || { echo "run.sh: the two drivers are the same" >&2; exit 2; }

passed=0
failed=0

# Runs one test program through one driver; leaves its stdout in $log.
# Prints nothing; returns non-zero with a reason in $why on failure.
render() {
    drv=$1 name=$2 prog=$3
    shift 3
    log=$out/$drv/$name.log
    if ! fp_run_driver "$drv" "$bindir/$prog" -o "$out/$drv/$name.png" \
            --mask "$out/$drv/$name.mask.png" "$@" >"$log" 2>&1; then
        why="$drv: $(grep -v '^stat:' "$log" | tail -n 1)"
        return 1
    fi
    # The driver that drew must be the one asked for: a wrong library path
    # would otherwise compare llvmpipe with itself and pass.
    renderer=$(sed -n 's/^renderer: //p' "$log")
    if ! printf '%s' "$renderer" | grep -qi -- "$drv"; then
        why="$drv: GL_RENDERER is '$renderer', not $drv"
        return 1
    fi
    errs=$(sed -n 's/^stat:.*self_check_errors=\([0-9]*\).*/\1/p' "$log")
    if [ -n "$errs" ] && [ "$errs" != 0 ]; then
        why="$drv: $errs self-check errors ($(grep '^depth:\|^error' "$log" | head -n 1))"
        return 1
    fi
    return 0
}

kv() { sed -n "s/^$1=//p" "$out/$name.kv"; }

while IFS= read -r line; do
    case $line in ''|'#'*) continue ;; esac
    spec=${line%%|*}
    limits=""
    case $line in *'|'*) limits=${line#*|} ;; esac
    # shellcheck disable=SC2086
    set -- $spec
    name=$1 prog=$2
    shift 2
    if [ -n "$only" ] && ! printf '%s' "$name" | grep -Eq -- "$only"; then
        continue
    fi
    why=""
    if render "$driver_a" "$name" "$prog" "$@" && render "$driver_b" "$name" "$prog" "$@"; then
        if ! cmp -s "$out/$driver_a/$name.mask.png" "$out/$driver_b/$name.mask.png"; then
            why="the two runs computed different masks (the test is not deterministic)"
        fi
    fi
    if [ -z "$why" ]; then
        # shellcheck disable=SC2086
        "$compare" "$out/$driver_a/$name.png" "$out/$driver_b/$name.png" \
            --mask "$out/$driver_a/$name.mask.png" --heatmap "$out/$name.heat.png" \
            --format=kv $limits >"$out/$name.kv" 2>"$out/$name.err"
        rc=$?
        [ $rc -le 1 ] || why="fp-compare: $(cat "$out/$name.err")"
    fi
    if [ -n "$why" ]; then
        printf 'FAIL %-16s %s\n' "$name" "$why"
        failed=$((failed + 1))
        continue
    fi
    stats=$(sed -n 's/^stat: //p' "$out/$driver_a/$name.log" | head -n 1)
    figures="diff $(kv diff_pixels)/$(kv pixels) px ($(kv diff_percent)%, >$(kv threshold))"
    figures="$figures max $(kv max_err) mean $(kv mean_err) psnr $(kv psnr)"
    [ "$(kv masked_pixels)" = 0 ] ||
        figures="$figures; masked $(kv masked_pixels) ($(kv masked_diff_pixels) differ there)"
    if [ "$rc" = 0 ]; then
        printf 'PASS %-16s %s [%s]\n' "$name" "$figures" "$stats"
        passed=$((passed + 1))
    else
        printf 'FAIL %-16s %s; over: %s [%s]\n' "$name" "$figures" "$(kv failed)" "$stats"
        failed=$((failed + 1))
    fi
done <"$tolerances"

echo "$passed passed, $failed failed   ($driver_a vs $driver_b; images in $out)"
[ $failed = 0 ] && [ $passed -gt 0 ]
