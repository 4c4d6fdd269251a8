"""The fit of a periodic-chute calibration study (Documentation/Calibration.md "The fit"), as
functions that fitCalibration.py and the tests call.

Points are dicts with the columns of CalibrationChute's result line: angle (degrees), h, F, mu
and state ("flowing", "arrested" or "undecided"). Lengths are in large-sphere diameters; d is the
diameter of the flowing spheres, so that A comes out in units of d as in the thesis's Table 3.1.
"""
import math

import numpy as np
from scipy.optimize import least_squares


class FitError(Exception):
    """Too few points of a kind for a step of the fit; the message says what is missing."""


PARAMETERS = ("delta1", "delta2", "A", "beta", "gamma")


def hstop_model(theta_deg, delta1, delta2, a_d):
    """h_stop(theta) = A d (tan d2 - tan theta) / (tan theta - tan d1): the inverse of
    tan theta = tan d1 + (tan d2 - tan d1) / (h_stop / (A d) + 1) (Pouliquen and Forterre 2002)."""
    t = np.tan(np.radians(theta_deg))
    return a_d * (math.tan(math.radians(delta2)) - t) / (t - math.tan(math.radians(delta1)))


def flows(point):
    """Whether a point brackets h_stop from above: steady, or unsteady and speeding up."""
    return point["state"] == "flowing" or (point["state"] == "unsteady" and point.get("uChange", 0) > 0)


def hstop_per_angle(points):
    """For each angle with both an arrested and a flowing point: h_stop halfway between the
    thickest arrested layer and the thinnest flowing one, and half their distance as its
    uncertainty. Returns a sorted list of (angle, h_stop, half gap). An unsteady point that
    sped up over its averaging flows (a slow flow just above h_stop whose velocity still
    wanders: it had not stopped when its run ended, and was not slowing down); one that slowed
    down may have been on its way to a stop, and brackets nothing. The flow rule uses neither."""
    angles = sorted({p["angle"] for p in points})
    estimates = []
    for angle in angles:
        arrested = [p["h"] for p in points if p["angle"] == angle and p["state"] == "arrested"]
        flowing = [p["h"] for p in points if p["angle"] == angle and flows(p)]
        if arrested and flowing:
            low, high = max(arrested), min(flowing)
            estimates.append((angle, 0.5 * (low + high), 0.5 * abs(high - low)))
    return estimates


def set_aside_thin_flows(points):
    """The points with each flowing layer (steady or not) that is thinner than the thickest arrested layer at its
    angle marked "thin-flowing" (copies; the others as they are). Such a layer is about one
    particle deep and rolls over the base's bumps as single spheres (Documentation/Calibration.md,
    "The v2 study"): not the flowing state of a bulk layer above h_stop. Taken as the thinnest
    flowing layer, it would put the bracket of h_stop below its arrested side; neither the
    h_stop nor the flow-rule fit uses it."""
    thickest = {}
    for p in points:
        if p["state"] == "arrested":
            thickest[p["angle"]] = max(thickest.get(p["angle"], -math.inf), p["h"])
    return [dict(p, state="thin-flowing")
            if p["state"] in ("flowing", "unsteady") and p["h"] < thickest.get(p["angle"], -math.inf) else p
            for p in points]


def fit_hstop(points, d=1.0):
    """delta1, delta2 (degrees) and A from the arrested/flowing boundary: least squares in
    log h_stop over the angles that have both kinds of point, with delta1 below the smallest and
    delta2 above the largest of those angles (where the model is finite and positive)."""
    estimates = hstop_per_angle(points)
    if len(estimates) < 3:
        have = ", ".join(f"{a:g}" for a, _, _ in estimates) or "none"
        raise FitError(f"h_stop fit: {len(estimates)} angles have both an arrested and a flowing point "
                       f"(angles: {have}); three are needed for delta1, delta2 and A: add depths above and below "
                       "h_stop at more angles")
    theta = np.array([e[0] for e in estimates])
    hstop = np.array([e[1] for e in estimates])
    low, high = theta.min(), theta.max()

    def residual(x):
        return np.log(hstop_model(theta, x[0], x[1], x[2])) - np.log(hstop)

    start = [max(low - 3, 1), min(high + 5, 80), float(np.median(hstop)) / 2]
    fit = least_squares(residual, start, bounds=([0.01, high + 1e-6, 1e-6], [low - 1e-6, 89.9, np.inf]))
    delta1, delta2, a_d = fit.x
    return {"delta1": delta1, "delta2": delta2, "A": a_d / d, "estimates": estimates}


