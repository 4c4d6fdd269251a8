#!/usr/bin/python3
"""The long chute of particles against the depth-averaged model (Documentation/ShallowFlow.md,
"Against the particles"), from saved files alone: no particle is simulated again.

    compareLongChute.py RUN --talus-cg BIN --talus-shallow BIN --times 100,200,300 -o PREFIX

RUN names a MaserFedChute run (RUN.data with its frames, RUN.restart, RUN.series). The particle
run works in units of the mean diameter; the comparison in the thesis's units, the large
diameter dL (--large-diameter, in the run's units) and sqrt(dL/g): x' = (x - maser length)/dL
(the maser box ends at x' = 0), h' = h/dL, t' = (t - activation)/sqrt(dL), u' = u/sqrt(dL).

1. The inflow: talus-cg depth averages (coordinates XZ, base excluded) of the maser box over
   the frames after the maser's activation give h_in, u_in and phi_in (the small spheres' share of
   the solids), averaged over the box's interior and the frames; and the basal slip a_s, from the
   shape factor alpha = m_A int rho u^2 dz / (int rho u dz)^2 of the time-averaged velocity
   profile in the box's interior columns, through the model's own relation alpha = 1 + (1 -
   a_s)^2 / 3 (its linear profile, Documentation/ShallowFlow.md; --basal-slip gives a_s instead).
2. The model: talus-shallow with that inflow, the friction law's parameters as given after "--"
   (default: its own, table 3.1), at the frames' times t'. It starts as the particles do: at the
   activation MaserFedChute seeds the first maser length of the chute with a copy of the maser's
   flow, so the model starts with the inflow state over that length (--seeded-length) and an
   empty chute beyond.
3. The particles: the depth averages along the chute at the frames nearest to --times (kernel
   widths --widths: wide along x, narrow in z, as anisotropic coarse graining of shallow flows
   takes them), h and phi against x'.
4. Per time, for both: the front (the last x' where h reaches 0.5, or --front-height, in the
   flow connected to the inflow: grains bouncing ahead of it, beyond a stretch of 25 dL below
   that level, are not its front), the shock (the last x' where phi reaches 0.25 among those
   where h is at least 1), the head's height (the largest h) and length (front - shock: the part
   of the flow that holds large particles only). PREFIX.csv holds them, PREFIX-profiles.png
   overlays the profiles, PREFIX-fronts.png the positions against time.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

FRONT_HEIGHT, SHOCK_CONCENTRATION = 0.5, 0.25  # talus-shallow's defaults (--front-height, --shock-concentration)
FRONT_GAP = 25.0  # dL: a stretch below FRONT_HEIGHT this long ends the flow (connected_front)


def fail(message):
    sys.exit(f"compareLongChute: {message}")


def activation_time(run):
    """The maser's activation (run.activatedAt in the restart file; -1: not activated)."""
    with open(run + ".restart") as f:
        for line in f:
            words = line.split()
            if len(words) == 2 and words[0] == "run.activatedAt":
                t = float(words[1])
                if t < 0:
                    fail(f"{run}.restart: the maser has not been activated yet (run.activatedAt {words[1]})")
                return t
    fail(f"{run}.restart: no run.activatedAt line (not a MaserFedChute restart file?)")


def frame_times(run):
    """The times of the frames in RUN.data (MercuryDPM format: a header line 'N t xmin ...' each)."""
    times = []
    with open(run + ".data") as f:
        while True:
            header = f.readline()
            if not header:
                return times
            words = header.split()
            try:
                count, time = int(words[0]), float(words[1])
            except (IndexError, ValueError):
                fail(f"{run}.data: frame header expected after {len(times)} frames, got {header[:60]!r}")
            times.append(time)
            for _ in range(count):
                if not f.readline():
                    fail(f"{run}.data: the frame at t = {time} is incomplete")


def coarse_grained(args, x_range, points, t_first, t_last, how, out):
    """talus-cg's XZ fields of the run's frames t_first..t_last (base excluded, Lucy widths
    --widths, --z-points over --z-range) with the options `how` (--depth-average, --time-average),
    read from `out`: a dict of columns."""
    command = [args.talus_cg, args.run, "--coordinates", "XZ", "--widths", str(args.widths[0]), "1", str(args.widths[1]),
               "-x", str(x_range[0]), str(x_range[1]), "-z", str(args.z_range[0]), str(args.z_range[1]),
               "-n", str(points), str(args.z_points)] + how + [
               "--fixed", "exclude", "--fixed-species", args.base_species, "--periodic", "y",
               "--stress", "off", "--time-min", repr(t_first - 1e-6), "--time-max", repr(t_last + 1e-6), "-o", out]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail("talus-cg failed: " + " ".join(command) + "\n" + done.stderr)
    return read_csv(out)


