#!/bin/sh
# ./fixpipe sweep's machinery on a small grid (tools/fp-sweep --grid quick: seed and
# seed:xy=12.4) over one trace and the seed-003 scene.  Checks:
#   it runs, and its CSV has the two references, the maximal-precision model and the
#     two settings, each with every figure;
#   the comparison sees differences (softpipe against llvmpipe is not 0), and the
#     maximal model rendered a second time is identical to its first render
#     (determinism: the maximal row is that second render);
#   the measurement sees precision: seed:xy=12.4 is further from the maximal model
#     than seed is;
#   the two charts are PNG files;
#   the figure scripts' charts (tools/bench-chart, tools/texfmt-charts) are 640x400
#     PNG files from a good data file, and a malformed data file is refused;
#   tools/replay-bench-report prints its tables and draws its charts from a made-up OUT.
# One line per check, then "N passed, N failed"; exit 1 on a failure.
checks=sweep
. "$(dirname "$0")/checks.sh"

if ! /usr/bin/python3 "$root/tools/fp-sweep" --grid quick --traces glmark2-build-vbo --no-docs \
        --out "$out" --build "$build" > "$out/sweep.log" 2>&1; then
    fail "fp-sweep --grid quick: $(tail -n 1 "$out/sweep.log")"
    checks_end
    exit
fi
pass "fp-sweep --grid quick ran"

# field SETTING COLUMN: one figure of the CSV
field() {
    /usr/bin/python3 - "$out/sweep.csv" "$1" "$2" <<'PY'
import csv, sys
rows = {r["setting"]: r for r in csv.DictReader(open(sys.argv[1]))}
print(rows.get(sys.argv[2], {}).get(sys.argv[3], "missing"))
PY
}

rows=$(($(wc -l < "$out/sweep.csv") - 1))
empty=$(/usr/bin/python3 - "$out/sweep.csv" <<'PY'
import csv, sys
keys = ("run_time_s", "llvm_mean", "llvm_psnr", "max_mean", "max_psnr", "persp_llvm_psnr",
        "sat_xy", "tex_flush", "watertight_holes", "watertight_twice")
print(sum(1 for r in csv.DictReader(open(sys.argv[1]))
          if r["family"] != "reference" for k in keys if r[k] == ""))
PY
)
if [ "$rows" = 5 ] && [ "$empty" = 0 ]; then
    pass "sweep.csv: llvmpipe, softpipe, maximal, seed, xy=12.4, every figure present"
else
    fail "sweep.csv: $rows rows (want 5), $empty empty figures"
fi

sp=$(field softpipe llvm_mean)
if awk -v m="$sp" 'BEGIN { exit !(m + 0 > 0) }' && [ "$(field maximal max_psnr)" = inf ]; then
    pass "softpipe against llvmpipe $sp (the comparison sees differences); the maximal model rendered twice identical"
else
    fail "softpipe against llvmpipe $sp (want > 0), the maximal model's second render $(field maximal max_psnr) dB (want inf)"
fi

s=$(field seed max_psnr) c=$(field xy=12.4 max_psnr)
if awk -v s="$s" -v c="$c" 'BEGIN { if (s == "inf") s = 1e9; exit !(c + 1 < s) }'; then
    pass "xy=12.4 is further from the maximal model ($c dB) than seed ($s dB)"
else
    fail "xy=12.4 ($c dB) is not further from the maximal model than seed ($s dB)"
fi

for f in pareto bits; do
    if [ "$(head -c 8 "$out/$f.png" 2>/dev/null | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; then
        pass "$f.png drawn"
    else
        fail "$f.png missing or not a PNG"
    fi
done

# png_size FILE: "PNG WxH", or nothing for a file that is not an image
png_size() {
    /usr/bin/python3 -c 'import sys
from PIL import Image
im = Image.open(sys.argv[1])
print(im.format, "%dx%d" % im.size)' "$1" 2>/dev/null
}
# refused SCRIPT ARGS...: tools/SCRIPT exits non-zero and writes none of the PNGs
# named in ARGS
refused() {
    _s=$1
    shift
    ! /usr/bin/python3 "$root/tools/$_s" "$@" 2>/dev/null || return 1
    for _p in "$@"; do case $_p in *.png) [ ! -e "$_p" ] || return 1 ;; esac; done
}
# softpipe not measured: left off the chart
printf 'name\tms_per_frame\tmean_error\nfixpipe seed\t41.2\t0.84\nsoftpipe\t\t\nllvmpipe\t6.3\t0\n' \
    > "$out/bench.tsv"
printf 'name\tms_per_frame\tmean_error\nfixpipe seed\tn/a\t0.84\n' > "$out/bench-bad.tsv"
if /usr/bin/python3 "$root/tools/bench-chart" "$out/bench.tsv" "$out/bench.png" &&
   [ "$(png_size "$out/bench.png")" = "PNG 640x400" ] &&
   refused bench-chart "$out/bench-bad.tsv" "$out/bench-bad.png"; then
    pass "bench-chart draws a 640x400 PNG and refuses a run time that is not a number"
