#!/bin/sh
# Inside the modeled hardware (docs/cycles.md, docs/vectors.md), through real programs:
#   GALLIUM_HUD=help lists every fixpipe query (the names of fp_query_driver.c's table);
#   GALLIUM_HUD with two of them runs glmark2-es2 under Xvfb without error;
#   fp-demo's modeled frame, read through GL_AMD_performance_monitor, is exactly half the
#     cycles FIXPIPE_STATS counts for its two identical frames;
#   piglit's amd_performance_monitor_api and _measure pass on fixpipe;
#   tools/demo.sh prints the modeled chip's time beside the host's for fixpipe;
#   FIXPIPE_VECTORS=DIR,frames=A-B on two trace replays (glmark2-es2's build scene: the
#     scan converter and the perspective division; its mipmapped texture scene: the
#     texture unit) writes vectors that fp-vectors replays bit-exactly, and with one
#     output bit flipped (a Z word, a filtered texel) it fails; their coverage is the
#     exact reference's (test_vectors_ref), and not once a pixel is flipped; units=tex
#     writes the texture unit's alone;
#   a malformed FIXPIPE_VECTORS or FIXPIPE_CYCLES list is reported once with the
#     accepted keys, and none of it takes effect.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=observability
. "$(dirname "$0")/checks.sh"

run() { "$root/fixpipe" run "$@"; }
piglit_bin=/usr/lib/x86_64-linux-gnu/piglit/bin

# 1. the HUD's list
run --xvfb -- env GALLIUM_HUD=help glmark2-es2 -b build:duration=0.2 -s 160x120 \
    > "$out/hud-help.log" 2>&1
grep -oE '^ +fp-[a-z0-9-]+$' "$out/hud-help.log" | tr -d ' ' | sort -u > "$out/hud-listed"
grep -oE '"fp-[a-z0-9-]+"' "$root/src/gallium-like/fp_query_driver.c" | tr -d '"' | sort -u \
    > "$out/hud-table"
n=$(wc -l < "$out/hud-listed") want=$(wc -l < "$out/hud-table")
if [ "$want" -ge 30 ] && cmp -s "$out/hud-listed" "$out/hud-table"; then
    pass "GALLIUM_HUD=help lists the $n fixpipe queries of the driver's table"
else
    fail "GALLIUM_HUD=help lists $n fixpipe queries, the driver's table $want (log: $out/hud-help.log; missing or extra: $(comm -3 "$out/hud-listed" "$out/hud-table" | tr -d '\t' | tr '\n' ' '))"
fi

# 2. two queries on the HUD over a real program
if run --xvfb -- env GALLIUM_HUD=fp-triangles,fp-cycles glmark2-es2 -s 320x240 \
        -b build:duration=1 -b jellyfish:duration=1 > "$out/hud-run.log" 2>&1 &&
   grep -q 'glmark2 Score' "$out/hud-run.log" && ! grep -qi 'gallium_hud' "$out/hud-run.log"; then
    pass "GALLIUM_HUD=fp-triangles,fp-cycles: glmark2-es2 build and jellyfish ran"
else
    fail "GALLIUM_HUD=fp-triangles,fp-cycles: $(grep -i 'hud\|error' "$out/hud-run.log" | head -n 1)"
fi

# 3. the performance monitor against FIXPIPE_STATS
FIXPIPE_STATS=1 run --no-xvfb -- "$build/tools/fp-demo" --frames 1 --size 128x128 \
    > "$out/perfmon.log" 2>&1
frame=$(sed -n 's/^modeled_cycles_per_frame: \([0-9]*\) .*/\1/p' "$out/perfmon.log")
total=$(sed -n 's/^ *modeled chip: \([0-9]*\) cycles.*/\1/p' "$out/perfmon.log")
if [ -n "$frame" ] && [ -n "$total" ] && [ "$frame" -gt 0 ] && [ $((2 * frame)) = "$total" ]; then
    pass "GL_AMD_performance_monitor: fp-cycles $frame a frame, FIXPIPE_STATS $total for two"
else
    fail "GL_AMD_performance_monitor: fp-cycles '$frame' a frame, FIXPIPE_STATS '$total' for two"
fi

# 4. piglit's tests of the extension
for t in amd_performance_monitor_api amd_performance_monitor_measure; do
    if timeout 300 env PIGLIT_PLATFORM=surfaceless_egl "$root/fixpipe" run --no-xvfb -- \
            "$piglit_bin/$t" -auto -fbo > "$out/$t.log" 2>&1 &&
       grep -q '"result": "pass"' "$out/$t.log"; then
        pass "piglit $t"
    else
        fail "piglit $t: $(tail -n 1 "$out/$t.log")"
    fi
done

# 5. the demo's modeled time
"$root/tools/demo.sh" "$out/demo" --frames 2 --size 128x128 --drivers "fixpipe llvmpipe" \
    > "$out/demo.log" 2>&1
line=$(grep -E '^fixpipe {2,}' "$out/demo.log" | head -n 1)
case $line in
*"ms a frame ("*" cycles at "*" MHz)"*) pass "demo: $(echo "$line" | tr -s ' ')" ;;
*) fail "demo prints no modeled time: '$line'" ;;
esac

