#!/usr/bin/python3
"""The drum's segregation pattern at several aspect ratios, one column each: above, the
cross-section (x, z) of a run's last frame seen along the axis (spheres orange, ellipsoids blue,
the wall grey); below, the volume fraction of spheres among the flowing particles, averaged over
the frames of the sweep's windows, from talus-cg's time-averaged fields in (x, z)
(Documentation/Drums/RotatingDrum.md, "The sweep"):

    talus-cg NAME --coordinates XZ --time-average --time-min T --fixed exclude -w 1 \\
        -n 60 60 -x -15 15 -z -15 15 --stress off --mixing 0 -o NAME.cg.csv
    /usr/bin/python3 Tools/Drum/plotDrumMaps.py --run NAME NAME.cg.csv R ... -o maps.png

Each --run gives the run's name (its NAME.data), its fields file and its aspect ratio R (the
ellipsoids' semi-axes are those of the sphere of diameter 1 of equal volume: R^(2/3)/2 and
R^(-1/3)/2). Where the flowing particles fill less than --least (0.1) of the volume the map is
blank.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LinearSegmentedColormap  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Plot"))
from cgFiles import read_cg_fields  # noqa: E402
from dataFrames import read_frame  # noqa: E402
from plotDrum import draw_cross_section  # noqa: E402


def equal_volume_axes(aspect):
    if not aspect >= 1:
        sys.exit(f"plotDrumMaps.py: the aspect ratio must be at least 1, got {aspect}")
    return np.array([aspect ** (2 / 3) / 2, aspect ** (-1 / 3) / 2, aspect ** (-1 / 3) / 2])


def sphere_fraction_map(path, least):
    columns = read_cg_fields(path, "plotDrumMaps.py")
    for name in ("x", "z", "VolumeFraction", "Concentration_s0"):
        if name not in columns:
            sys.exit(f"plotDrumMaps.py: {path}: no column {name} (talus-cg --coordinates XZ, with species)")
    x, z = np.unique(columns["x"]), np.unique(columns["z"])
    if len(x) * len(z) != len(columns["x"]):
        sys.exit(f"plotDrumMaps.py: {path}: not one frame on an x-z grid (use --time-average)")
    shape = (len(x), len(z))
    order = np.lexsort((columns["z"], columns["x"]))  # x slowest, as the grid
    fraction = columns["Concentration_s0"][order].reshape(shape)
    filled = columns["VolumeFraction"][order].reshape(shape)
    return x, z, np.ma.masked_where(filled < least, fraction)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--run", nargs=3, action="append", required=True, metavar=("NAME", "FIELDS", "R"),
                        help="a run's name, its talus-cg fields file and its aspect ratio")
    parser.add_argument("--least", type=float, default=0.1, help="volume fraction below which the map is blank")
    parser.add_argument("-o", "--output", default="drumMaps.png")
    args = parser.parse_args()

    count = len(args.run)
    fig, axes = plt.subplots(2, count, figsize=(5 * count, 9.6), squeeze=False)
    image = None
    # Ellipsoid-rich blue, sphere-rich orange, as the particles above; even mixtures white.
    kinds = LinearSegmentedColormap.from_list("kinds", ["tab:blue", "white", "tab:orange"])
    for column, (name, fields, aspect_text) in enumerate(args.run):
        try:
            aspect = float(aspect_text)
        except ValueError:
            sys.exit(f"plotDrumMaps.py: --run {name}: the aspect ratio {aspect_text!r} is not a number")
        t, rows, _ = read_frame(name + ".data", None, "plotDrumMaps.py")
        top, bottom = axes[0, column], axes[1, column]
        draw_cross_section(top, rows, equal_volume_axes(aspect), t)
        top.set_title(f"R = {aspect:g}, t = {t:g}", fontsize=10)
        x, z, fraction = sphere_fraction_map(fields, args.least)
        image = bottom.pcolormesh(x, z, fraction.T, cmap=kinds, vmin=0.2, vmax=0.8, shading="nearest")
        bottom.set_xlim(top.get_xlim())
        bottom.set_ylim(top.get_ylim())
        bottom.set_aspect("equal")
        bottom.set_xlabel("x")
        bottom.set_ylabel("z")
        bottom.set_title(f"R = {aspect:g}: sphere fraction", fontsize=10)
        richest = np.unravel_index(np.ma.argmax(fraction), fraction.shape)
        print(f"R = {aspect:g}: frame t = {t:g} of {len(rows)} particles; sphere fraction "
              f"{fraction.min():.4f} to {fraction.max():.4f} over {fraction.count()} filled cells, "
              f"the largest at x = {x[richest[0]]:.6g}, z = {z[richest[1]]:.6g}")
    fig.colorbar(image, ax=axes[1, :].tolist(), shrink=0.8, label="volume fraction of spheres")
    fig.suptitle("above: the last frame seen along the axis (spheres orange, ellipsoids blue, the wall grey); "
                 "below: the sphere fraction averaged over the windows' frames", fontsize=10)
    fig.savefig(args.output, dpi=90)
    print(f"wrote {args.output} ({count} runs)")


if __name__ == "__main__":
    main()
