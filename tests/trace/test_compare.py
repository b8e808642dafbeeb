#!/usr/bin/env python3
"""fp-compare on synthetic images with planted differences: the figures it prints must be
exactly the ones the planted set implies (count, box, max, mean, PSNR), and its limits and
input errors must give the documented exit status.

usage: test_compare.py FP_COMPARE
Prints one line per check and 'compare: N passed, N failed'."""
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(os.path.dirname(HERE), "harness")]
from pngs import base, plant, write_png  # noqa: E402
from tally import Tally  # noqa: E402

TOOL = sys.argv[1]
W, H = 64, 48
N = W * H
T = Tally()
check = T.check


def run(a, b, *opts):
    p = subprocess.run([TOOL, a, b, "--format=kv", *opts], capture_output=True, text=True)
    kv = dict(line.split("=", 1) for line in p.stdout.splitlines() if "=" in line)
    return p.returncode, kv, p.stderr


def expected(changes, threshold=0):
    """The figures the planted changes imply, from their definitions in docs/demo.md."""
    diff = [xy for xy, d in changes.items() if max(abs(v) for v in d) > threshold]
    sq = sum(d[c] ** 2 for d in changes.values() for c in range(3))
    ab = sum(abs(d[c]) for d in changes.values() for c in range(3))
    e = {
        "diff_pixels": str(len(diff)),
        "diff_percent": f"{100.0 * len(diff) / N:.4f}",
        "max_err": str(max([abs(v) for d in changes.values() for v in d] or [0])),
        "mean_err": f"{ab / (3.0 * N):.4f}",
        "psnr": "inf" if sq == 0 else f"{10 * math.log10(255.0 ** 2 / (sq / (3.0 * N))):.2f}",
    }
    if diff:
        xs, ys = [x for x, _ in diff], [y for _, y in diff]
        e["diff_bbox"] = f"{min(xs)},{min(ys)},{max(xs)},{max(ys)}"
    for c, ch in enumerate("rgba"):
        e[f"max_err_{ch}"] = str(max([abs(d[c]) for d in changes.values()] or [0]))
    return e


def case(name, changes, *opts, threshold=0, tmp=None, alpha_a=True, alpha_b=True):
    px = base(W, H)
    a, b = os.path.join(tmp, name + "-a.png"), os.path.join(tmp, name + "-b.png")
    write_png(a, W, H, plant(px, W, changes), alpha=alpha_a)
    write_png(b, W, H, px, alpha=alpha_b)
    rc, kv, err = run(a, b, f"--threshold={threshold}", *opts)
    exp = expected(changes, threshold)
    bad = {k: (kv.get(k), v) for k, v in exp.items() if kv.get(k) != v}
    if "diff_bbox" not in exp and "diff_bbox" in kv:
        bad["diff_bbox"] = (kv["diff_bbox"], None)
    check(f"{name}: figures", rc in (0, 1) and not bad, f"rc={rc} got/expected {bad} {err}")
    return rc, kv


def main():
    with tempfile.TemporaryDirectory() as tmp:
        case("identical", {}, tmp=tmp)
        # 16 pixels, red +10 each: worked by hand, 160/(3*3072) = 0.0174 mean,
        # MSE 1600/9216, PSNR 10*log10(65025*9216/1600) = 55.74 dB.
        sixteen = {(4 + 3 * i, 7 + (i % 4)): (10, 0, 0, 0) for i in range(16)}
        _, kv = case("red16", sixteen, tmp=tmp)
        check("red16: hand-worked figures",
              (kv.get("diff_pixels"), kv.get("mean_err"), kv.get("psnr"), kv.get("max_err"))
              == ("16", "0.0174", "55.74", "10"), str(kv))
        mixed = {(0, 0): (-37, 5, 0, 0), (63, 47): (0, 0, 100, 0), (10, 20): (3, -3, 3, 0),
                 (11, 20): (1, 0, 0, 0), (30, 5): (0, 0, 0, -40), (31, 40): (-8, 8, -8, 0)}
        case("mixed", mixed, tmp=tmp)
        # A threshold leaves out pixels differing by at most T, but not from max/mean/PSNR.
        case("mixed-t8", mixed, threshold=8, tmp=tmp)
        # Alpha counts for 'differs' and max, not for mean and PSNR.
        case("alpha-only", {(5, 5): (0, 0, 0, -100)}, tmp=tmp)
        # eglretrace writes RGB PNGs, the demo RGBA: the same pixels compare equal.
        case("rgb-vs-rgba", {}, tmp=tmp, alpha_a=False)
        case("rgb-planted", {(2, 2): (20, 20, 20, 0)}, tmp=tmp, alpha_a=False)

        # Limits: over -> exit 1 naming the limit; at the limit -> 0.
        rc, kv = case("limit-pixels", sixteen, "--max-diff-pixels=15", tmp=tmp)
        check("limit-pixels: exit 1, named", rc == 1 and kv.get("failed") == "max_diff_pixels",
              f"rc={rc} {kv.get('failed')}")
        rc, kv = case("limit-at", sixteen, "--max-diff-pixels=16", "--max-error=10", tmp=tmp)
        check("limit-at: exit 0", rc == 0 and kv.get("result") == "pass", f"rc={rc}")
        rc, kv = case("limit-psnr", sixteen, "--min-psnr=56", tmp=tmp)
        check("limit-psnr: exit 1", rc == 1 and kv.get("failed") == "min_psnr", f"rc={rc}")

        # Bad input: size mismatch, not a PNG, missing file -> 2.
        px = base(W, H)
        a, small = os.path.join(tmp, "a.png"), os.path.join(tmp, "small.png")
        write_png(a, W, H, px)
        write_png(small, W - 1, H, [p for i, p in enumerate(px) if i % W != W - 1])
        junk = os.path.join(tmp, "junk.png")
        with open(junk, "w") as f:
            f.write("not a png\n")
        for what, other in (("size mismatch", small), ("not a PNG", junk),
                            ("missing", os.path.join(tmp, "none.png"))):
            rc, _, _ = run(a, other)
            check(f"bad input ({what}): exit 2", rc == 2, f"rc={rc}")

        # The heat map is written, with the legend strip under the image.
        hm = os.path.join(tmp, "hm.png")
        p = subprocess.run([TOOL, os.path.join(tmp, "red16-a.png"),
                            os.path.join(tmp, "red16-b.png"), "--heatmap", hm],
                           capture_output=True)
        ok = p.returncode == 0 and os.path.exists(hm)
        if ok:
            with open(hm, "rb") as f:
                head = f.read(24)
            w, h = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
            ok = (w, h) == (W, H) or (w == W and h > H)
        check("heat map written", ok)

    return T.summary("compare")


if __name__ == "__main__":
    sys.exit(main())
