#!/bin/sh
# The model's datapath on lanes with its skips against the scalar reference
# computing everything (docs/datapath.md): every end-to-end program of
# tolerances.txt, the demo, and every checked-in trace (traces/recorded, and
# every 50th frame of the benchmark's traces/bench/glmark2-long.trace) are
# rendered through fixpipe twice, with compiled shaders both times,
#   FIXPIPE_DEBUG=jitall                  the default datapath: lanes, skips
#   FIXPIPE_DEBUG=jitall,scalar,noskip    the scalar reference, nothing skipped
# and every image must be the same bytes.  The default runs of the programs
# must also have taken the lanes (FIXPIPE_STATS names the instruction set),
# and some of them skipped work.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=datapath-identity
. "$(dirname "$0")/checks.sh"
MODES="lanes scalar"
flags() { [ "$1" = lanes ] && echo jitall || echo jitall,scalar,noskip; }

# skips NAME: the default run's skip counters, summed over its contexts
skips() {
    sed -n 's/.*datapath: \([a-z0-9]*\); skipped: quads with a constant 1\/w \([0-9]*\), constant component-quads \([0-9]*\), texture quads without a LOD \([0-9]*\), texture quad-axes addressed per column or row \([0-9]*\), quads without gl_FragCoord [0-9]*, quads without a Z walk \([0-9]*\), quads rejected whole before shading \([0-9]*\), quads not shaded (no visible effect) \([0-9]*\).*/\1 \2 \3 \4 \5 \6 \7 \8/p' \
        "$out/$1.lanes.log" |
        awk '{ isa = $1; w += $2; c += $3; l += $4; a += $5; z += $6; e += $7; s += $8 }
             END { print isa, w + 0, c + 0, l + 0, a + 0, z + 0, e + 0, s + 0 }'
}

total_w=0 total_c=0 total_l=0 total_a=0 total_z=0 total_e=0 total_s=0 total_f=0
check_lanes() { # NAME
    set -- $(skips "$1")
    case ${1:-} in
    avx512 | avx2 | sse2) total_w=$((total_w + $2)); total_c=$((total_c + $3)); total_l=$((total_l + $4))
                 total_a=$((total_a + $5)); total_z=$((total_z + $6)); total_e=$((total_e + $7))
                 total_s=$((total_s + $8)) ;;
    *) fail "$name: the default run did not report the lanes (datapath: ${1:-none})"; return 1 ;;
    esac
    if grep -q "datapath: scalar" "$out/$name.scalar.log"; then :; else
        fail "$name: the scalar run did not report the scalar datapath"; return 1
    fi
}

# work_ok LOG SKIPS: the work counters' lines (FIXPIPE_STATS=frames:N, in the form
# "skip_w ... skip_axes A skip_fragcoord F divided D ... quads Q"): at least one, every skip count at most
# what it is a share of, and with SKIPS=none nothing skipped
work_ok() {
    awk -v none="$2" '
        { for (i = 1; i < NF; i += 2) v[$i] = $(i + 1)
          if (v["divided"] > v["quads"] || v["skip_w"] > v["divided"] ||
              v["skip_comp"] > v["comp_quads"] || v["skip_lod"] > v["lod_quads"] ||
              v["skip_axes"] > 2 * v["tex_quads"] || v["skip_fragcoord"] > v["quads"] ||
              v["skip_z"] > v["quads"] || v["skip_early"] + v["skip_shade"] > v["quads"] ||
              v["skip_footprint"] > v["tex_quads"]) bad++
          skipped = v["skip_w"] + v["skip_comp"] + v["skip_lod"] + v["skip_axes"] + v["skip_fragcoord"]
          skipped += v["skip_z"] + v["skip_early"] + v["skip_shade"] + v["skip_footprint"]
          if (none == "none" && skipped > 0) bad++
          n++ }
        END { exit !(n > 0 && !bad) }' "$1"
}

