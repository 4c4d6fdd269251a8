#!/usr/bin/python3
"""Side view of a long chute at one saved frame of NAME.data, with its height and composition
along x: spheres drawn in the x-z plane (large red, small blue, base grey), the flow height
and the large spheres' volume share, both per 5-wide window. The height is the solids volume
per unit base area divided by 0.6 (the height of a layer of packing fraction 0.6 with the same
solids), which single spheres bouncing ahead of the flow hardly change. The front is the end of
the last window, counted from the inflow, whose height is at least 1. The script prints the
inflow height (the mean over the first box length of the chute), the front, the highest window
within 30 behind the front and the large share there: a bulbous head is a front higher than
the inflow, made mostly of large spheres. A second line gives the highest window anywhere past
the chute's first box length and where the flow turns to large spheres only (share above 0.9).

    /usr/bin/python3 Tools/Plot/plotChuteFront.py NAME.data out.png [time]
        [--large S,S] [--small S,S] [--box LENGTH]

out: the picture, or - for the printed lines alone. time: the frame closest to it (default: the last). --large/--small: the species indices of the
large and small spheres (default 0,3 and 1,4: MaserFedChute's chute and maser species);
--box: the maser box length (default 20): the chute starts there.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PatchCollection
from matplotlib.patches import Circle
import numpy as np

from dataFrames import read_frame


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("data")
    parser.add_argument("out")
    parser.add_argument("time", nargs="?", type=float)
    parser.add_argument("--large", default="0,3")
    parser.add_argument("--small", default="1,4")
    parser.add_argument("--box", type=float, default=20)
    args = parser.parse_args()
    time, p, header = read_frame(args.data, args.time, "plotChuteFront")
    width = header[6] - header[3]
    x, z, r, species = p[:, 0], p[:, 2], p[:, 6], p[:, 13].astype(int)
    large = np.isin(species, [int(s) for s in args.large.split(",")])
    small = np.isin(species, [int(s) for s in args.small.split(",")])
    mobile = large | small
    if not (mobile & (x >= args.box)).any():
        sys.exit("plotChuteFront: no sphere in the chute at this frame")

    window = 5.0
    edges = np.arange(0, np.ceil(x[mobile].max()) + window, window)
    centres = 0.5 * (edges[1:] + edges[:-1])
    volume = 4 / 3 * np.pi * r**3
    index = np.clip(np.floor(x / window).astype(int), 0, len(centres) - 1)
    solids = np.bincount(index[mobile], weights=volume[mobile], minlength=len(centres))
    solidsLarge = np.bincount(index[large], weights=volume[large], minlength=len(centres))
    height = solids / (window * width * 0.6)
    share = np.where(solids > 0, solidsLarge / np.maximum(solids, 1e-300), np.nan)
    inChute = centres > args.box
    inflowWindows = inChute & (centres < 2 * args.box)
    inflow = height[inflowWindows].mean()
    # The front: the end of the flow's connected part, from the inflow on.
    k = np.flatnonzero(inChute)[0]
    while k + 1 < len(centres) and height[k + 1] >= 1:
        k += 1
    front = edges[k + 1]
    head = (centres > front - 30) & (centres < front)
    k_head = np.flatnonzero(head)[np.argmax(height[head])]
    print(f"plotChuteFront: t = {time:g}: front at x = {front:.0f}; inflow height {inflow:.2f}; "
          f"highest behind the front {height[k_head]:.2f} at x = {centres[k_head]:.1f} "
          f"({height[k_head] / inflow:.2f} x the inflow); large share {share[k_head]:.2f} there, "
          f"{np.nanmean(share[inflowWindows]):.2f} at the inflow; "
          f"{np.count_nonzero(mobile & (x > front))} spheres ahead of the front")
    # Behind the front: the highest window past the first box length of the chute, and where the
    # flow turns to large spheres only (share above 0.9): a head forms where the large front,
    # slower than the inflow, holds the flow back.
    past = centres > 2 * args.box
    if past.any():
        k_max = np.flatnonzero(past)[np.argmax(height[past])]
        pure = np.flatnonzero(past & (share > 0.9) & (height > 0.5))
        where = (f"large spheres only from x = {edges[pure[0]]:.0f} (height {height[pure[0]]:.2f} there)"
                 if len(pure) else "no window of large spheres only")
        print(f"plotChuteFront: t = {time:g}: highest past x = {2 * args.box:g}: {height[k_max]:.2f} at x = "
              f"{centres[k_max]:.1f} ({height[k_max] / inflow:.3f} x the inflow), large share {share[k_max]:.2f}; {where}")
        # The thesis's head is a front of large particles higher than the inflow: the highest
        # window that is mostly large (three quarters of the volume) and large only (0.9).
        parts = []
        for threshold, what in ((0.75, "mostly large"), (0.9, "large only")):
            rich = np.flatnonzero(past & (share >= threshold) & (height > 1))
            if not len(rich):
                parts.append(f"{what} (share >= {threshold:g}): none")
                continue
            k_rich = rich[np.argmax(height[rich])]
            parts.append(f"{what} (share >= {threshold:g}) from x = {edges[rich[0]]:.0f}, up to {height[k_rich]:.2f} "
                         f"({height[k_rich] / inflow:.3f} x the inflow) at x = {centres[k_rich]:.1f}")
        print(f"plotChuteFront: t = {time:g}: " + "; ".join(parts))

    if args.out == "-":
        return
    figure, axes = plt.subplots(3, 1, figsize=(12, 7), sharex=True, gridspec_kw={"height_ratios": [2, 1, 1]})
    colours = np.where(large, "tab:red", "tab:blue")
    colours = np.where(mobile, colours, "0.6")
    circles = [Circle((xi, zi), ri) for xi, zi, ri in zip(x, z, r)]
    axes[0].add_collection(PatchCollection(circles, facecolors=colours, edgecolors="none", alpha=0.5))
    axes[0].axvline(args.box, color="k", lw=0.8, ls="--")
    axes[0].axvline(front, color="tab:green", lw=0.8, ls=":")
    axes[0].set_xlim(0, x[mobile].max() + 5)
    axes[0].set_ylim(-1, max(np.nanmax(height) + 4, 8))
    axes[0].set_ylabel("z")
    axes[0].set_title(f"t = {time:g}: large (red) and small (blue) spheres, base (grey); maser box left of the "
                      "dashed line, front at the dotted one")
    axes[1].plot(centres, height, "k.-")
    axes[1].axhline(inflow, color="tab:green", lw=0.8, label=f"inflow height {inflow:.2f}")
    axes[1].set_ylabel("flow height")
    axes[1].legend(loc="upper right")
    axes[2].plot(centres, share, "r.-")
    axes[2].set_ylim(0, 1)
    axes[2].set_ylabel("large share (volume)")
    axes[2].set_xlabel("x (downslope)")
    figure.tight_layout()
    figure.savefig(args.out, dpi=110)


if __name__ == "__main__":
    main()
