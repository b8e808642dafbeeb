#!/bin/sh
# Adversarial GL input (docs/adversarial.md): every case of e2e-adversarial through
# the driver built with fixpipe's sources under ASan+UBSan (./fixpipe setup --sanitize,
# ./fixpipe run --sanitize) and through llvmpipe.  A case passes when, through fixpipe:
#   it ends by itself within 10 minutes (no hang), with status 0 and no sanitizer
#     report (any report aborts the process);
#   every check of its defined result holds ("check: NAME ok");
#   its picture matches llvmpipe's within the case's limit below, where GL defines
#     the picture ("-": GL leaves it undefined; the difference is reported only);
#   the scalar reference datapath on one thread (FIXPIPE_DEBUG=scalar,noskip,nothreads),
#     sanitized too, draws the same bytes with the same checks holding: the defined
#     result is the model's, not one datapath's;
# and w-near-zero has reached the model's own rule (its counter of primitives dropped
# for a non-finite position is not 0).  Whether llvmpipe's pictures meet the same
# checks is reported, not checked.
# One line per case, then "N passed, N failed"; exit 1 on a failure.
checks=adversarial
. "$(dirname "$0")/checks.sh"

prog=$build/tests/e2e/e2e-adversarial
compare=$build/tools/fp-compare
[ -x "$prog" ] || { fail "no $prog (build build/std)"; checks_end; exit; }
if [ ! -e "$root/.fixpipe/prefix-asan/lib/dri/swrast_dri.so" ]; then
    fail "no sanitized driver: run ./fixpipe setup --sanitize"
    checks_end
    exit
fi

# case | fp-compare limits against llvmpipe ("-": not compared)
cases='
nan-position   | --max-diff-pixels 0
inf-position   | --max-diff-pixels 0
huge-position  | --max-diff-pixels 0
w-near-zero    | --max-diff-pixels 16
bad-texcoord   | -
bad-pointsize  | --max-diff-pixels 0
slivers        | --max-diff-pixels 0
pixel-centres  | --max-diff-pixels 0
fan            | --max-diff-pixels 0
jitter         | --max-diff-pixels 0
jitter-tiles   | --max-diff-pixels 0
'

# run DRIVER CASE: $out/CASE-DRIVER.png and .log; the exit status (124: timed out)
run() {
    opt="--driver $1" debug=${FIXPIPE_DEBUG:-}
    [ "$1" != fixpipe ] || opt=--sanitize
    [ "$1" != reference ] || opt=--sanitize debug=scalar,noskip,nothreads
    # shellcheck disable=SC2086  # one option, or two words
    FIXPIPE_DEBUG=$debug FIXPIPE_STATS=1 timeout 600 "$root/fixpipe" run $opt --no-xvfb -- \
        "$prog" --case "$2" -o "$out/$2-$1.png" > "$out/$2-$1.log" 2>&1
}

echo "$cases" | while IFS='|' read -r name limits; do
    name=$(echo "$name" | tr -d ' ')
    [ -n "$name" ] || continue
    start=$(date +%s)
    run fixpipe "$name"
    rc=$?
    secs=$(( $(date +%s) - start ))
    log=$out/$name-fixpipe.log
    sanitizer=$(grep -m1 -E 'AddressSanitizer|runtime error|LeakSanitizer' "$log")
    failed_checks=$(grep -c '^check: .* FAIL ' "$log")
    ok_checks=$(grep -c '^check: .* ok ' "$log")
    run llvmpipe "$name"
    llvm_failed=$(grep -c '^check: .* FAIL ' "$out/$name-llvmpipe.log")
    llvm_note="llvmpipe: $llvm_failed of its checks fail"
    if [ -e "$out/$name-fixpipe.png" ] && [ -e "$out/$name-llvmpipe.png" ]; then
        diff=$("$compare" --format=kv "$out/$name-fixpipe.png" "$out/$name-llvmpipe.png" |
               sed -n 's/^diff_pixels=//p')
    else
        diff="(no picture)"
    fi
    why=""
    if [ -n "$sanitizer" ]; then
        why="sanitizer: $sanitizer"
    elif [ "$rc" = 124 ]; then
        why="did not end within 600 s"
    elif [ "$rc" != 0 ] && [ "$failed_checks" = 0 ]; then
        why="exit $rc: $(grep -v '^stat:\|^check:\|^renderer:' "$log" | tail -n 1)"
    elif [ "$failed_checks" != 0 ] || [ "$ok_checks" = 0 ]; then
        why="$failed_checks of $((failed_checks + ok_checks)) checks fail: $(grep -m1 '^check: .* FAIL ' "$log")"
    fi
    limits=$(echo "$limits" | sed 's/^ *//; s/ *$//')
    if [ -z "$why" ] && [ "$limits" != - ]; then
        # shellcheck disable=SC2086  # the limits are words
        if ! "$compare" "$out/$name-fixpipe.png" "$out/$name-llvmpipe.png" $limits \
                > "$out/$name-compare.txt" 2>&1; then
            why="against llvmpipe: $diff pixels differ ($limits)"
        fi
    fi
    if [ -z "$why" ]; then
        run reference "$name"
        rc=$?
        rlog=$out/$name-reference.log
        if grep -q -E 'AddressSanitizer|runtime error|LeakSanitizer' "$rlog"; then
            why="reference datapath, sanitizer: $(grep -m1 -E 'AddressSanitizer|runtime error' "$rlog")"
        elif [ "$rc" != 0 ]; then
            why="reference datapath: exit $rc: $(grep -m1 '^check: .* FAIL ' "$rlog" || tail -n 1 "$rlog")"
        elif ! "$compare" "$out/$name-fixpipe.png" "$out/$name-reference.png" --max-diff-pixels 0 \
                > "$out/$name-reference.txt" 2>&1; then
            why="the reference datapath drew another picture: $(sed -n 's/^diff_pixels=//p' \
                "$out/$name-reference.txt") pixels differ"
        fi
    fi
    if [ -z "$why" ] && [ "$name" = w-near-zero ]; then
        dropped=$(sed -n 's/.*dropped for a non-finite position \([0-9]*\).*/\1/p' "$log" | tail -n 1)
        [ "${dropped:-0}" -gt 0 ] || why="the model dropped no primitive for a non-finite position"
    fi
    if [ -z "$why" ]; then
        pass "$name: $ok_checks checks hold, the reference datapath's bytes, $diff pixels unlike llvmpipe's ($limits); $llvm_note; ${secs} s"
    else
        fail "$name: $why"
    fi
    echo "$passed $failed" > "$out/tally"
done
read -r passed failed < "$out/tally" 2>/dev/null || { passed=0 failed=1; }
checks_end