def fit_flow_rule(points, hstop_fit, d=1.0, with_gamma=True, beta=None, gamma=None):
    """beta and gamma of F = beta h / h_stop(theta) - gamma by least squares over the steady
    flowing points at angles inside (delta1, delta2) (gamma = 0 when with_gamma is False; both
    as given when given, for the residuals of a joint fit)."""
    delta1, delta2, a_d = hstop_fit["delta1"], hstop_fit["delta2"], hstop_fit["A"] * d
    used = [p for p in points if p["state"] == "flowing" and delta1 < p["angle"] < delta2 and math.isfinite(p["F"])]
    if len(used) < 3:
        raise FitError(f"flow rule fit: {len(used)} steady flowing points at angles inside (delta1, delta2) = "
                       f"({delta1:.2f}, {delta2:.2f}) degrees; at least 3 are needed: add depths above h_stop")
    x = np.array([p["h"] / hstop_model(p["angle"], delta1, delta2, a_d) for p in used])
    y = np.array([p["F"] for p in used])
    if beta is not None:
        pass
    elif with_gamma:
        beta, minus_gamma = np.polyfit(x, y, 1)
        gamma = -minus_gamma
    else:
        beta, gamma = float(x @ y / (x @ x)), 0.0
    residuals = y - (beta * x - gamma)
    return {"beta": beta, "gamma": gamma, "x": x, "F": y, "residuals": residuals, "used": used}


def friction_law(h, froude, delta1, delta2, a_d, beta, gamma):
    """mu(h, F) = tan d1 + (tan d2 - tan d1) / (beta h / (A d (F + gamma)) + 1): the h_stop curve
    with h_stop = beta h / (F + gamma) from the flow rule (Weinhart et al. 2012; gamma = 0 gives the
    thesis's eq. (3.11))."""
    t1, t2 = math.tan(math.radians(delta1)), math.tan(math.radians(delta2))
    return t1 + (t2 - t1) / (beta * np.asarray(h) / (a_d * (np.asarray(froude) + gamma)) + 1)


def refine_jointly(h, rule, d, with_gamma, held=None):
    """All parameters at once, from the h_stop estimates and the flowing points together: weighted
    least squares of log h_stop (each estimate weighted by its uncertainty, the half gap relative
    to h_stop, at least 2%) and of F (weighted by the rms residual of the separate flow-rule fit,
    at least 0.005). Near delta2 h_stop is below a particle and no depth brackets it, but the flows
    there are fast and their F depends on h_stop(theta): the joint fit lets them pin delta2 down.

    held: parameters kept at given values (names of PARAMETERS, A in units of d), the others fitted;
    the returned misfit (the sum of the squared weighted residuals) then says how much worse the
    data fit with them held than free."""
    estimates, used = h["estimates"], rule["used"]
    theta_h = np.array([e[0] for e in estimates])
    log_h = np.log([e[1] for e in estimates])
    sigma_h = np.maximum([e[2] / e[1] for e in estimates], 0.02)
    theta_f = np.array([p["angle"] for p in used])
    depth = np.array([p["h"] for p in used])
    sigma_f = max(float(np.sqrt(np.mean(rule["residuals"] ** 2))), 0.005)
    low, high = min(theta_h.min(), theta_f.min()), max(theta_h.max(), theta_f.max())

    def residual(full):
        delta1, delta2, a_d, beta, gamma = full
        on_curve = (np.log(hstop_model(theta_h, delta1, delta2, a_d)) - log_h) / sigma_h
        froude = (beta * depth / hstop_model(theta_f, delta1, delta2, a_d) - gamma - rule["F"]) / sigma_f
        return np.concatenate([on_curve, froude])

    names = PARAMETERS if with_gamma else PARAMETERS[:4]
    held = dict(held or {})
    held_full = {k: (v * d if k == "A" else v) for k, v in held.items()}  # (A d, as the model takes it)
    if not with_gamma:
        held_full["gamma"] = 0.0
    start = [min(h["delta1"], low - 1e-3), max(h["delta2"], high + 1e-3), h["A"] * d, rule["beta"], rule["gamma"]]
    lower, upper = [0.01, high + 1e-6, 1e-6, 0, -np.inf], [low - 1e-6, 89.9, np.inf, np.inf, np.inf]
    if held_full.get("delta2", math.inf) <= high or held_full.get("delta1", -math.inf) >= low:
        raise FitError(f"held delta1 and delta2 must lie below and above every angle of the points used ({low:g} to "
                       f"{high:g} degrees), where the h_stop curve is defined; held: "
                       + ", ".join(f"{k} = {v:g}" for k, v in held.items()))
    free = [k for k in PARAMETERS if k not in held_full]
    index = [PARAMETERS.index(k) for k in free]

    def expand(x):
        full = [held_full.get(k, 0.0) for k in PARAMETERS]
        for i, v in zip(index, x):
            full[i] = v
        return full

    # (The separate fits may end outside the joint bounds, e.g. a negative beta from a resample
    # with few flowing points: start inside them.)
    start = [min(max(start[i], lower[i] + 1e-6 * max(1.0, abs(lower[i]))), upper[i] - 1e-6 * max(1.0, abs(upper[i])))
             if np.isfinite(upper[i]) else max(start[i], lower[i]) for i in index]
    x = least_squares(lambda x: residual(expand(x)), start, bounds=([lower[i] for i in index], [upper[i] for i in index])).x \
        if index else []
    full = expand(x)
    delta1, delta2, a_d, beta, gamma = full
    misfit = float(np.sum(residual(full) ** 2))
    h = {"delta1": delta1, "delta2": delta2, "A": a_d / d, "estimates": estimates}
    rule = fit_flow_rule(used, h, d, with_gamma, beta=beta, gamma=gamma)
    rule["misfit"], rule["residualCount"], rule["free"] = misfit, len(theta_h) + len(theta_f), [k for k in free if k in names]
    return h, rule


