#!/usr/bin/python3
"""The calibration fit (calibrationFit.py) on synthetic studies with known parameters.

A study is made from the closure relations themselves: at each angle, depths drawn at random;
a point is arrested when its depth lies below h_stop(theta) of the known delta1, delta2, A
(Documentation/Calibration.md eq. (1)), and otherwise flows with the Froude number of the known
flow rule F = beta h/h_stop - gamma (eq. (2)) plus Gaussian noise of 0.01, and a basal friction
tan(theta) plus noise of 0.003 (the momentum balance of a steady flow). The fit must recover each
known parameter inside its 95% bootstrap interval, and refuse studies with too few points of a
kind with a message that says which. Prints "calibration fit: all checks passed" at the end.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Studies"))
import calibrationFit as cf  # noqa: E402
from checks import check, finish  # noqa: E402 (Tools/Studies, beside this folder)


def synthetic_study(truth, d, angles, per_angle, seed):
    rng = np.random.default_rng(seed)
    points = []
    for angle in angles:
        hstop = cf.hstop_model(angle, truth["delta1"], truth["delta2"], truth["A"] * d)
        # Depths evenly spaced in log h from 0.3 to 40, each moved at random within its spacing
        # (a study's grid, without a bias of where h_stop falls between two of its depths).
        spacing = math.log(40 / 0.3) / (per_angle - 1)
        grid = 0.3 * np.exp(spacing * (np.arange(per_angle) + rng.uniform(-0.5, 0.5, per_angle)))
        for h in grid:
            if h < hstop:
                points.append({"angle": angle, "h": h, "F": 0.0, "mu": math.nan, "state": "arrested"})
            else:
                froude = truth["beta"] * h / hstop - truth["gamma"] + rng.normal(0, 0.01)
                mu = math.tan(math.radians(angle)) + rng.normal(0, 0.003)
                points.append({"angle": angle, "h": h, "F": froude, "mu": mu, "state": "flowing"})
    return points


# How close the fit itself must come: the h_stop estimate of an angle is uncertain by about half
# the distance between neighbouring depths (9% of h_stop with 28 depths from 0.3 to 40), which
# moves delta1 and delta2 by a few tenths of a degree and A by some 10%; F carries noise 0.01
# into beta and gamma.
CLOSE = {"delta1": 0.6, "delta2": 1.5, "A": 0.2, "beta": 0.01, "gamma": 0.06}  # A relative, others absolute


def recovers(label, truth, d, with_gamma):
    angles = np.linspace(truth["delta1"] + 1.5, truth["delta2"] - 1.5, 9)
    points = synthetic_study(truth, d, angles=angles, per_angle=28, seed=7)
    fit = cf.fit_all(points, d, with_gamma)
    intervals, failed = cf.bootstrap(points, d, with_gamma, replicates=150, seed=3)
    for k in cf.PARAMETERS:
        low, high = intervals[k]
        check(low <= truth[k] <= high, f"{label}: {k} = {truth[k]} inside the 95% interval [{low:.4g}, {high:.4g}] "
                                       f"(fit {fit[k]:.4g})")
        error = abs(fit[k] - truth[k]) / (truth[k] if k == "A" else 1)
        check(error <= CLOSE[k], f"{label}: {k} fitted within {CLOSE[k]}{' (relative)' if k == 'A' else ''} of the truth")
    check(failed < 15, f"{label}: {failed} of 150 resamples could not be fitted (fewer than 15)")
    # The friction law at the flowing points: mu(h, F) of the fitted parameters is tan(theta)
    # up to the noise that F carries through it.
    rms = math.sqrt(np.mean(fit["muResidualTan"] ** 2))
    check(rms < 0.01, f"{label}: rms of mu(h, F) - tan(theta) at the flowing points {rms:.4f} below 0.01")


def refuses(label, points, words):
    try:
        cf.fit_all(points)
        check(False, f"{label}: refused")
    except cf.FitError as error:
        text = str(error)
        check(all(w in text for w in words), f"{label}: refused saying {text!r}")


# The large spheres of Table 3.1, with a gamma as in Weinhart et al. 2012 (0.045 there).
large = {"delta1": 18.60, "delta2": 30.06, "A": 3.07, "beta": 0.146, "gamma": 0.05}
recovers("large spheres of Table 3.1", large, 1.0, with_gamma=True)
# The small spheres of Table 3.1 (A in units of their own diameter), with gamma = 0 and the
# thesis's form of the flow rule.
small = {"delta1": 17.92, "delta2": 36.53, "A": 0.71, "beta": 0.148, "gamma": 0.0}
recovers("small spheres of Table 3.1, gamma = 0", small, 2 ** (-1 / 3), with_gamma=False)

study = synthetic_study(large, 1.0, [20, 22, 24, 26], 10, seed=1)
refuses("no arrested point", [p for p in study if p["state"] != "arrested"], ["0 angles", "arrested"])
refuses("arrested and flowing at two angles only", [p for p in study if p["angle"] in (22, 24)],
        ["2 angles", "three are needed"])
# The flow rule on its own (the h_stop step always leaves one flowing point per angle it used):
# two flowing points inside (delta1, delta2) are refused.
hstop = {"delta1": large["delta1"], "delta2": large["delta2"], "A": large["A"]}
two = [p for p in study if p["state"] == "flowing"][:2] + [p for p in study if p["state"] == "arrested"]
try:
    cf.fit_flow_rule(two, hstop)
    check(False, "two flowing points: refused")
except cf.FitError as error:
    check("2 steady flowing points" in str(error), f"two flowing points: refused saying {str(error)!r}")

# A layer of one particle that flows below thicker arrested layers (a monolayer rolling over
# the base): set aside, the fit is that of the study without it; taken as the thinnest flowing
# layer, it would have put the 22-degree bracket of h_stop below its arrested side.
hstop22 = cf.hstop_model(22, large["delta1"], large["delta2"], large["A"])
monolayer = {"angle": 22, "h": 0.5 * min(p["h"] for p in study if p["angle"] == 22 and p["state"] == "arrested") + 0.01,
             "F": 0.9, "mu": math.tan(math.radians(22)), "state": "flowing"}
check(monolayer["h"] < hstop22, f"the monolayer ({monolayer['h']:.2f}) lies below h_stop(22) = {hstop22:.2f}")
marked = cf.set_aside_thin_flows(study + [monolayer])
check(marked[-1]["state"] == "thin-flowing" and [p["state"] for p in marked[:-1]] == [p["state"] for p in study],
      "the monolayer alone is set aside")
with_it, without = cf.fit_all(study + [monolayer]), cf.fit_all(study)
check(all(with_it[k] == without[k] for k in cf.PARAMETERS), "the fit with the monolayer is the fit without it")
raw = dict((a, (h, e)) for a, h, e in cf.hstop_per_angle(study + [monolayer]))
check(raw[22][0] - raw[22][1] < monolayer["h"] + 1e-12 and raw[22][0] < hstop22,
      "unmarked, the monolayer would have been the 22-degree bracket's flowing side")

# An unsteady point that sped up (a slow flow whose velocity still rose when its run ended)
# brackets h_stop from above like a steady one; one that slowed down brackets nothing; the flow
# rule leaves both out.
slow = dict(monolayer, h=hstop22 * 1.02, F=0.05, state="unsteady", uChange=0.4)
estimate = dict((a, (h, e)) for a, h, e in cf.hstop_per_angle(study + [slow]))[22]
check(estimate[0] + estimate[1] == slow["h"], "an unsteady flow speeding up just above h_stop is the 22-degree "
                                              "bracket's flowing side")
stopping = dict(slow, uChange=-0.9)
check(cf.hstop_per_angle(study + [stopping]) == cf.hstop_per_angle(study), "one slowing down brackets nothing")
check(len(cf.fit_flow_rule(study + [slow], without["hstop"])["F"]) == len(cf.fit_flow_rule(study, without["hstop"])["F"]),
      "the flow rule leaves the unsteady point out")

# The height offset: a study written with every h too high by 0.74 (the driver's h against the
# thickness of a uniform layer, Calibration.md accounts (c)) and its F = u / sqrt(h cos theta)
# computed with that h, F (h / (h + 0.74))^(1/2), read back with --height-offset 0.74, gives the
# true h and F again (to rounding); an offset that leaves a point no height is refused naming the flag.
import csv  # noqa: E402
import tempfile  # noqa: E402
with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "results.csv")
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["species", "angle", "h", "F", "mu", "alpha", "state", "uChange"])
        writer.writeheader()
        for q in study:
            writer.writerow({"species": "large", "angle": q["angle"], "h": repr(q["h"] + 0.74),
                             "F": repr(q["F"] * math.sqrt(q["h"] / (q["h"] + 0.74))), "mu": q["mu"], "alpha": 1.2,
                             "state": q["state"], "uChange": 0})
    back = cf.read_points(path, "large", height_offset=0.74)
    worst = max(max(abs(b["h"] - q["h"]), abs(b["F"] - q["F"])) for b, q in zip(back, study))
    check(worst < 1e-12, f"height offset 0.74: h and F read back within {worst:.2g} of the study's")
    try:
        cf.read_points(path, "large", height_offset=50)
        check(False, "height offset 50: refused")
    except cf.FitError as error:
        check("--height-offset 50" in str(error), f"height offset 50: refused saying {str(error)!r}")

# Parameters held (fitCalibration.py --hold): held at the truth the misfit is the free fit's
# within its noise (two fewer free parameters: the least squares cannot do better than free, and
# the truth fits the synthetic points); held 5 degrees off in delta2 with A at the truth, far worse;
# held below an angle of the points (where the curve is not defined), refused.
truth_study = synthetic_study(large, 1.0, np.linspace(large["delta1"] + 1.5, large["delta2"] - 1.5, 9), 28, seed=7)
free = cf.fit_all(truth_study)
at_truth = cf.fit_all(truth_study, held={"delta2": large["delta2"], "A": large["A"]})
off = cf.fit_all(truth_study, held={"delta2": large["delta2"] + 5, "A": large["A"]})
try:
    cf.fit_all(truth_study, held={"delta2": large["delta2"] - 5})
    check(False, "delta2 held below an angle of the points: refused")
except cf.FitError as error:
    check("held delta1 and delta2" in str(error), f"delta2 held below an angle of the points: refused saying {str(error)!r}")
check(at_truth["delta2"] == large["delta2"] and at_truth["A"] == large["A"], "held parameters keep their values")
check(free["misfit"] <= at_truth["misfit"] * (1 + 1e-9), f"holding cannot fit better than free ({free['misfit']:.4g} "
                                                         f"<= {at_truth['misfit']:.4g})")
check(at_truth["misfit"] < 1.25 * free["misfit"],
      f"held at the truth: misfit {at_truth['misfit']:.4g} within 25% of the free fit's {free['misfit']:.4g}")
check(off["misfit"] > 5 * at_truth["misfit"], f"delta2 held 5 degrees high: misfit {off['misfit']:.4g} far above "
                                              f"{at_truth['misfit']:.4g}")
import importlib.util  # noqa: E402
spec = importlib.util.spec_from_file_location("fitCalibration", os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                                              "fitCalibration.py"))
tool = importlib.util.module_from_spec(spec)
spec.loader.exec_module(tool)
check(tool.parse_held("delta2=30.06, A=3.07") == {"delta2": 30.06, "A": 3.07}, "--hold read")
for text, words in (("delta3=1", ["delta3", "delta1"]), ("A=big", ["A=big", "not a number"])):
    try:
        tool.parse_held(text)
        check(False, f"--hold {text}: refused")
    except cf.FitError as error:
        check(all(w in str(error) for w in words), f"--hold {text}: refused saying {str(error)!r}")

finish("calibration fit")