else
    fail "bench-chart: no 640x400 PNG from a good file (got '$(png_size "$out/bench.png")'), or a bad file accepted"
fi
hdr() { printf 'series\tname\tmantissa_bits\tms_median\tground_mean\tpanel0_mean\tpanel1_mean\n'; }
{
    hdr
    printf 'format\tfloat\t\t30.1\t0\t\t\n'
    printf 'format\tfx16.16\t\t31.0\t2.7\t\t\n'
    printf 'sweep\tdfx17\t12\t32.1\t40\t60\t30\n'
    printf 'sweep\tdfx18\t13\t32.2\t21\t36\t20\n'
    printf 'sweep\tdfx19\t14\t32.3\t0.0004\t23\t15\n'
} > "$out/texfmt.tsv"
# a sweep row without its second panel
{ hdr; printf 'sweep\tdfx17\t12\t32.1\t40\t60\t\n'; } > "$out/texfmt-bad.tsv"
set -- --setup "fp-persp 640x480 (mipmap)" --frames 9 --panels 4,8
if /usr/bin/python3 "$root/tools/texfmt-charts" "$out/texfmt.tsv" "$out/texfmt.png" "$out/texfmt-sweep.png" "$@" &&
   [ "$(png_size "$out/texfmt.png") $(png_size "$out/texfmt-sweep.png")" = "PNG 640x400 PNG 640x400" ] &&
   refused texfmt-charts "$out/texfmt-bad.tsv" "$out/texfmt-bad.png" "$out/texfmt-bad-sweep.png" "$@"; then
    pass "texfmt-charts draws its two 640x400 PNGs and refuses a sweep row without a panel"
else
    fail "texfmt-charts: no two 640x400 PNGs from a good file, or a bad file accepted"
fi

# tools/replay-bench-report on a made-up OUT: two rounds of four configurations, a trace
# of 2 scenes of 3 frames (the last without a swap), fixpipe's counters, two snapshots' kv
rb=$out/replay-bench; rm -rf "$rb"; mkdir -p "$rb/fixpipe.1.snap"
{
    printf 'config\trun\treplay_s\tfirst_frame_s\tmean_err\tworst_psnr\tframes_compared\n'
    for r in 1 2; do
        printf 'llvmpipe\t%s\t6.00\t0.10\tn/a\tn/a\t2\n' $r
        printf 'fixpipe\t%s\t%s\t0.11\t0.0340\t48.25\t2\n' $r "$([ $r = 1 ] && echo 9.00 || echo 9.60)"
        printf 'fixpipe-1thread\t%s\t16.20\t0.11\t0.0340\t48.25\t2\n' $r
        printf 'llvmpipe-1thread\t%s\t9.00\t0.12\t0.0000\tinf\t2\n' $r
    done
} > "$rb/results.tsv"
for r in 1 2; do
    for c in llvmpipe fixpipe llvmpipe-1thread; do
        printf 'rendering_finished %s\n' 0 1000000000 3000000000 4000000000 4500000000 > "$rb/$c.$r.log"
    done
    printf 'rendering_finished %s\n' 0 1700000000 5100000000 6800000000 7650000000 > "$rb/fixpipe-1thread.$r.log"
done
printf 'fixpipe work at frame %s: quads %s divided 10 skip_w %s\n' 1 100 5 2 200 5 3 300 5 4 400 5 5 500 9 6 600 10 \
    > "$rb/fixpipe.stats.log"
printf 'mean_err_r=0.5000\nmean_err=0.0300\npsnr=inf\n' > "$rb/fixpipe.1.snap/a.kv"
printf 'mean_err=0.0401\npsnr=41.20\n' > "$rb/fixpipe.1.snap/b.kv"
report=$root/tools/replay-bench-report
if "$report" report "$rb" --configs "llvmpipe fixpipe fixpipe-1thread llvmpipe-1thread" --frames 6 \
       --scenes "one two" --nproc 2 > "$rb/report.md" &&
   grep -qxF '| fixpipe | 9.3 | 0.6 | 1.55 | n/a | 0.0340 | 48.25 | 0.11 |' "$rb/report.md" &&
   grep -qxF "fixpipe's speed-up on 2 cores (fixpipe-1thread's time ÷ fixpipe's), per round: 1.74 (1.69–1.80)" "$rb/report.md" &&
   grep -qxF '| one | 3 | 3 | 5.1 | 3 | 1.00 | n/a | 50% | – | – | – | 0% | 0% | 0% |' "$rb/report.md" &&
   grep -qxF '| two | 1.70 | 1.00 |' "$rb/report.md" &&
   [ "$(png_size "$rb/speedup-per-scene.png") $(png_size "$rb/replay-time-vs-error.png")" = "PNG 720x420 PNG 720x420" ] &&
   [ "$("$report" errors "$rb/fixpipe.1.snap")" = "0.0350 41.20" ] &&
   ! "$report" report "$rb" --configs llvmpipe --frames 7 --scenes "one two" 2>/dev/null; then
    pass "replay-bench-report prints its tables and draws its two 720x420 charts from an OUT"
else
    fail "replay-bench-report: a table line, a chart or a run's error not as expected (see $rb/report.md)"
fi

checks_end