def depth_averages(args, t, x_range, points, folder, t_last=None):
    """talus-cg's depth averages of the frame at t (or of every frame from t to t_last, rows one
    block per frame): x, the height, the velocity along x, phi."""
    rows = coarse_grained(args, x_range, points, t, t if t_last is None else t_last, ["--depth-average"],
                          os.path.join(folder, f"depth-{t:.6f}.csv"))
    phi = sum(rows[f"DepthAveragedConcentration_s{s}"] for s in args.small_species
              if f"DepthAveragedConcentration_s{s}" in rows)
    return rows["x"], rows["Height"], rows["DepthAveragedVelocityX"], phi


def slip_of_shape_factor(alpha):
    """The basal slip a_s of the model's linear profile with shape factor alpha = 1 + (1 - a_s)^2 / 3
    (1 for alpha <= 1)."""
    return 1.0 - math.sqrt(3.0 * max(alpha - 1.0, 0.0))


def slip_from_profile(dz, rho, p):
    """The shape factor alpha = m_A int rho u^2 dz / (int rho u dz)^2 of one column (rho and the
    momentum p = rho u at points dz apart; u^2 rho = p^2 / rho) and its basal slip a_s
    (slip_of_shape_factor)."""
    mass = np.sum(rho) * dz
    flux = np.sum(p) * dz
    energy = np.sum(np.where(rho > 0, p * p / np.where(rho > 0, rho, 1.0), 0.0)) * dz
    alpha = mass * energy / (flux * flux)
    return alpha, slip_of_shape_factor(alpha)


def measured_slip(args, t_first, t_last, folder):
    """alpha and a_s of the maser box's interior (columns farther than a width from its ends),
    from talus-cg's XZ fields time-averaged over the frames t_first..t_last (base excluded)."""
    rows = coarse_grained(args, (0, args.maser_length), max(4, int(args.maser_length)), t_first, t_last,
                          ["--time-average"], os.path.join(folder, "maser-profile.csv"))
    dz = (args.z_range[1] - args.z_range[0]) / args.z_points
    alphas = []
    for x in np.unique(rows["x"]):
        if args.widths[0] < x < args.maser_length - args.widths[0]:
            column = rows["x"] == x
            alphas.append(slip_from_profile(dz, rows["Density"][column], rows["MomentumX"][column])[0])
    alpha = float(np.mean(alphas))
    return alpha, slip_of_shape_factor(alpha)


