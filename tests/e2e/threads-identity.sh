#!/bin/sh
# The model on one thread against several (docs/threads.md): every
# end-to-end program of tolerances.txt, the demo, and every checked-in trace
# (traces/recorded, and every 50th frame of the benchmark's
# traces/bench/glmark2-long.trace) are rendered through fixpipe with
#   FIXPIPE_DEBUG=nothreads   the reference: one thread (the same as FIXPIPE_THREADS=1)
#   FIXPIPE_THREADS=N         N = 2 for the programs and traces, 3 for the demo
# and every image must be the same bytes, and the programs' counters
# (FIXPIPE_STATS=1, all but the lines of shader compile times and threads)
# the same numbers.  The programs run on N threads with
# FIXPIPE_DEBUG=divideall, every batch divided between the threads however
# small (a batch under 4096 pixels is otherwise drawn by the calling thread
# alone, and most e2e images are 64x64): each program must have drawn
# primitives on all its threads, or its comparison proves nothing and
# fails.  The traces run as a player would, without it.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=threads-identity
. "$(dirname "$0")/checks.sh"
# the environment of a thread count: 1 is the reference switch, FIXPIPE_DEBUG=nothreads
# (FIXPIPE_THREADS set high too, which it must override)
mode_env() { if [ "$1" = 1 ]; then echo "FIXPIPE_DEBUG=nothreads FIXPIPE_THREADS=8"; else echo "FIXPIPE_THREADS=$1"; fi; }
# the programs' N-thread runs: every batch divided
program_env() { if [ "$1" = 1 ]; then mode_env 1; else echo "$(mode_env "$1") FIXPIPE_DEBUG=divideall"; fi; }
parallel_total=0

# counters LOG: the FIXPIPE_STATS lines that must not depend on the threads
counters() {
    awk '/^fixpipe stats/ { on = 1; print; next } on && /^  / { print; next } { on = 0 }' "$1" |
        grep -v 'fragment shaders:\|threads [0-9]*:'
}

render() { # THREADS NAME PROGRAM ARGS...
    many=$1 name=$2 prog=$3
    shift 3
    for n in 1 "$many"; do
        if ! env $(program_env "$n") FIXPIPE_STATS=1 \
             "$root/fixpipe" run --no-xvfb --driver fixpipe -- "$prog" -o "$out/$name.$n.png" "$@" \
             > "$out/$name.$n.log" 2>&1; then
            fail "$name: the run on $n threads failed ($(tail -n 1 "$out/$name.$n.log"))"
            return 1
        fi
    done
    p=$(sed -n 's/.*threads [0-9]*: primitives drawn on one thread [0-9]*, on all \([0-9]*\).*/\1/p' \
        "$out/$name.$many.log" | awk '{ s += $1 } END { print s + 0 }')
    parallel_total=$((parallel_total + p))
    if ! grep -q '^  threads 1:' "$out/$name.1.log" ||
       ! grep -q "^  threads $many:" "$out/$name.$many.log"; then
        fail "$name: not drawn on 1 and on $many threads (FIXPIPE_STATS' threads lines)"
        return 1
    fi
    counters "$out/$name.1.log" > "$out/$name.1.counters"
    counters "$out/$name.$many.log" > "$out/$name.$many.counters"
    if [ ! -s "$out/$name.1.counters" ]; then
        fail "$name: no counters printed"
    elif ! cmp -s "$out/$name.1.png" "$out/$name.$many.png"; then
        fail "$name: 1 and $many threads differ ($("$build/tools/fp-compare" "$out/$name.1.png" "$out/$name.$many.png" | grep differing))"
    elif ! cmp -s "$out/$name.1.counters" "$out/$name.$many.counters"; then
        fail "$name: the counters differ on $many threads ($(diff "$out/$name.1.counters" "$out/$name.$many.counters" | grep '^>' | head -n 1))"
    elif [ "$p" = 0 ]; then
        fail "$name: no primitive drawn on all $many threads under divideall: 1 thread = $many proves nothing"
    else
        pass "$name: 1 thread = $many threads, image and counters ($p primitives drawn on all)"
    fi
}

. "$here/identity-programs.sh"
each_program render 2
render 3 demo "$build/tools/fp-demo" --scene all --frames 3

# every trace on 1 and 2 threads, snapshots byte for byte
MODES="1 2"
SAME="1 thread = 2 threads"
. "$here/identity-replays.sh"
replay_all

# the per-program check can fail: without divideall a 64x64 program's
# batches are all small, drawn by the calling thread alone
if FIXPIPE_THREADS=2 FIXPIPE_STATS=1 "$root/fixpipe" run --no-xvfb --driver fixpipe -- \
       "$build/tests/e2e/e2e-es31" --case gather-clamp -o "$out/undivided.png" \
       > "$out/undivided.log" 2>&1; then
    u=$(sed -n 's/.*threads [0-9]*: primitives drawn on one thread [0-9]*, on all \([0-9]*\).*/\1/p' \
        "$out/undivided.log" | awk '{ s += $1 } END { print s + 0 }')
    if [ "$u" = 0 ]; then
        pass "without divideall es31-gather-clamp draws nothing on all threads: the check above would fail it"
    else
        fail "without divideall es31-gather-clamp drew $u primitives on all threads (want 0)"
    fi
else
    fail "the undivided run of es31-gather-clamp failed ($(tail -n 1 "$out/undivided.log"))"
fi

if [ "$parallel_total" -gt 0 ]; then
    pass "the programs drew $parallel_total primitives on all their threads"
else
    fail "no program drew on more than one thread: the comparison proves nothing"
fi
checks_end
