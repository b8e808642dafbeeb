#!/bin/sh
# The overhead of --slurm on this machine (docs/cluster.md): a one-node cluster of its own
# (tests/slurm/cluster.sh), then the same campaigns locally and through Slurm, wall time from
# the command's start to its verdict:
#   piglit smoke, and the quick sweep on the short traces, locally and as 2 shards;
#   a list of 4 tests with the fake piglit (no GL: the campaign itself takes well under a
#     second) locally and as 1, 2, 4 and 8 shards: Slurm's own cost per job.
# Prints one line a run; needs root, slurm-wlm and munge.  Usage: tests/slurm/measure.sh [DIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
dir=${1:-$root/out/slurm-measure}
rm -rf "$dir"
mkdir -p "$dir"
"$here/cluster.sh" start "$dir/cluster" > /dev/null
trap '"$here/cluster.sh" stop "$dir/cluster"' EXIT
export SLURM_CONF=$dir/cluster/slurm.conf

timed() { # label command...: its wall time and exit status
    label=$1; shift
    t0=$(date +%s.%N)
    rc=0
    "$@" > "$dir/$label.log" 2>&1 || rc=$?
    t1=$(date +%s.%N)
    printf '%-28s %7.1f s  exit %s\n' "$label" "$(echo "$t1 - $t0" | bc)" "$rc"
}

echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores ($(sed -n 's/^model name[^:]*: //p' /proc/cpuinfo | head -n 1)), load $(cut -d' ' -f1-3 /proc/loadavg)"
timed piglit-smoke-local "$root/fixpipe" piglit smoke --out "$dir/smoke-local"
timed piglit-smoke-slurm-2 "$root/fixpipe" piglit smoke --slurm --nodes 2 --wait --out "$dir/smoke-slurm"
timed sweep-quick-local "$root/fixpipe" sweep --grid quick --traces short --no-docs --out "$dir/sweep-local"
timed sweep-quick-slurm-2 "$root/fixpipe" sweep --grid quick --traces short --no-docs --slurm --nodes 2 --wait --out "$dir/sweep-slurm"
mkdir -p "$dir/exp"
: > "$dir/exp/fixpipe-fails.txt"
printf 'fake@a@pass-1\nfake@b@pass-2\nfake@c@pass-3\nfake@d@pass-4\n' > "$dir/tiny.txt"
export FIXPIPE_PIGLIT=$root/tests/harness/fake-piglit FIXPIPE_PIGLIT_DIR=$dir/no-piglit \
    FIXPIPE_PIGLIT_EXPECTATIONS=$dir/exp
timed tiny-local "$root/fixpipe" piglit "$dir/tiny.txt" --out "$dir/tiny-local"
for n in 1 2 4 8; do
    timed "tiny-slurm-$n" "$root/fixpipe" piglit "$dir/tiny.txt" --slurm --nodes $n --wait --out "$dir/tiny-slurm-$n"
done
echo "load $(cut -d' ' -f1-3 /proc/loadavg)"
