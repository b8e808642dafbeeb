#!/bin/sh
# Compiled shaders against the interpreter, and cached code against freshly
# compiled code: every end-to-end program of tolerances.txt and the demo are
# rendered through fixpipe three times,
#   FIXPIPE_DEBUG=nojit                       the reference path (tgsi_exec)
#   FIXPIPE_DEBUG=jitall, empty shader cache  every shader compiled
#   FIXPIPE_DEBUG=jitall, same cache again    every shader from the disk cache
# and the PNGs compared, the jitall run having refused no fragment or vertex
# shader and interpreted no quad (a check shown failing on a tiered run);
# the programs of fragment shaders with storage buffers, images or atomic
# counters (fsmem-*) or interpolateAt* (interpat- but its gathers), which
# stay interpreted by design (docs/jit.md), must instead have had those
# refused, and match the interpreter all the same;
# and the demo tiered (the default), where a batch that
# alone takes an interpreted shader past the threshold compiles it first
# (fp_fs_batch_ahead): each compiled shader then interpreted fewer than the
# threshold's 16,384 quads on average, which compiling only after the crossing
# cannot give, and a small frame compiles nothing.  The model (coverage, interpolation, depth, stencil,
# texture unit, back end) is the same code either way, so the e2e programs must
# match byte for byte.  The programs that gather from 2-D views clamped to
# their edges run a fourth time,
# FIXPIPE_DEBUG=jitall,nojitgather, their gathers through the texture unit's C
# functions instead of its copy in the compiled code (fp_jit_gather.c): the
# same bytes, the same work and range events counted, and the copy must have
# gathered under jitall (none under nojitgather).  The demo's lighting is float shader arithmetic, which
# LLVM may contract or reorder: it may differ by 1 LSB, nothing more.  Cached
# and compiled code must match byte for byte everywhere.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=jit-identity
. "$(dirname "$0")/checks.sh"
mkdir -p "$out/cache"

# uncompiled LOG: "F I V N C", the fragment shaders gallivm refused, the quads
# interpreted, the vertex shaders it refused, the contexts counted and the
# vertex shaders compiled, summed over the contexts
uncompiled() {
    sed -n 's/.*fragment shaders: tiered, .* failed \([0-9]*\) .*interpreted \([0-9]*\); vertex shaders compiled \([0-9]*\) failed \([0-9]*\);.*/\1 \2 \4 \3/p' \
        "$1" | awk '{ f += $1; q += $2; v += $3; c += $4; n++ } END { print (n ? f : "x") + 0, q + 0, v + 0, n + 0, c + 0 }'
}

# render NAME PROGRAM ARGS...: the three images, or a failure line
render() {
    name=$1 prog=$2
    shift 2
    for m in nojit jitall cached; do
        flag=$m; [ $m = cached ] && flag=jitall
        if ! FIXPIPE_DEBUG=$flag FIXPIPE_STATS=1 MESA_SHADER_CACHE_DIR=$out/cache \
             MESA_SHADER_CACHE_DISABLE=false \
             "$root/fixpipe" run --no-xvfb --driver fixpipe -- "$prog" -o "$out/$name.$m.png" "$@" \
             > "$out/$name.$m.log" 2>&1; then
            fail "$name: the $m run failed ($(tail -n 1 "$out/$name.$m.log"))"
            return 1
        fi
    done
    # fragment shaders with side effects or interpolateAt*: refused
    # (interpreted) under jitall
    case $name in fsmem-*|interpat-offset|interpat-sample|interpat-centroid)
        set -- $(uncompiled "$out/$name.jitall.log")
        if [ "$4" -gt 0 ] && [ "$1" -gt 0 ] && [ "$2" -gt 0 ] && [ "$3" = 0 ]; then
            pass "$name: under jitall the $1 fragment shaders with storage buffers, images or interpolateAt* stay interpreted ($2 quads)"
            return 0
        fi
        fail "$name: under jitall $1 fragment shaders refused, $2 quads interpreted, $3 vertex shaders refused (want those with storage buffers, images or interpolateAt* interpreted)"
        return 1
    esac
    # the third run must have taken every compiled shader from the cache
    set -- $(sed -n 's/.*fragment shaders: tiered, compiled \([0-9]*\) .*from the disk cache \([0-9]*\)).*/\1 \2/p' \
                 "$out/$name.cached.log" | awk '{ c += $1; h += $2 } END { print c + 0, h + 0 }')
    if [ "$1" -gt 0 ] && [ "$1" = "$2" ]; then
        pass "$name: $1 shaders compiled, all from the disk cache"
    else
        fail "$name: the cached run compiled $1 shaders, $2 from the disk cache"
        return 1
    fi
    # and under jitall no shader refused, no quad interpreted: st's NIR
    # reaches gallivm whole (gathers, multisample fetches, every built-in),
    # and every vertex shader compiles, those that sample textures too (their
    # texture instructions call the unit through draw's sampler factory,
    # mesa/patches/0016), so that nojit = jitall below holds them to
    # tgsi_exec (es2-vs-cube, es2-proj-mip)
    set -- $(uncompiled "$out/$name.jitall.log")
    if [ "$4" -gt 0 ] && [ "$1" = 0 ] && [ "$2" = 0 ] && [ "$3" = 0 ] && [ "$5" -gt 0 ]; then
        pass "$name: under jitall no shader refused, no quad interpreted, $5 vertex shaders compiled"
    else
        fail "$name: under jitall $1 fragment shaders refused, $2 quads interpreted, $3 vertex shaders refused, $5 compiled ($4 contexts counted)"
        return 1
    fi
}

