#!/usr/bin/python3
"""interp-cost-charts: the interpolator cost figures of docs/interp-modes.md
from fp-interp-cost's CSVs, drawn by matplotlib (Debian's python3-matplotlib).

usage: interp-cost-charts.py OUTDIR IMGDIR
  reads OUTDIR/cost.csv (pixels,mode,add,mul,div) and OUTDIR/cores.csv
  (pixels,unit,cores,pixels_per_clock); writes IMGDIR/interp-cost.png and
  IMGDIR/interp-cores.png
"""
import argparse
import csv
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

MODES = [("scanline", "scan-line walk (000)"), ("baseline", "walk per pixel (002's baseline)"),
         ("barycentric", "barycentric (001)"), ("vector", "vector (002)")]


def rows(path):
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def cost_chart(cost, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6), dpi=100)
    fig.suptitle("Interpolator operations per covered pixel "
                 "(Z, R, G, B registers; seed profile; fp-interp-cost)")
    for ax, op, title in ((axes[0], "add", "additions"), (axes[1], "mul", "multiplications")):
        for mode, label in MODES:
            pts = [(int(r["pixels"]), float(r[op])) for r in cost if r["mode"] == mode]
            pts = [(x, y) for x, y in pts if y > 0]   # a log axis has no zero
            if pts:
                ax.plot(*zip(*pts), marker="o", linewidth=2, label=label)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlim(350, 45000)
        ax.set_ylim(0.01, 30000)
        ax.set_xlabel("polygon size (pixels)")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(loc="upper left", fontsize=9)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def cores_chart(cores, path):
    fig, ax = plt.subplots(figsize=(8, 4.8), dpi=100)
    ax.set_title("Pixels per clock: seed 001's N cores against seed 000's scan-line unit "
                 "(fp-interp-cost)", fontsize=10)
    counts = sorted({int(r["cores"]) for r in cores if r["unit"] == "barycentric"})
    for n in counts:
        pts = [(int(r["pixels"]), float(r["pixels_per_clock"]))
               for r in cores if r["unit"] == "barycentric" and int(r["cores"]) == n]
        ax.plot(*zip(*pts), marker="o", linewidth=2, label=f"{n} cores (001)")
    pts = [(int(r["pixels"]), float(r["pixels_per_clock"]))
           for r in cores if r["unit"] == "scanline"]
    ax.plot(*zip(*pts), marker="o", linewidth=3, linestyle="--", color="black",
            label="scan-line (000)")
    ax.set_xscale("log")
    ax.set_xlim(350, 45000)
    ax.set_xlabel("polygon size (pixels)")
    ax.set_ylabel("covered pixels per clock")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), fontsize=9)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description="the interpolator cost charts")
    ap.add_argument("outdir", help="fp-interp-cost's output directory")
    ap.add_argument("imgdir", help="where the PNGs go")
    a = ap.parse_args()
    cost_chart(rows(os.path.join(a.outdir, "cost.csv")), os.path.join(a.imgdir, "interp-cost.png"))
    cores_chart(rows(os.path.join(a.outdir, "cores.csv")),
                os.path.join(a.imgdir, "interp-cores.png"))


if __name__ == "__main__":
    main()
