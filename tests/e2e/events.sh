#!/bin/sh
# FIXPIPE_EVENTS=DIR[,frames=A-B] (docs/events.md) through a real program: glmark2-es2's
# mipmapped texture scene (traces/recorded/glmark2-texture-mipmap.trace) replayed under
# Xvfb, whose window buffer is the display target the maps are drawn for.
#   planted: FIXPIPE_TEXFMT=fx24.8, whose 8 fraction bits flush the texture path's small
#     values (tens of thousands of events), writes texflush maps, each a well-formed
#     16-bit PGM of the window's size with marked pixels; the default dfx24 counts none
#     in this scene and writes no map (what the check of the planted run rests on);
#   the maps and draws.tsv are the same bytes for FIXPIPE_THREADS=1 and 2, on two
#     threads once as a player runs and once with every batch divided between them
#     (FIXPIPE_DEBUG=divideall), which must have drawn primitives on both: the planted
#     scene, and the refract scene as it is (Z saturations of set-up and of the walk,
#     texture flushes, offscreen passes);
#   draws.tsv's columns, summed over every row, are the totals FIXPIPE_STATS prints
#     (both scenes);
#   the refract scene's frames and FIXPIPE_STATS counters are the same without
#     FIXPIPE_EVENTS (the instrument observes; the back end one quad at a time changes
#     nothing);
#   frames=1-2 records those frames' rows and maps alone, the same as the whole run's;
#   a malformed setting is reported once with the accepted form, and nothing is written.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=events
. "$(dirname "$0")/checks.sh"

mipmap=$root/traces/recorded/glmark2-texture-mipmap.trace
refract=$root/traces/recorded/glmark2-refract.trace
trace=$mipmap
# record NAME SETTING-SUFFIX ENV...: a replay of $trace recording into $out/NAME
# (its frames in $out/NAME.snap; SETTING-SUFFIX "off": no FIXPIPE_EVENTS at all)
record() {
    name=$1 suffix=$2
    shift 2
    rm -rf "$out/$name" "$out/$name.snap"
    mkdir -p "$out/$name.snap"
    if [ "$suffix" = off ]; then set -- FIXPIPE_EVENTS= "$@"; else set -- FIXPIPE_EVENTS="$out/$name$suffix" "$@"; fi
    env FIXPIPE_STATS=1 "$@" \
        "$root/fixpipe" run --xvfb --driver fixpipe -- eglretrace --snapshot-prefix="$out/$name.snap/" \
        "$trace" > "$out/$name.log" 2>&1
}
# counters LOG: the FIXPIPE_STATS blocks, but for the lines of times (shaders, threads)
counters() {
    awk '/^fixpipe stats/ { on = 1; print; next } on && /^  / { print; next } { on = 0 }' "$1" |
        grep -v 'fragment shaders:\|threads [0-9]*:'
}

# pgm_ok FILE W H: a binary 16-bit PGM of W x H with a nonzero sample
pgm_ok() {
    python3 - "$1" "$2" "$3" <<'EOF'
import sys
d = open(sys.argv[1], 'rb').read()
head = b'P5\n%d %d\n65535\n' % (int(sys.argv[2]), int(sys.argv[3]))
body = d[len(head):]
ok = d.startswith(head) and len(body) == 2 * int(sys.argv[2]) * int(sys.argv[3])
sys.exit(0 if ok and any(body) else 1)
EOF
}

# 1. the planted setting writes maps
record planted "" FIXPIPE_TEXFMT=fx24.8 FIXPIPE_THREADS=1
size=$(awk -F'\t' '$3 == "display" { print $4 " " $5; exit }' "$out/planted/draws.tsv" 2>/dev/null)
maps=$(ls "$out/planted" 2>/dev/null | grep -c '^frame-[0-9]\{6\}-texflush\.pgm$')
bad=0
for f in "$out"/planted/frame-*.pgm; do
    [ -e "$f" ] || continue
    # shellcheck disable=SC2086
    pgm_ok "$f" $size || bad=$((bad + 1))
done
if [ -n "$size" ] && [ "$maps" -gt 0 ] && [ "$bad" = 0 ]; then
    pass "FIXPIPE_TEXFMT=fx24.8: $maps texflush maps of the ${size% *}x${size#* } window, each with marked pixels"
else
    fail "FIXPIPE_TEXFMT=fx24.8: window '$size', $maps texflush maps, $bad malformed or empty (log: $out/planted.log)"
fi
record default "" FIXPIPE_THREADS=1
nd=$(ls "$out/default" 2>/dev/null | grep -c '\.pgm$')
rows=$(($(wc -l < "$out/default/draws.tsv" 2>/dev/null || echo 1) - 1))
if [ "$nd" = 0 ] && [ "$rows" -gt 0 ]; then
    pass "dfx24: $rows draws recorded, no event and no map"
else
    fail "dfx24: $nd maps, $rows draws (the planted check proves nothing without the contrast)"
fi