same() { # NAME A B: byte-identical
    if cmp -s "$out/$1.$2.png" "$out/$1.$3.png"; then
        pass "$1: $2 = $3"
    else
        fail "$1: $2 and $3 differ ($("$build/tools/fp-compare" "$out/$1.$2.png" "$out/$1.$3.png" | grep differing))"
    fi
}

grep -v '^#' "$here/tolerances.txt" | grep -v '^[[:space:]]*$' | while IFS= read -r line; do
    echo "$line"
done > "$out/list"
while IFS= read -r line; do
    spec=${line%%|*}
    # shellcheck disable=SC2086
    set -- $spec
    name=$1 prog=$2
    shift 2
    render "$name" "$build/tests/e2e/$prog" "$@" || continue
    same "$name" nojit jitall
    same "$name" jitall cached
done < "$out/list"

# gathered NAME PROGRAM ARGS...: jitall against jitall,nojitgather
gathered() {
    name=$1 prog=$2
    shift 2
    if ! FIXPIPE_DEBUG=jitall,nojitgather FIXPIPE_STATS=1 "$root/fixpipe" run --no-xvfb \
         --driver fixpipe -- "$prog" -o "$out/$name.nojitgather.png" "$@" \
         > "$out/$name.nojitgather.log" 2>&1; then
        fail "$name: the nojitgather run failed ($(tail -n 1 "$out/$name.nojitgather.log"))"
        return 1
    fi
    same "$name" jitall nojitgather
    # the counters the unit keeps: work, texels, range events
    for log in jitall nojitgather; do
        grep -E "texels read|texture path|datapath work" "$out/$name.$log.log" > "$out/$name.$log.work"
    done
    if [ -s "$out/$name.jitall.work" ] && cmp -s "$out/$name.jitall.work" "$out/$name.nojitgather.work"; then
        pass "$name: jitall and nojitgather count the same texture work and range events"
    else
        fail "$name: the texture counters differ between jitall and nojitgather (see $out/$name.*.work)"
    fi
    set -- $(sed -n 's/.*gathers in compiled code: quads \([0-9]*\) .*/\1/p' "$out/$name.jitall.log")
    jit=${1:-0}
    set -- $(sed -n 's/.*gathers in compiled code: quads \([0-9]*\) .*/\1/p' "$out/$name.nojitgather.log")
    if [ "$jit" -gt 0 ] && [ "${1:-x}" = 0 ]; then
        pass "$name: $jit gather quads in compiled code under jitall, none under nojitgather"
    else
        fail "$name: gather quads in compiled code: jitall $jit (want some), nojitgather ${1:-?} (want 0)"
    fi
}
# the programs whose gathers the copy covers (2-D views clamped to their
# edges), and gather-ties, random coordinates at every distance from a texel
# boundary: not in tolerances.txt (drivers decide ties differently), here
# for the identity of the two units alone
{ grep -E '^(es31-gather-clamp|upscale) ' "$out/list"
  echo "es31-gather-ties e2e-es31 --case gather-ties"; } > "$out/gathering"
while IFS= read -r line; do
    spec=${line%%|*}
    # shellcheck disable=SC2086
    set -- $spec
    gname=$1 gprog=$build/tests/e2e/$2
    shift 2
    if [ ! -f "$out/$gname.jitall.log" ]; then
        render "$gname" "$gprog" "$@" || continue
        same "$gname" nojit jitall
        same "$gname" jitall cached
    fi
    gathered "$gname" "$gprog" "$@"
done < "$out/gathering"

if render demo "$build/tools/fp-demo" --scene all --frames 3; then
    if "$build/tools/fp-compare" "$out/demo.nojit.png" "$out/demo.jitall.png" \
           --threshold 1 --max-diff-pixels 0 > "$out/demo.compare" 2>&1; then
        pass "demo: nojit ~ jitall within 1 LSB ($(grep differing "$out/demo.compare" | sed 's/ *differing: *//'))"
    else
        fail "demo: nojit and jitall differ by more than 1 LSB ($(grep 'max error' "$out/demo.compare"))"
    fi
    same demo jitall cached
