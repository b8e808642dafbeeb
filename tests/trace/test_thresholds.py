#!/usr/bin/env python3
"""The threshold check of tools/fp-trace on synthetic snapshot directories: frames within
the limits of traces/thresholds.txt pass, a planted regression (a block gone wrong in one
frame), a missing frame or a trace without a fixpipe line fail with a non-zero exit.

usage: test_thresholds.py FP_TRACE FP_COMPARE
Prints one line per check and 'thresholds: N passed, N failed'."""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(os.path.dirname(HERE), "harness")]
from pngs import base, plant, write_png  # noqa: E402
from tally import Tally  # noqa: E402

FP_TRACE, FP_COMPARE = sys.argv[1], sys.argv[2]
# fp-trace finds fp-compare as BUILD/tools/fp-compare.
BUILD = os.path.dirname(os.path.dirname(os.path.abspath(FP_COMPARE)))
W, H = 80, 60
T = Tally()
check = T.check


def frames(d, changes_per_frame):
    os.makedirs(d, exist_ok=True)
    px = base(W, H)
    for i, ch in enumerate(changes_per_frame):
        # eglretrace's names: the call number of the snapshot.
        write_png(os.path.join(d, f"{1000 + 37 * i:010d}.png"), W, H, plant(px, W, ch),
                  alpha=False)


def judge(tmp, name, test, driver="fixpipe", heat=None):
    cmd = [sys.executable, FP_TRACE, "judge", "--name", name, "--driver", driver,
           "--ref", os.path.join(tmp, "ref"), "--test", test, "--build", BUILD,
           "--thresholds", os.path.join(tmp, "thresholds.txt")]
    if heat:
        cmd += ["--heatmaps", heat]
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def main():
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "thresholds.txt"), "w") as f:
            f.write("# TRACE DRIVER diff% over8% mean psnr\n"
                    "demo-*   fixpipe  1.0  0.05  0.05  45\n"
                    "demo-*   softpipe -    -     -     30\n"
                    "exact    fixpipe  0    0     0     -\n")
        frames(os.path.join(tmp, "ref"), [{}, {}, {}])
        # Edge-like noise: a few pixels 1-2 LSB off, one 30 off: within the limits.
        noise = {(x, 10 + x % 7): (1 + x % 2, 0, -1, 0) for x in range(0, 40, 2)}
        noise[(70, 50)] = (30, 0, 0, 0)
        frames(os.path.join(tmp, "good"), [noise, {}, noise])
        rc, out = judge(tmp, "demo-a", os.path.join(tmp, "good"))
        check("within thresholds: exit 0", rc == 0 and "1 passed, 0 failed" in out, out)

        # The planted regression: a 20x10 block 60 LSB off in the middle frame only.
        block = {(x, y): (0, -60, 0, 0) for x in range(30, 50) for y in range(20, 30)}
        frames(os.path.join(tmp, "bad"), [noise, block, noise])
        rc, out = judge(tmp, "demo-a", os.path.join(tmp, "bad"), heat=os.path.join(tmp, "hm"))
        check("planted regression: exit 1", rc == 1 and "0 passed, 1 failed" in out, out)
        check("planted regression: names the limits",
              "diff_percent 4.167 > 1" in out and "over8_percent" in out and "psnr" in out, out)
        check("planted regression: per-frame figures",
              "frame 0000001037:    200 px (4.167%)" in out, out)
        hm = os.path.join(tmp, "hm", "fixpipe-vs-llvmpipe-0000001037.heat.png")
        check("planted regression: heat map of the worst frame", os.path.exists(hm), out)

        # The same frames judged for softpipe, whose line only asks PSNR >= 30.
        rc, out = judge(tmp, "demo-a", os.path.join(tmp, "bad"), driver="softpipe")
        check("softpipe line is its own: exit 0", rc == 0, out)

        # A frame the driver did not produce (a crash mid-trace) fails.
        os.remove(os.path.join(tmp, "good", f"{1000 + 37 * 2:010d}.png"))
        rc, out = judge(tmp, "demo-a", os.path.join(tmp, "good"))
        check("missing frame: exit 1", rc == 1 and "1 of 3 frames missing" in out, out)

        # Exact line: a single 1-LSB pixel is a regression.
        frames(os.path.join(tmp, "one"), [{}, {(3, 3): (0, 0, 1, 0)}, {}])
        rc, out = judge(tmp, "exact", os.path.join(tmp, "one"))
        check("exact trace, 1 LSB: exit 1", rc == 1, out)
        rc, out = judge(tmp, "exact", os.path.join(tmp, "ref"))
        check("exact trace, identical: exit 0", rc == 0, out)

        # fixpipe needs a line for every trace; softpipe figures are informative without one.
        rc, out = judge(tmp, "unlisted", os.path.join(tmp, "good"))
        check("no fixpipe threshold: exit 1", rc == 1 and "no line for unlisted" in out, out)
        rc, out = judge(tmp, "unlisted", os.path.join(tmp, "ref"), driver="softpipe")
        check("no softpipe threshold: exit 0", rc == 0, out)

    return T.summary("thresholds")


if __name__ == "__main__":
    sys.exit(main())