# 2. one thread against two: the planted mipmap scene, and glmark2-es2's refract scene
# (Z saturations in set-up and in the walk, texture flushes, offscreen passes) as it is
# whose files FIXPIPE_THREADS=1 writes as the reference
trace=$refract
record refract "" FIXPIPE_THREADS=1
for t in planted refract; do
    if [ $t = planted ]; then trace=$mipmap set -- FIXPIPE_TEXFMT=fx24.8; else trace=$refract set --; fi
    n=$(ls "$out/$t" | grep -c '\.pgm$')
    for m in threads2 divideall; do
        if [ $m = threads2 ]; then
            record $t-$m "" "$@" FIXPIPE_THREADS=2
        else
            record $t-$m "" "$@" FIXPIPE_THREADS=2 FIXPIPE_DEBUG=divideall
        fi
        p=$(sed -n 's/.*threads 2: primitives drawn on one thread [0-9]*, on all \([0-9]*\).*/\1/p' \
            "$out/$t-$m.log" | awk '{ s += $1 } END { print s + 0 }')
        if [ "$n" = 0 ]; then
            fail "$(basename "$trace" .trace): no map written on one thread: the identity proves nothing"
        elif ! diff -r "$out/$t" "$out/$t-$m" > "$out/$t-$m.diff" 2>&1; then
            fail "$(basename "$trace" .trace) on 2 threads ($m): $(head -n 1 "$out/$t-$m.diff")"
        elif [ $m = divideall ] && [ "$p" = 0 ]; then
            fail "$(basename "$trace" .trace) divideall: no primitive drawn on both threads: the identity proves nothing"
        else
            pass "$(basename "$trace" .trace) on 2 threads ($m, $p primitives drawn on both): draws.tsv and $n maps the same bytes"
        fi
    done
done

# the instrument observes from outside: without it, the same frames and counters
record refract-off off FIXPIPE_THREADS=2
counters "$out/refract-threads2.log" > "$out/refract-on.counters"
counters "$out/refract-off.log" > "$out/refract-off.counters"
n=$(ls "$out/refract-off.snap" | wc -l)
if [ "$n" -gt 0 ] && diff -r "$out/refract-off.snap" "$out/refract-threads2.snap" > /dev/null &&
   [ -s "$out/refract-off.counters" ] &&
   cmp -s "$out/refract-off.counters" "$out/refract-on.counters"; then
    pass "glmark2-refract with and without FIXPIPE_EVENTS: $n frames and every counter the same"
else
    fail "glmark2-refract with and without FIXPIPE_EVENTS: frames or counters differ ($n frames; $(diff "$out/refract-off.counters" "$out/refract-on.counters" | grep '^>' | head -n 1))"
fi
trace=$mipmap

# 3. draws.tsv's sums against FIXPIPE_STATS (every context's block: the one that records
# is the only one that draws)
for t in planted refract; do
    sums=$(awk -F'\t' 'NR > 1 { for (i = 6; i <= 15; i++) s[i] += $i }
        END { for (i = 6; i <= 15; i++) printf "%s%d", (i > 6 ? " " : ""), s[i] }' "$out/$t/draws.tsv")
    stats=$(awk '/saturation (xy|dxdy|z|color|weight) / { s[$2] += $4 + $6 }
        /range saturations/ { for (i = 1; i <= NF; i++) {
            if ($i == "saturations") ts += $(i + 1); if ($i == "flushes") tf += $(i + 1) } }
        /^  triangles [0-9]/ { tri += $2 }
        /^  quads [0-9]* pixels covered/ { q += $2; ps += $7 }
        END { printf "%d %d %d %d %d %d %d %d %d %d", s["xy"], s["dxdy"], s["z"], s["color"],
              s["weight"], ts, tf, tri, q, ps }' "$out/$t.log")
    if [ -n "$sums" ] && [ "$sums" = "$stats" ] && [ "${sums#* * * * * * }" != "0 0 0 0" ]; then
        pass "$t: draws.tsv's sums are FIXPIPE_STATS' totals: $sums"
    else
        fail "$t: draws.tsv's sums '$sums', FIXPIPE_STATS '$stats' (sat_xy .. pixels_shaded)"
    fi
done

# 4. a range of frames: its rows and maps, as the whole run has them
record range ",frames=1-2" FIXPIPE_TEXFMT=fx24.8 FIXPIPE_THREADS=2
awk -F'\t' 'NR == 1 || $1 == 1 || $1 == 2' "$out/planted/draws.tsv" > "$out/range.want"
extra=$(ls "$out/range" | grep '^frame-' | grep -cv '^frame-00000[12]-')
missing=0
for f in "$out"/planted/frame-00000[12]-*.pgm; do
    [ -e "$f" ] || continue
    cmp -s "$f" "$out/range/$(basename "$f")" || missing=$((missing + 1))
done
if cmp -s "$out/range.want" "$out/range/draws.tsv" && [ "$extra" = 0 ] && [ "$missing" = 0 ] &&
   [ "$(wc -l < "$out/range.want")" -gt 1 ]; then
    pass "frames=1-2: $(($(wc -l < "$out/range.want") - 1)) rows and the maps of frames 1 and 2, as the whole run's"
else
    fail "frames=1-2: draws.tsv differs, $extra maps of other frames, $missing maps differing"
fi

# 5. malformed settings: one message with the accepted form, nothing recorded
for bad in ",frames=3-1" ",frames=2" ",units=tex" ",,frames=1-2"; do
    rm -rf "$out/bad"
    env FIXPIPE_EVENTS="$out/bad$bad" "$root/fixpipe" run --xvfb --driver fixpipe -- \
        eglretrace "$trace" > "$out/bad.log" 2>&1
    n=$(grep -c "^fixpipe: bad FIXPIPE_EVENTS " "$out/bad.log")
    if [ "$n" = 1 ] && grep -q "frames=A-B with A <= B" "$out/bad.log" &&
       grep -q "nothing recorded" "$out/bad.log" && [ ! -e "$out/bad" ]; then
        pass "FIXPIPE_EVENTS='DIR$bad' reported once: $(grep "^fixpipe: bad FIXPIPE_EVENTS" "$out/bad.log" | sed 's/.*\/bad[^:]*: //' | cut -c1-90)"
    else
        fail "FIXPIPE_EVENTS='DIR$bad': $n reports, or without the accepted form, or $out/bad written"
    fi
done
checks_end