# 6. vectors from trace replays, and a flipped bit in each
# flip FILE QUAD WORD [BIT]: bit BIT (0, or a multiple of 4) of word WORD of
# record QUAD of FILE
flip() {
    awk -v q="// quad $2" -v w="$3" -v d="$((16 - ${4:-0} / 4))" '$0 == q { at = NR + 1 + w }
        NR == at {
            c = substr($0, d, 1); n = index("0123456789abcdef", c) - 1;
            n = n % 2 ? n - 1 : n + 1
            $0 = substr($0, 1, d - 1) substr("0123456789abcdef", n + 1, 1) substr($0, d + 1) }
        { print }' "$1" > "$1.flipped" && mv "$1.flipped" "$1"
}
# vectors NAME TRACE FRAMES FILE QUAD WORD: record, replay, flip one output bit, replay
vectors() {
    name=$1 trace=$root/traces/recorded/$2.trace
    rm -rf "$out/$name"
    if FIXPIPE_VECTORS="$out/$name,frames=$3" run --xvfb -- eglretrace "$trace" \
            > "$out/$name-record.log" 2>&1 &&
       "$build/tools/fp-vectors" "$out/$name" > "$out/$name-replay.log" 2>&1; then
        pass "vectors of $2 frames $3: $(sed 's/^fp-vectors: [^:]*: //' "$out/$name-replay.log")"
    else
        fail "vectors of $2: $(tail -n 2 "$out/$name-record.log" "$out/$name-replay.log" | tr '\n' ' ')"
        return
    fi
    # the recorded coverage against the exact reference, and a quad's pixel 0
    # (bit 32 of its word 0) flipped in a copy
    if "$build/tests/unit/test_vectors_ref" "$out/$name" > "$out/$name-ref.log" 2>&1; then
        pass "vectors of $2: $(sed 's/^test_vectors_ref: [^:]*: //' "$out/$name-ref.log")"
        rm -rf "$out/$name-cov" && cp -r "$out/$name" "$out/$name-cov"
        flip "$out/$name-cov/scan.out.hex" 100 0 32
        if "$build/tests/unit/test_vectors_ref" "$out/$name-cov" > "$out/$name-cov.log" 2>&1; then
            fail "vectors of $2 with quad 100's pixel 0 flipped: the reference check passed"
        else
            pass "vectors of $2 with quad 100's pixel 0 flipped: the reference check finds it"
        fi
    else
        fail "vectors of $2 against the exact reference: $(tail -n 3 "$out/$name-ref.log" | tr '\n' ' ')"
    fi
    flip "$out/$name/$4" "$5" "$6"
    "$build/tools/fp-vectors" "$out/$name" > "$out/$name-flipped.log" 2>&1
    if grep -q ' 1 differ$' "$out/$name-flipped.log"; then
        pass "vectors of $2 with bit 0 of word $6 of $4's quad $5 flipped: the replay finds it"
    else
        fail "vectors of $2 with one bit flipped: $(tail -n 1 "$out/$name-flipped.log")"
    fi
}
vectors vec-build glmark2-build-vbo 1-2 scan.out.hex 100 2
vectors vec-texture glmark2-texture-mipmap 1-1 tex.out.hex 100 0
# units=tex: the texture unit alone
rm -rf "$out/vec-units"
FIXPIPE_VECTORS="$out/vec-units,frames=1-1,units=tex" run --xvfb -- eglretrace \
    "$root/traces/recorded/glmark2-texture-mipmap.trace" > "$out/vec-units.log" 2>&1
tq=$(sed -n 's/^tex_quads //p' "$out/vec-units/scan.txt" 2>/dev/null)
tr=$(sed -n 's/^triangles //p' "$out/vec-units/scan.txt" 2>/dev/null)
if [ "$tr" = 0 ] && [ "${tq:-0}" -gt 0 ] && "$build/tools/fp-vectors" "$out/vec-units" \
        > "$out/vec-units-replay.log" 2>&1; then
    pass "vectors with units=tex: $tq texture quads, no triangle, replayed bit-exactly"
else
    fail "vectors with units=tex: triangles '$tr', texture quads '$tq' ($(tail -n 1 "$out/vec-units-replay.log" 2>/dev/null))"
fi
# 7. a malformed list in a setting: reported once, with the accepted keys, and
# nothing of it takes effect (no vectors directory; the cycle model's defaults)
bad_setting() { # NAME VALUE MUST_SAY
    rm -rf "$out/bad-vec"
    run --no-xvfb -- env "$1=$2" FIXPIPE_STATS=1 "$build/tools/fp-demo" --frames 1 --size 64x64 \
        > "$out/bad-$1.log" 2>&1
    n=$(grep -c "^fixpipe: bad $1 " "$out/bad-$1.log")
    if [ "$n" = 1 ] && grep -q -- "$3" "$out/bad-$1.log" && [ ! -e "$out/bad-vec" ]; then
        pass "$1='$2' reported once: $(grep "^fixpipe: bad $1 " "$out/bad-$1.log" | cut -c1-100)..."
    else
        fail "$1='$2': $n reports, or none saying '$3', or its directory written (log: $out/bad-$1.log)"
    fi
}
bad_setting FIXPIPE_VECTORS "$out/bad-vec,frames=3-1" "frames=3-1 (accepted: frames=A-B"
bad_setting FIXPIPE_VECTORS "$out/bad-vec,,units=tex" "an empty item"
bad_setting FIXPIPE_CYCLES "clock=100,warp=9" "unknown key 'warp' (accepted: clock=MHZ"
defaults="clock=100,setup=24,cull=2,span=1,pixel=1,cores=6,texels=4,fragments=1"
if grep -qF "cycles ($defaults)" "$out/bad-FIXPIPE_CYCLES.log"; then
    pass "FIXPIPE_CYCLES refused: the cycle model keeps its defaults"
else
    fail "FIXPIPE_CYCLES refused: not the defaults ($(grep -o 'cycles ([^)]*)' "$out/bad-FIXPIPE_CYCLES.log"))"
fi
checks_end
