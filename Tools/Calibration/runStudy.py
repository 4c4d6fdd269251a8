#!/usr/bin/python3
"""Runs a periodic-chute calibration study (Documentation/Calibration.md): one CalibrationChute
run per point of a grid of species, angles and depths, as independent jobs (--jobs at once).

Each point runs in its own folder OUT/points/NAME, and a killed study resumes where it stopped when
the same command runs again (Tools/Studies/studyRunner.py: finished points are skipped, killed
ones continue from their restart files; --done takes the points of an earlier results.csv as
finished). Every finished point's line goes into OUT/results.csv.

    Tools/Calibration/runStudy.py --driver build/Drivers/Calibration/CalibrationChute --out DIR

Without grid flags the reduced default study runs: large spheres on a base of small spheres in a
10 x 10 box, angles 23 to 27 degrees by 1, depths 1, 2, 3, 4 and 6 (25 points; estimated at 15
to 30 minutes on two free cores).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Studies"))
from studyRunner import Point, run_study  # noqa: E402 (Tools/Studies, beside this folder)

# The reduced default study: large spheres only (the fewest per unit depth) in a 10 x 10 box
# (in 6 x 6 the flows near h_stop fluctuate too much for any plateau) on a base of small spheres
# (the thesis's section 3.2.4; on a base of large spheres h_stop comes out 1.5 to 2 times Table
# 3.1's: Documentation/Calibration.md "Accounts"), five angles and five depths around the large
# spheres' h_stop curve: Table 3.1 (d1 = 18.6, d2 = 30.06 deg, A = 3.07) gives h_stop = 5.4, 3.8,
# 2.7, 1.9, 1.2 at 23 ... 27 deg, which the driver's h puts 0.74 higher, and a depth D gives h of
# about D + 0.7. A plateau of 100 samples within 5%, 30 time units of averaging, at most 500 a point.
REDUCED = {
    "species": ["large"],
    "angles": [23, 24, 25, 26, 27],
    "depths": [1, 2, 3, 4, 6],
    "driver_flags": ["--base-diameter", "0.7937005259840998", "--length", "10", "--width", "10", "--window", "100",
                     "--tolerance", "0.05", "--average-time", "30", "--end-time", "500"],
}


def parse_list(text, kind, flag):
    try:
        return [kind(x) for x in text.split(",") if x.strip() != ""]
    except ValueError:
        sys.exit(f"runStudy: {flag} {text!r}: a comma-separated list of numbers is expected")


def point_name(species, angle, depth):
    return f"{species}-a{angle:g}-d{depth:g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--driver", required=True, help="the CalibrationChute program")
    parser.add_argument("--out", required=True, help="the study's folder (points/ and results.csv)")
    parser.add_argument("--species", help="comma-separated: large, small, mixture")
    parser.add_argument("--angles", help="comma-separated angles in degrees")
    parser.add_argument("--depths", help="comma-separated depths (CalibrationChute --depth)")
    parser.add_argument("--jobs", type=int, default=2, help="points run at once (default 2)")
    parser.add_argument("--restart-interval", type=float, default=20,
                        help="simulated time between restart files of a point (default 20)")
    parser.add_argument("--done", help="an earlier results.csv: its points of this grid count as finished")
    parser.add_argument("driver_flags", nargs="*", help="after --: flags for every point's run")
    args = parser.parse_args()

    grid_given = args.species is not None or args.angles is not None or args.depths is not None
    species = args.species.split(",") if args.species is not None else REDUCED["species"]
    angles = parse_list(args.angles, float, "--angles") if args.angles is not None else REDUCED["angles"]
    depths = parse_list(args.depths, float, "--depths") if args.depths is not None else REDUCED["depths"]
    flags = list(args.driver_flags) if grid_given or args.driver_flags else list(REDUCED["driver_flags"])
    species = [s for s in species if s.strip() != ""]
    if not species or not angles or not depths:
        missing = [f for f, v in (("--species", species), ("--angles", angles), ("--depths", depths)) if not v]
        sys.exit(f"runStudy: the study grid is empty: {', '.join(missing)} gave no values")
    # A point costs about its number of spheres, so its depth.
    points = [Point(point_name(s, a, d), ["--species", s, "--angle", f"{a:g}", "--depth", f"{d:g}"], cost=d)
              for s in species for a in angles for d in depths]
    run_study("runStudy", args.driver, args.out, points, args.jobs, ["--vtu", "off", "--fstat", "off"] + flags,
              args.restart_interval, done=args.done,
              describe=lambda row: f"{row['state']}, h = {row['h']}, F = {row['F']}")


if __name__ == "__main__":
    main()
