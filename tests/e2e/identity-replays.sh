# Sourced by the identity checks (datapath-identity.sh, threads-identity.sh):
# every checked-in trace (traces/recorded, and every 50th frame of the
# benchmark's traces/bench/glmark2-long.trace) replayed headless through
# fixpipe in two modes, the snapshots compared byte for byte.
# The caller sets root, out, MODES ("A B"), SAME (what the pass line says,
# e.g. "1 thread = 2 threads"), and defines pass, fail and mode_env MODE
# (the environment of that mode, as VAR=value words).

# replay TRACE NAME SNAPSHOT-CALLS
replay() {
    trace=$1 name=$2 snaps=$3
    for m in $MODES; do
        mkdir -p "$out/$name.$m"
        set -- --snapshot-prefix="$out/$name.$m/"
        [ -n "$snaps" ] && set -- "$@" --snapshot="$snaps"
        # shellcheck disable=SC2046
        if ! env $(mode_env "$m") "$root/fixpipe" run --no-xvfb --driver fixpipe -- \
             env WAFFLE_PLATFORM=surfaceless_egl eglretrace --headless "$@" "$trace" \
             > "$out/$name.$m.log" 2>&1; then
            fail "$name: the $m replay failed ($(tail -n 1 "$out/$name.$m.log"))"
            return 1
        fi
    done
    a=${MODES%% *} b=${MODES##* }
    n=$(ls "$out/$name.$a" | wc -l)
    if [ "$n" -eq 0 ] || [ "$n" -ne "$(ls "$out/$name.$b" | wc -l)" ]; then
        fail "$name: $n snapshots in mode $a, $(ls "$out/$name.$b" | wc -l) in mode $b"
        return 1
    fi
    if diff -rq "$out/$name.$a" "$out/$name.$b" > "$out/$name.diff" 2>&1; then
        pass "$name: $n frames, $SAME"
    else
        fail "$name: $(wc -l < "$out/$name.diff") of $n frames differ"
    fi
}

replay_all() {
    for t in "$root"/traces/recorded/*.trace; do
        name=$(basename "$t" .trace)
        snaps=$(python3 -c 'import json, sys; s = json.load(open(sys.argv[1])).get("snap_calls"); print(",".join(map(str, s)) if s else "")' \
                "${t%.trace}.json")
        replay "$t" "$name" "$snaps"
    done
    long=$root/traces/bench/glmark2-long.trace
    snaps=$(apitrace dump --grep=eglSwapBuffers --arg-names=no "$long" 2>/dev/null |
            awk '/eglSwapBuffers/ { if (n++ % 50 == 0) { sub(/ .*/, ""); printf "%s%s", s, $0; s = "," } }')
    replay "$long" glmark2-long "$snaps"
}