def read_csv(path):
    """A CSV file with '#' comment lines before its names line: a dict of columns."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    names = lines[0].strip().split(",")
    values = np.array([[float(v) for v in line.split(",")] for line in lines[1:] if line.strip()])
    return {n: values[:, k] for k, n in enumerate(names)}


def crossing_after(x, value, k, level):
    """Where value, at least level at point k, falls to level on the way to point k + 1 (linear
    between them; x[k] at the last point)."""
    if k + 1 >= len(x):
        return x[k]
    return x[k] + (value[k] - level) / (value[k] - value[k + 1]) * (x[k + 1] - x[k])


def last_crossing(x, value, level):
    """The last x where value reaches level, linear between points (nan if nowhere)."""
    above = np.nonzero(value >= level)[0]
    return math.nan if len(above) == 0 else crossing_after(x, value, above[-1], level)


def connected_front(x, h, level, gap):
    """The front of the flow that is connected to the inflow: scanning downstream, the last x
    where h reaches level before the first stretch longer than gap where it stays below (linear
    between points; nan if h never reaches level). Single grains that bounce ahead of the flow
    raise a coarse-grained h above the level here and there, far downstream of the flow's end:
    they are not its front. A smooth profile (the model's) has no such stretch, and this is its
    last crossing."""
    above = np.nonzero(h >= level)[0]
    if len(above) == 0:
        return math.nan
    k = above[0]
    for following in above[1:]:
        if x[following] - x[k] > gap:
            break
        k = following
    return crossing_after(x, h, k, level)


def measures(x, h, phi, front_gap=FRONT_GAP, front_height=FRONT_HEIGHT):
    """Front, shock, head height and length. The front is that of the flow connected to the
    inflow (connected_front). The shock is sought where h is at least one large diameter: near
    the particles' front a few grains make phi anything from 0 to 1."""
    front = connected_front(x, h, front_height, front_gap)
    shock = last_crossing(x, np.where(h >= 1.0, phi, 0.0), SHOCK_CONCENTRATION)
    return {"front": front, "shock": shock, "head_height": float(np.max(h)), "head_length": front - shock}


def write_start(path, length, cells, seeded, inflow):
    """talus-shallow's --initial file: the inflow state (h, u, phi) in the cells whose centres lie
    within the seeded length, an empty chute beyond."""
    with open(path, "w") as f:
        f.write("x,h,u,phi\n")
        for i in range(cells):
            x = (i + 0.5) * length / cells
            h, u, phi = inflow if x < seeded else (0.0, 0.0, 0.0)
            f.write(f"{x!r},{h!r},{u!r},{phi!r}\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="the particle run's name (RUN.data, RUN.restart)")
    parser.add_argument("--talus-cg", required=True)
    parser.add_argument("--talus-shallow", required=True)
    parser.add_argument("--times", required=True, help="times after the activation, thesis units (frames nearest)")
    parser.add_argument("--large-diameter", type=float, default=2 * 2 ** (1 / 3) / (1 + 2 ** (1 / 3)),
                        help="dL in the run's units (default 1.1150: size ratio 2^(1/3) at mean diameter 1)")
    parser.add_argument("--maser-length", type=float, required=True, help="the maser box's length, run units")
    parser.add_argument("--chute-length", type=float, required=True, help="the open chute's length, run units")
    parser.add_argument("--front-height", type=float, default=FRONT_HEIGHT,
                        help=f"the level (in dL) that marks the front (default {FRONT_HEIGHT}: the thinnest flow; "
                             "1-4 dL leave out the dilute grains rolling ahead of the dense flow)")
    parser.add_argument("--basal-slip", type=float, default=None,
                        help="a_s for the model (default: from the maser's velocity profile)")
    parser.add_argument("--seeded-length", type=float, default=None,
                        help="the chute's length seeded at the activation, run units (default: the maser length; 0: none)")
    parser.add_argument("--small-species", default="1,4", help="species of the small spheres (default 1,4: chute, maser)")
    parser.add_argument("--base-species", default="2,5", help="species of the fixed base (default 2,5: chute, maser)")
    parser.add_argument("--widths", type=float, nargs=2, default=[5.0, 0.5], metavar=("WX", "WZ"),
                        help="Lucy widths along x and z, run units (default 5 0.5)")
    parser.add_argument("--z-range", type=float, nargs=2, default=[-1.0, 45.0])
    parser.add_argument("--z-points", type=int, default=184)
    parser.add_argument("-o", "--output", default="longChute", help="output prefix (PREFIX.csv, PREFIX-*.png)")
    parser.add_argument("shallow", nargs="*", help="after --: flags for talus-shallow (e.g. the friction laws)")
    args = parser.parse_args()
    args.small_species = [int(s) for s in args.small_species.split(",")]
    dl, tu = args.large_diameter, math.sqrt(args.large_diameter)
    wanted = [float(t) for t in args.times.split(",")]
    activated = activation_time(args.run)
    frames = frame_times(args.run)
    after = [t for t in frames if t > activated + 1e-9]
    if not after:
        fail(f"{args.run}.data: no frame after the activation at t = {activated}")
    chosen = sorted({min(after, key=lambda t: abs((t - activated) / tu - w)) for w in wanted})
    print(f"activation at t = {activated:g} (run units); frames at t' = " +
          ", ".join(f"{(t - activated) / tu:.2f}" for t in chosen))

    with tempfile.TemporaryDirectory() as folder:
        # 1. The inflow, from the maser box's interior over every frame after the activation.
        w = args.widths[0]
        x, h, u, phi = depth_averages(args, after[0], (0, args.maser_length), max(4, int(args.maser_length)), folder,
                                      after[-1])
        inside = (x > w) & (x < args.maser_length - w)
        h_in, u_in, phi_in = h[inside].mean(), u[inside].mean(), phi[inside].mean()
        print(f"inflow from the maser ({len(after)} frames): h = {h_in / dl:.4g} dL, u = {u_in / tu:.4g}, phi = {phi_in:.4g}")
        if args.basal_slip is None:
            alpha, slip = measured_slip(args, after[0], after[-1], folder)
            print(f"velocity profile in the maser: alpha = {alpha:.4g}, so a_s = {slip:.4g}")
        else:
            slip = args.basal_slip

        # 2. The model at the frames' times, from the chute as the activation left it.
        times = [(t - activated) / tu for t in chosen]
        prefix = os.path.join(folder, "model")
        length, cells = args.chute_length / dl, int(round(args.chute_length / dl))
        seeded = (args.maser_length if args.seeded_length is None else args.seeded_length) / dl
        start = os.path.join(folder, "start.csv")
        write_start(start, length, cells, seeded, (h_in / dl, u_in / tu, phi_in))
        command = [args.talus_shallow, "--length", repr(length), "--initial", start,
                   "--cells", str(cells), "--end-time", repr(max(times)),
                   "--output-times", ",".join(repr(t) for t in times), "--inflow-height", repr(h_in / dl),
                   "--inflow-velocity", repr(u_in / tu), "--inflow-concentration", repr(phi_in), "--basal-slip", repr(slip),
                   "--output", prefix] + args.shallow
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            fail("talus-shallow failed: " + " ".join(command) + "\n" + done.stderr)
        model = read_csv(prefix + ".profiles.csv")

        # 3-4. The particles along the chute, and the measures of both.
        results, profiles = [], []
        for t, t_thesis in zip(chosen, times):
            x, h, u, phi = depth_averages(args, t, (0, args.maser_length + args.chute_length),
                                          int(round(args.maser_length + args.chute_length)), folder)
            xs, hs, phis = (x - args.maser_length) / dl, h / dl, phi
            nearest = model["t"][np.argmin(np.abs(model["t"] - t_thesis))]  # (the time as the model printed it)
            m = {k: v[model["t"] == nearest] for k, v in model.items()}
            dpm = measures(xs, hs, phis, front_height=args.front_height)
            cont = measures(m["x"], m["h"], m["phi"], front_height=args.front_height)
            results.append({"t": t_thesis, **{f"{k}_particles": v for k, v in dpm.items()},
                            **{f"{k}_model": v for k, v in cont.items()}})
            profiles.append((t_thesis, xs, hs, hs * phis, m["x"], m["h"], m["hphi"]))

    with open(args.output + ".csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        writer.writeheader()
        for r in results:
            writer.writerow({k: f"{v:.6g}" for k, v in r.items()})
    print(f"{'t':>7} {'front':>17} {'shock':>17} {'head height':>17} {'head length':>17}   (particles / model)")
    for r in results:
        print(f"{r['t']:7.1f} " + " ".join(f"{r[k + '_particles']:8.1f}/{r[k + '_model']:<8.1f}"
                                           for k in ("front", "shock", "head_height", "head_length")))
    plot(args.output, profiles, results, h_in / dl)


def plot(prefix, profiles, results, h_in):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(len(profiles), 1, figsize=(10, 2.4 * len(profiles)), squeeze=False)
    top = 1.15 * max(max(p[2].max(), p[5].max()) for p in profiles)
    right = max(max(p[1][p[2] > 0.05].max(initial=0), p[4][p[5] > 0.05].max(initial=0)) for p in profiles) * 1.05 + 20
    for axis, (t, xs, hs, hphis, xm, hm, hphim) in zip(axes[:, 0], profiles):
        axis.fill_between(xs, 0, hphis, color="tab:green", alpha=0.35, label="particles: h phi (small)")
        axis.plot(xs, hs, color="tab:red", label="particles: h")
        axis.plot(xm, hm, "k", label="model: h")
        axis.plot(xm, hphim, "k--", label="model: h phi")
        axis.axhline(h_in, color="0.6", lw=0.8)
        axis.set_xlim(-20, right)
        axis.set_ylim(0, top)
        axis.set_ylabel("h / dL")
        axis.set_title(f"t = {t:.1f}", loc="left", fontsize=9)
    axes[0, 0].legend(loc="upper right", fontsize=7, ncol=2)
    axes[-1, 0].set_xlabel("x / dL")
    figure.tight_layout()
    figure.savefig(prefix + "-profiles.png", dpi=120)
    figure, axis = plt.subplots(figsize=(6, 4))
    t = [r["t"] for r in results]
    for key, colour in (("front", "tab:red"), ("shock", "tab:green")):
        axis.plot(t, [r[key + "_particles"] for r in results], "o", color=colour, label=f"{key}: particles")
        axis.plot(t, [r[key + "_model"] for r in results], "-", color=colour, label=f"{key}: model")
    axis.set_xlabel("t")
    axis.set_ylabel("x / dL")
    axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(prefix + "-fronts.png", dpi=120)
    print(f"wrote {prefix}.csv, {prefix}-profiles.png, {prefix}-fronts.png")


if __name__ == "__main__":
    main()