render() { # NAME PROGRAM ARGS...
    name=$1 prog=$2
    shift 2
    for m in $MODES; do
        if ! FIXPIPE_DEBUG=$(flags $m) FIXPIPE_STATS=1 \
             "$root/fixpipe" run --no-xvfb --driver fixpipe -- "$prog" -o "$out/$name.$m.png" "$@" \
             > "$out/$name.$m.log" 2>&1; then
            fail "$name: the $m run failed ($(tail -n 1 "$out/$name.$m.log"))"
            return 1
        fi
    done
    check_lanes "$name" || return 1
    for m in $MODES; do   # the totals at the context's end, as work lines
        sed -n 's/.*datapath: [a-z0-9]*; skipped: quads with a constant 1\/w \([0-9]*\), constant component-quads \([0-9]*\), texture quads without a LOD \([0-9]*\), texture quad-axes addressed per column or row \([0-9]*\), quads without gl_FragCoord \([0-9]*\), quads without a Z walk \([0-9]*\), quads rejected whole before shading \([0-9]*\), quads not shaded (no visible effect) \([0-9]*\).*/skip_w \1 skip_comp \2 skip_lod \3 skip_axes \4 skip_fragcoord \5 skip_z \6 skip_early \7 skip_shade \8/p' \
            "$out/$name.$m.log" > "$out/$name.$m.skipped"
        sed -n 's/.*datapath work: quads divided \([0-9]*\), component-quads \([0-9]*\), texture quads with a LOD from differences \([0-9]*\), texture quads \([0-9]*\), quads \([0-9]*\).*/divided \1 comp_quads \2 lod_quads \3 tex_quads \4 quads \5/p' \
            "$out/$name.$m.log" > "$out/$name.$m.shares"
        sed -n 's/.*gather quads whose footprint was addressed before \([0-9]*\).*/skip_footprint \1/p' \
            "$out/$name.$m.log" > "$out/$name.$m.footprints"
        paste -d' ' "$out/$name.$m.skipped" "$out/$name.$m.shares" "$out/$name.$m.footprints" \
            > "$out/$name.$m.work"
        total_f=$((total_f + $(awk '{ n += $2 } END { print n + 0 }' "$out/$name.$m.footprints")))
        if ! work_ok "$out/$name.$m.work" "$([ $m = scalar ] && echo none || echo some)"; then
            fail "$name: the $m run's skipped work is missing or beyond what it is a share of"
            return 1
        fi
    done
    if cmp -s "$out/$name.lanes.png" "$out/$name.scalar.png"; then
        pass "$name: lanes = scalar,noskip"
    else
        fail "$name: lanes and scalar,noskip differ ($("$build/tools/fp-compare" "$out/$name.lanes.png" "$out/$name.scalar.png" | grep differing))"
    fi
}

. "$here/identity-programs.sh"
each_program render
render demo "$build/tools/fp-demo" --scene all --frames 3

# every trace in both modes, snapshots byte for byte (eglretrace ends without
# destroying its context, and frames on the surfaceless platform are not
# presented: no FIXPIPE_STATS to check; see the end)
mode_env() { echo "FIXPIPE_DEBUG=$(flags "$1") FIXPIPE_STATS=1"; }
SAME="lanes = scalar,noskip"
. "$here/identity-replays.sh"
replay_all

# FIXPIPE_STATS=frames:1 where frames are presented (X11): one work line per frame
gears=$root/traces/recorded/es2gears.trace
swaps=$(apitrace dump --grep=eglSwapBuffers --arg-names=no "$gears" 2>/dev/null | grep -c eglSwapBuffers || true)
for m in $MODES; do
    FIXPIPE_DEBUG=$(flags $m) FIXPIPE_STATS=frames:1 "$root/fixpipe" run --xvfb --driver fixpipe -- \
        eglretrace -b "$gears" > "$out/frames.$m.log" 2>&1 || true
    sed -n 's/^fixpipe work at frame [0-9]*: //p' "$out/frames.$m.log" > "$out/frames.$m.work"
    lines=$(wc -l < "$out/frames.$m.work")
    if [ "$lines" -eq "$swaps" ] && [ "$lines" -gt 0 ] &&
       work_ok "$out/frames.$m.work" "$([ $m = scalar ] && echo none || echo some)"; then
        pass "FIXPIPE_STATS=frames:1 ($m): $lines work lines for $swaps frames presented"
    else
        fail "FIXPIPE_STATS=frames:1 ($m): $lines work lines for $swaps frames presented (log $out/frames.$m.log)"
    fi
done

taken="$total_w quads with a constant 1/w, $total_c constant component-quads, $total_l texture quads without a LOD, $total_a texture quad-axes addressed per column or row, $total_z quads without a Z walk, $total_e quads rejected whole before shading, $total_s quads not shaded, $total_f gather quads on a footprint addressed before"
if [ "$total_w" -gt 0 ] && [ "$total_c" -gt 0 ] && [ "$total_l" -gt 0 ] && [ "$total_a" -gt 0 ] &&
   [ "$total_z" -gt 0 ] && [ "$total_e" -gt 0 ] && [ "$total_s" -gt 0 ] && [ "$total_f" -gt 0 ]; then
    pass "skips taken: $taken"
else
    fail "skips taken: $taken"
fi
checks_end
