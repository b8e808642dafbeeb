#!/bin/sh
# ./fixpipe explain (tools/fp-explain, docs/explain.md) on checked-in traces, against the
# model at its maximal precision, with a difference planted by a setting:
#   FIXPIPE_PROFILE=seed:xy=12.2 on glmark2-build-vbo: the first diverging draw's top unit
#     is positions, for at least 90% of its differing pixels;
#   FIXPIPE_TEXFMT=dfx17 on glmark2-terrain: texture, for at least 90%;
#   explain.json has the fields the report promises, and the driver's per-draw rows
#     (FIXPIPE_EVENTS) line up with the trace's draw calls;
#   the page renders in headless Chromium: its verdict and attribution in the DOM, every
#     picture decodes, the screenshot is not blank;
#   bad input: a missing trace, a file that is not a trace, frames outside the trace, a
#     reference that is not built, a replay that crashes: exit 1 and one message each,
#     and a complete earlier report at --out left as it was, nothing half-written beside it.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=explain
. "$(dirname "$0")/checks.sh"

explain="/usr/bin/python3 $root/tools/fp-explain"
traces=$root/traces/recorded
py=/usr/bin/python3

# planted NAME SETTING TRACE UNIT: the top unit of the first divergence is UNIT for >= 90%
planted() {
    if ! env "$2" $explain "$traces/$3.trace" --reference maximal --threshold 60 \
            --out "$out/$1" > "$out/$1.log" 2>&1; then
        fail "$2 on $3: fp-explain failed: $(tail -n 1 "$out/$1.log")"
        return
    fi
    verdict=$($py - "$out/$1/explain.json" "$4" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
fd, att = r["first_divergence"], r["attribution"]
need = {"frame", "call", "call_text", "pixels", "psnr"}
if not fd or not need <= set(fd) or not r["draws"] or not att:
    print("explain.json lacks first_divergence fields, draws or attribution"); sys.exit()
units = [a["unit"] for a in att]
if sorted(units) != sorted(["positions", "depth", "color", "perspective", "texture",
                            "backend"]):
    print(f"attribution names {units}"); sys.exit()
if [a["pixels"] for a in att] != sorted((a["pixels"] for a in att), reverse=True):
    print("attribution is not largest first"); sys.exit()
top = att[0]
share = top["pixels"] / fd["pixels"] if fd["pixels"] else 0
if top["unit"] != sys.argv[2] or share < 0.9:
    print(f"top unit {top['unit']} with {top['pixels']} of {fd['pixels']} pixels"); sys.exit()
if not r.get("events") or r.get("draw_rows_match") is not True:
    print("no FIXPIPE_EVENTS rows, or they do not line up with the trace's draw calls")
    sys.exit()
print(f"ok {top['unit']}: {top['pixels']} of {fd['pixels']} pixels at call {fd['call']}")
EOF
)
    case $verdict in
    ok*) pass "$2 on $3: ${verdict#ok }" ;;
    *) fail "$2 on $3: $verdict" ;;
    esac
}

planted xy FIXPIPE_PROFILE=seed:xy=12.2 glmark2-build-vbo positions
planted dfx17 FIXPIPE_TEXFMT=dfx17 glmark2-terrain texture

# ---- the event maps in the page: fx24.8 flushes texture coordinates on every frame of
# glmark2-texture-mipmap (tests/e2e/events.sh), dfx24 on none
for fmt in fx24.8 dfx24; do
    if ! FIXPIPE_TEXFMT=$fmt $explain "$traces/glmark2-texture-mipmap.trace" --reference maximal \
            --out "$out/maps-$fmt" > "$out/maps-$fmt.log" 2>&1; then
        fail "$fmt: fp-explain failed: $(tail -n 1 "$out/maps-$fmt.log")"
        continue
    fi
    eval "n_$(echo $fmt | tr -d .)=$(grep -c "alt='frame [0-9]* texflush'" "$out/maps-$fmt/report.html")"
done
if [ "${n_fx248:-0}" = 4 ] && [ "${n_dfx24:-1}" = 0 ]; then
    pass "the page maps the texture flushes of fx24.8's 4 frames, none of dfx24's"
else
    fail "texflush maps in the page: fx24.8 ${n_fx248:-?} (want 4), dfx24 ${n_dfx24:-?} (want 0)"
fi

# ---- the page in a real browser
page=$out/xy/report.html
if [ ! -f "$page" ]; then
    fail "no report to render"
elif ! command -v chromium >/dev/null; then
    fail "chromium is not installed (./fixpipe setup installs it)"
