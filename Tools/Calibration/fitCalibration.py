#!/usr/bin/python3
"""Fits the closure relations of the depth-averaged model to a periodic-chute calibration study
(Documentation/Calibration.md "The fit"): the h_stop curve (delta1, delta2, A) from the
arrested/flowing boundary, the flow rule (beta, gamma), the friction law's residuals, bootstrap
intervals, plots, and the parameters next to the thesis's Table 3.1.

    Tools/Calibration/fitCalibration.py DIR/results.csv --plots DIR/fit
    Tools/Calibration/fitCalibration.py DIR/results.csv --species large --hold delta2=30.06,A=3.07
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import calibrationFit as cf  # noqa: E402

SMALL_DIAMETER = 2 ** (-1 / 3)
# The thesis's Table 3.1 (Denissen 2019, chapter 3), per constituent.
TABLE_3_1 = {"small": {"delta1": 17.92, "delta2": 36.53, "A": 0.71, "beta": 0.148},
             "large": {"delta1": 18.60, "delta2": 30.06, "A": 3.07, "beta": 0.146}}


def save(fig, ax, xlabel, ylabel, path):
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    return path


def plot(points, fit, d, prefix, table=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    d1, d2, a_d, beta, gamma = fit["delta1"], fit["delta2"], fit["A"] * d, fit["beta"], fit["gamma"]
    paths = []
    points = cf.set_aside_thin_flows(points)

    fig, ax = plt.subplots(figsize=(5, 4))
    for state, marker, colour in (("arrested", "x", "tab:blue"), ("flowing", "o", "tab:red"), ("unsteady", "^", "orange"),
                                  ("undecided", "s", "grey"), ("thin-flowing", "v", "grey")):
        chosen = [p for p in points if p["state"] == state]
        if chosen:
            ax.scatter([p["angle"] for p in chosen], [p["h"] for p in chosen], marker=marker, color=colour, label=state,
                       facecolors="none" if marker != "x" else None)
    est = fit["hstop"]["estimates"]
    ax.errorbar([e[0] for e in est], [e[1] for e in est], yerr=[e[2] for e in est], fmt="k_", capsize=3,
                label="h_stop per angle")
    theta = np.linspace(d1 + 0.05 * (d2 - d1), d2, 200)
    ax.plot(theta, cf.hstop_model(theta, d1, d2, a_d), "k-", label="fit")
    if table:
        t1, t2, t_ad = table["delta1"], table["delta2"], table["A"] * d
        theta = np.linspace(t1 + 0.05 * (t2 - t1), t2, 200)
        ax.plot(theta, cf.hstop_model(theta, t1, t2, t_ad), "k--", lw=0.8, label="Table 3.1")
    ax.set_ylim(0, 1.2 * max(p["h"] for p in points))
    paths.append(save(fig, ax, "angle (degrees)", "h (large diameters)", prefix + "-hstop.png"))

    # The collapse, and below it the residuals F - (beta h/h_stop - gamma) of the fit.
    fig, (ax, below) = plt.subplots(2, 1, figsize=(5, 5.5), sharex=True, gridspec_kw={"height_ratios": [3, 1.3]})
    rule = fit["rule"]
    angles = [p["angle"] for p in rule["used"]]
    scatter = ax.scatter(rule["x"], rule["F"], c=angles, cmap="viridis")
    fig.colorbar(scatter, ax=[ax, below], label="angle (degrees)")
    x = np.linspace(0, 1.1 * max(rule["x"]), 50)
    ax.plot(x, beta * x - gamma, "k-", label=f"F = {beta:.3f} h/h_stop {-gamma:+.3f}")
    ax.set_ylabel("F")
    ax.legend(fontsize=8)
    below.scatter(rule["x"], rule["residuals"], c=angles, cmap="viridis", s=14)
    below.axhline(0, color="k", lw=0.8)
    below.set_xlabel("h / h_stop(theta)")
    below.set_ylabel("residual of F")
    paths.append(prefix + "-flowrule.png")
    fig.savefig(paths[-1], dpi=120)

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4))
    used = rule["used"]
    h = np.array([p["h"] for p in used])
    froude = np.array([p["F"] for p in used])
    left.scatter(froude, fit["muMeasured"], c="tab:red", label="measured (base force)")
    right.scatter(h, fit["muMeasured"], c="tab:red", label="measured (base force)")
    f_axis = np.linspace(0, 1.1 * froude.max(), 100)
    for depth in sorted({round(v) for v in h}):
        left.plot(f_axis, cf.friction_law(depth, f_axis, d1, d2, a_d, beta, gamma), lw=0.8, label=f"law, h = {depth}")
    h_axis = np.linspace(0.5, 1.1 * h.max(), 100)
    for value in sorted({round(v, 1) for v in froude})[:: max(1, len(froude) // 4)]:
        right.plot(h_axis, cf.friction_law(h_axis, value, d1, d2, a_d, beta, gamma), lw=0.8, label=f"law, F = {value}")
    for a in (left, right):
        a.set_ylabel("mu")
        a.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    left.set_xlabel("F")
    right.set_xlabel("h")
    fig.tight_layout()
    paths.append(prefix + "-friction.png")
    fig.savefig(paths[-1], dpi=120)
    return paths


def parse_held(text):
    """--hold NAME=VALUE,...: a dict of parameters to keep fixed; a name not among the parameters,
    or a value that is not a number, stops with a message naming it."""
    held = {}
    for item in filter(None, (t.strip() for t in text.split(","))):
        name, _, value = item.partition("=")
        if name not in cf.PARAMETERS:
            raise cf.FitError(f"--hold {item}: no parameter {name!r} (one of {', '.join(cf.PARAMETERS)})")
        try:
            held[name] = float(value)
        except ValueError:
            raise cf.FitError(f"--hold {item}: the value of {name} is not a number") from None
    return held


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="a study's results.csv")
    parser.add_argument("--species", help="the points of one species (large, small, mixture)")
    parser.add_argument("--diameter", type=float, help="d of the flowing spheres (default: by species)")
    parser.add_argument("--no-gamma", action="store_true", help="flow rule F = beta h/h_stop (the thesis's eq. 3.11)")
    parser.add_argument("--max-change", type=float, default=0.2,
                        help="flowing points whose velocity changed by more than this share over the averaging "
                             "are left out as unsteady (default 0.2)")
    parser.add_argument("--height-offset", type=float, default=0.0,
                        help="taken off every h before the fit (0.74: h as the thickness of a uniform layer of "
                             "the bulk's solid fraction; Documentation/Calibration.md, accounts (c)); default 0")
    parser.add_argument("--bootstrap", type=int, default=200, help="resamples for the intervals (default 200)")
    parser.add_argument("--plots", help="prefix of the plots PREFIX-hstop.png, -flowrule.png, -friction.png")
    parser.add_argument("--hold", default="",
                        help="NAME=VALUE,...: parameters (delta1, delta2, A in units of d, beta, gamma) kept at these "
                             "values while the others are fitted; the misfit is compared with the free fit's")
    args = parser.parse_args()
    try:
        held = parse_held(args.hold)
        points = cf.read_points(args.results, args.species, args.max_change, args.height_offset)
        species = points[0]["species"]
        d = args.diameter or (SMALL_DIAMETER if species == "small" else 1.0)
        fit = cf.fit_all(points, d, not args.no_gamma, held)
        free = cf.fit_all(points, d, not args.no_gamma) if held else fit
    except (cf.FitError, OSError) as error:
        sys.exit(f"fitCalibration: {error}")
    # (A study with few points near the curve still has a fit; it says why it has no intervals.)
    try:
        intervals, failed = cf.bootstrap(points, d, not args.no_gamma, args.bootstrap, held=held)
    except cf.FitError as error:
        print(f"fitCalibration: no intervals: {error}")
        intervals, failed = {k: (math.nan, math.nan) for k in cf.PARAMETERS}, args.bootstrap
    kinds = ("flowing", "arrested", "unsteady", "undecided", "thin-flowing")
    counts = {s: sum(p["state"] == s for p in cf.set_aside_thin_flows(points)) for s in kinds}
    print(f"{len(points)} points of {species} (d = {d:.4g}): {counts['flowing']} flowing, {counts['arrested']} arrested, "
          f"{counts['unsteady']} unsteady (left out of the flow rule; those speeding up bracket h_stop), "
          f"{counts['undecided']} undecided (left out), {counts['thin-flowing']} flowing below an arrested layer at "
          "their angle (left out)")
    print("h_stop per angle: " + ", ".join(f"{a:g}: {h:.2f} +- {e:.2f}" for a, h, e in fit["hstop"]["estimates"]))
    seed = TABLE_3_1.get(species, {})
    print(f"{'parameter':<10}{'fit':>10}{'95% interval':>22}{'Table 3.1':>12}")
    for k in cf.PARAMETERS:
        low, high = intervals[k]
        table = f"{seed[k]:.4g}" if k in seed else "-"
        interval = "   (held)" + " " * 13 if k in held else f"   [{low:8.4g}, {high:8.4g}]"
        print(f"{k:<10}{fit[k]:>10.4g}{interval}{table:>12}")
    if held:
        # (Weighted residuals: log h_stop by its bracket, F by the flow rule's rms residual.)
        dof = free["residualCount"] - len(free["free"])
        print(f"misfit (sum of squared weighted residuals, {fit['residualCount']} residuals): {fit['misfit']:.4g} with "
              + ", ".join(f"{k} = {v:g}" for k, v in held.items()) + f" held, {free['misfit']:.4g} with all free "
              f"(per degree of freedom of the free fit: {free['misfit'] / max(dof, 1):.3g}); free fit: "
              + ", ".join(f"{k} = {free[k]:.4g}" for k in cf.PARAMETERS))
    print(f"(bootstrap: {args.bootstrap - failed} of {args.bootstrap} resamples fitted)")
    rule = fit["rule"]
    rms = math.sqrt(sum(r * r for r in rule["residuals"]) / len(rule["residuals"]))
    print(f"flow rule: {len(rule['F'])} points, rms residual of F {rms:.4f}")
    mu_rms = math.sqrt(sum(r * r for r in fit["muResidualTan"]) / len(fit["muResidualTan"]))
    base = fit["muMeasured"] - [math.tan(math.radians(p["angle"])) for p in rule["used"]]
    print(f"friction law: rms of mu(h, F) - tan(theta) {mu_rms:.4f}; measured basal friction - tan(theta): "
          f"mean {base.mean():+.4f}, largest {abs(base).max():.4f}")
    if args.plots:
        print("plots: " + ", ".join(plot(points, fit, d, args.plots, seed if "delta1" in seed else None)))


if __name__ == "__main__":
    main()
