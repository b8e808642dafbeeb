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
#     PNG files from a good data file, and a malformed data file is refused.
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
checks_end