else
    ( cd "$out" && timeout 120 chromium --headless --no-sandbox --disable-gpu \
        --hide-scrollbars --window-size=1300,2400 --dump-dom "file://$page" \
        > "$out/dom.html" 2> "$out/chromium.log" )
    ( cd "$out" && timeout 120 chromium --headless --no-sandbox --disable-gpu \
        --hide-scrollbars --window-size=1300,2400 --screenshot="$out/report.png" \
        "file://$page" >> "$out/chromium.log" 2>&1 )
    verdict=$($py - "$out/dom.html" "$out/report.png" "$page" <<'EOF'
import base64, io, re, sys
from PIL import Image
dom = open(sys.argv[1], errors="replace").read()
if not re.search(r'id="verdict"[^>]*>[^<]*First divergence', dom):
    print("the rendered DOM has no verdict"); sys.exit()
if not re.search(r'id="attribution".*?<td class="l">positions</td>', dom, re.S):
    print("the rendered DOM has no attribution table naming positions"); sys.exit()
imgs = re.findall(r"src='data:image/png;base64,([^']*)'", open(sys.argv[3]).read())
for b in imgs:
    Image.open(io.BytesIO(base64.b64decode(b))).load()
shot = Image.open(sys.argv[2]).convert("RGB")
colours = len(shot.getcolors(1 << 24) or [])
if colours < 256:
    print(f"the screenshot has {colours} colours: nothing rendered"); sys.exit()
print(f"ok {len(imgs)} pictures decode, screenshot of {colours} colours")
EOF
)
    case $verdict in
    ok*) pass "the report renders in headless Chromium: ${verdict#ok }" ;;
    *) fail "headless Chromium: $verdict" ;;
    esac
fi

# ---- bad input: exit 1, one message, the complete report at --out untouched
keep=$out/keep
$explain "$traces/glmark2-texture-mipmap.trace" --reference maximal --out "$keep" \
    > "$out/keep.log" 2>&1 || fail "the report kept for the bad-input checks: $(tail -n 1 "$out/keep.log")"
cp "$keep/explain.json" "$out/keep.json" 2>/dev/null

# bad NAME MESSAGE-REGEX COMMAND...: exit 1, the message on stderr once, $keep intact
bad() {
    name=$1 want=$2
    shift 2
    "$@" --out "$keep" > "$out/bad.out" 2> "$out/bad.err"
    rc=$?
    n=$(grep -c -E "$want" "$out/bad.err")
    left=$(ls -a "$out" | grep -c '^\.explain-')
    if [ $rc != 1 ]; then
        fail "$name: exit status $rc, not 1"
    elif [ "$n" != 1 ]; then
        fail "$name: the message /$want/ printed $n times: $(tail -n 1 "$out/bad.err")"
    elif ! cmp -s "$keep/explain.json" "$out/keep.json"; then
        fail "$name: the earlier report at --out changed"
    elif [ "$left" != 0 ]; then
        fail "$name: a half-written directory is left beside --out"
    else
        pass "$name: $(grep -E "$want" "$out/bad.err")"
    fi
}

bad "a missing trace" "no such trace file" $explain "$out/none.trace"
printf 'not a trace\n' > "$out/text.trace"
bad "a file that is not a trace" "is not a trace apitrace can read" $explain "$out/text.trace"
bad "frames outside the trace" "outside the trace's frames 0-3" \
    $explain "$traces/glmark2-texture-mipmap.trace" --frames 2-9
bad "a reference that is not built" "fixpipe is not built" \
    env FIXPIPE_WORK="$out/no-build" $explain "$traces/glmark2-texture-mipmap.trace" \
    --reference maximal

# a replay that crashes at its second snapshot: an eglretrace that writes the first and
# then dies of SIGSEGV
mkdir -p "$out/crash-bin"
cat > "$out/crash-bin/eglretrace" <<EOF
#!/bin/sh
for a; do
    case \$a in
    --snapshot-prefix=*) prefix=\${a#*=} ;;
    --snapshot=*) first=\$(echo "\${a#*=}" | cut -d, -f1) ;;
    --dump-state=*) echo '"GL_RENDERER": "fixpipe (seed)"'; exit 0 ;;
    esac
done
cp "$root/docs/img/demo-fixpipe.png" "\$prefix\$(printf %010d "\$first").png" 2>/dev/null ||
    $py -c "from PIL import Image; Image.new('RGB', (8, 8)).save('\$prefix\$(printf %010d "\$first").png')"
kill -SEGV \$\$
EOF
chmod +x "$out/crash-bin/eglretrace"
bad "a replay that crashes" "crashed \\(signal 11\\) after the snapshot of call" \
    env FIXPIPE_RETRACE="$out/crash-bin/eglretrace" $explain "$traces/glmark2-texture-mipmap.trace"

checks_end