fi

# tiered DEMO-SIZE: the demo's "compiled C ... interpreted I ... hot before a batch H"
tiered() {
    FIXPIPE_STATS=1 MESA_SHADER_CACHE_DIR=$out/cache MESA_SHADER_CACHE_DISABLE=false \
        "$root/fixpipe" run --no-xvfb --driver fixpipe -- "$build/tools/fp-demo" --scene all \
        --frames 3 --size "$1" -o "$out/demo.tiered-$1.png" > "$out/demo.tiered-$1.log" 2>&1 &&
    sed -n 's/.*fragment shaders: tiered, compiled \([0-9]*\) .*interpreted \([0-9]*\);.*hot before a batch \([0-9]*\).*/\1 \2 \3/p' \
        "$out/demo.tiered-$1.log" | awk '{ c += $1; i += $2; h += $3 } END { print c + 0, i + 0, h + 0 }'
}
set -- $(tiered 512x512)
if [ "${1:-0}" -gt 0 ] && [ "$3" -gt 0 ] && [ "$2" -lt $(($1 * 16384)) ] &&
   "$build/tools/fp-compare" "$out/demo.nojit.png" "$out/demo.tiered-512x512.png" \
       --threshold 1 --max-diff-pixels 0 > /dev/null 2>&1; then
    pass "demo tiered: $1 shaders compiled, $3 before a batch, $2 quads interpreted; ~ nojit within 1 LSB"
else
    fail "demo tiered: compiled ${1:-?}, interpreted ${2:-?}, hot before a batch ${3:-?} (want some, fewer than 16,384 quads a shader), or unlike nojit"
fi
# the check above on a run that interpreted quads (the tiered demo's first
# ones): it must fail, or it proves nothing
set -- $(uncompiled "$out/demo.tiered-512x512.log")
if [ "$4" -gt 0 ] && [ "$2" -gt 0 ]; then
    pass "the jitall check fails on the tiered demo: $2 quads interpreted"
else
    fail "the jitall check passes a run that interpreted quads (refused $1, interpreted $2, contexts $4)"
fi
set -- $(tiered 64x64)
if [ "${1:-x}" = 0 ]; then
    pass "demo tiered at 64x64: nothing compiled ($2 quads interpreted)"
else
    fail "demo tiered at 64x64: ${1:-?} shaders compiled, want none"
fi

# Once the process has presented a frame, a shader is hot past 1,024 quads
# (fp_jit_hot_loop): a phong replay on a virtual X server, whose shader no
# batch makes hot before it, compiles after the first present, with fewer
# than 16,384 quads interpreted; headless, where nothing is presented, the
# rule never applies and the shader is interpreted longer.
# loop MODE: "compiled interpreted hot-before-a-batch hot-after-a-present"
loop() {
    phong=$root/traces/recorded/glmark2-shading-phong.trace
    if [ "$1" = x11 ]; then
        FIXPIPE_STATS=1 "$root/fixpipe" run --xvfb --driver fixpipe -- eglretrace -b "$phong"
    else
        FIXPIPE_STATS=1 "$root/fixpipe" run --no-xvfb --driver fixpipe -- \
            env WAFFLE_PLATFORM=surfaceless_egl eglretrace --headless -b "$phong"
    fi > "$out/loop.$1.log" 2>&1
    sed -n 's/.*fragment shaders: tiered, compiled \([0-9]*\) .*interpreted \([0-9]*\);.*hot before a batch \([0-9]*\), hot after a present \([0-9]*\).*/\1 \2 \3 \4/p' \
        "$out/loop.$1.log" | awk '{ c += $1; i += $2; h += $3; l += $4 } END { print c + 0, i + 0, h + 0, l + 0 }'
}
set -- $(loop x11)
x11_interp=${2:-0}
if [ "${4:-0}" -gt 0 ] && [ "$2" -lt $(($1 * 16384)) ]; then
    pass "phong on X11: $4 shaders hot after a present, $1 compiled, $2 quads interpreted"
else
    fail "phong on X11: compiled ${1:-?}, interpreted ${2:-?}, hot after a present ${4:-?} (want some, fewer than 16,384 quads a shader)"
fi
set -- $(loop headless)
if [ "${4:-x}" = 0 ] && [ "${2:-0}" -gt "$x11_interp" ]; then
    pass "phong headless: none hot after a present, $2 quads interpreted (on X11 $x11_interp)"
else
    fail "phong headless: hot after a present ${4:-?}, interpreted ${2:-?} (want none, more than on X11: $x11_interp)"
fi
checks_end