def fit_all(points, d=1.0, with_gamma=True, held=None):
    """The h_stop curve and the flow rule, each on its own and then jointly (refine_jointly), and
    the friction law's residuals at the flowing points (against their measured basal friction mu
    and against tan theta). Flowing layers thinner than an arrested one at their angle are left
    out (set_aside_thin_flows)."""
    points = set_aside_thin_flows(points)
    h = fit_hstop(points, d)
    rule = fit_flow_rule(points, h, d, with_gamma)
    h, rule = refine_jointly(h, rule, d, with_gamma, held)
    used = rule["used"]
    predicted = friction_law([p["h"] for p in used], [p["F"] for p in used], h["delta1"], h["delta2"], h["A"] * d,
                             rule["beta"], rule["gamma"])
    tan_theta = np.tan(np.radians([p["angle"] for p in used]))
    return {"delta1": h["delta1"], "delta2": h["delta2"], "A": h["A"], "beta": rule["beta"], "gamma": rule["gamma"],
            "hstop": h, "rule": rule, "muPredicted": predicted, "muResidualTan": predicted - tan_theta,
            "muMeasured": np.array([p["mu"] for p in used]), "misfit": rule["misfit"],
            "residualCount": rule["residualCount"], "free": rule["free"]}



def bootstrap(points, d=1.0, with_gamma=True, replicates=200, seed=1, level=0.95, held=None):
    """Percentile intervals of the parameters from fits to the points resampled with replacement.
    Resamples for which a step has too few points are counted and left out."""
    rng = np.random.default_rng(seed)
    values = {k: [] for k in PARAMETERS}
    failed = 0
    for _ in range(replicates):
        sample = [points[i] for i in rng.integers(0, len(points), len(points))]
        try:
            fit = fit_all(sample, d, with_gamma, held)
        except FitError:
            failed += 1
            continue
        for k in PARAMETERS:
            values[k].append(fit[k])
    if failed > replicates // 2:
        raise FitError(f"bootstrap: {failed} of {replicates} resamples had too few arrested or flowing points for a "
                       "fit; the study has too few points near the h_stop curve for intervals")
    tail = 50 * (1 - level)
    intervals = {k: (float(np.percentile(v, tail)), float(np.percentile(v, 100 - tail))) for k, v in values.items()}
    return intervals, failed


def read_points(path, species=None, max_change=0.2, height_offset=0.0):
    """The result lines of a study (runStudy.py's results.csv, or one run's NAME.result.csv). A
    flowing point whose velocity changed by more than max_change of its mean over the averaging
    (column uChange) was still slowing down or speeding up: its state becomes "unsteady", and
    neither the h_stop nor the flow-rule fit uses it.

    height_offset is taken off every h (Documentation/Calibration.md "Accounts", (c): the driver's
    h, twice the mean height above z = 0, exceeds the thickness of a uniform layer of the same
    volume at the bulk's solid fraction by about 0.74); F = u / sqrt(h cos theta) follows the new
    h: F' = F sqrt(h / h')."""
    import csv
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise FitError(f"{path}: no result lines")
    kinds = sorted({r["species"] for r in rows})
    if species is None and len(kinds) > 1:
        raise FitError(f"{path}: points of several species ({', '.join(kinds)}); choose one with --species")
    points = []
    for r in rows:
        if species is not None and r["species"] != species:
            continue
        change = float(r.get("uChange", "nan"))
        state = "unsteady" if r["state"] == "flowing" and abs(change) > max_change else r["state"]
        h = float(r["h"]) - height_offset
        if not h > 0:
            raise FitError(f"--height-offset {height_offset:g}: the point at {r['angle']} degrees with h = {r['h']} "
                           "would have no height left")
        froude = float(r["F"]) * math.sqrt(float(r["h"]) / h)
        points.append({"angle": float(r["angle"]), "h": h, "F": froude, "mu": float(r["mu"]),
                       "alpha": float(r["alpha"]), "state": state, "species": r["species"], "uChange": change})
    if not points:
        raise FitError(f"{path}: no points of species {species!r} (it has {', '.join(kinds)})")
    return points
