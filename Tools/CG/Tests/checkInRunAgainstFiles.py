#!/usr/bin/env python3
"""In-run coarse graining against talus-cg on the same frames (InRun/InRunFields.h).

usage: checkInRunAgainstFiles.py INRUN.csv FILES.csv [--frames FRAMES.csv]

INRUN.csv was written by a run's in-run coarse graining (snapshots, one block per sample, each
sample at an output step), FILES.csv by talus-cg from the .data/.fstat files that the same run
wrote at those steps, with the same coordinates, kernel, points and fixed-particle mode. Both
evaluate the same sums (Fields/CoarseGrainer.h) of the same particles and contacts; they differ
only by what the files round:

  .data    positions with 15 significant digits, velocities with 10, radii with 10 (the radii of
           this chute, 0.5, print exactly, so masses and volumes are exact);
  .fstat   contact points, overlaps, fn, |ft|, normals and tangents with 10 digits;
  .csv     every field with 12 digits (both files).

A number printed with 10 digits is within 5e-10 of itself, relatively. Hence, with W_i the
kernel at particle i and the sums over the particles:
  Density, VolumeFraction: exact inputs (positions to 5e-15: a change of W of order 1e-14), so
      only the csv's 12 digits and summation order: |d| <= 1e-11 |F|.
  MomentumA: |d p_a| <= 5e-10 sum m_i |v_ia| W_i <= 5e-10 sqrt(rho K_aa) (Cauchy-Schwarz), with
      K_aa = sum m_i v_ia^2 W_i = KineticStressAA + p_a^2 / rho, from the file itself.
      VelocityA = p_a / rho: the same divided by rho.
  KineticStressAB = K_ab - p_a p_b / rho: |d K_ab| <= 1e-9 sqrt(K_aa K_bb) (Cauchy-Schwarz again)
      and |d(p_a p_b / rho)| <= 5e-10 (sqrt(rho K_aa) |p_b| + |p_a| sqrt(rho K_bb)) / rho
      <= 1e-9 sqrt(K_aa K_bb), since |p_a| <= sqrt(rho K_aa): together 2e-9 sqrt(K_aa K_bb).
  ContactStress, InteractionForce: each contact's f (x) b carries fn, |ft|, n, t and the overlap,
      each to 5e-10: at most about 3e-9 of |f| |b| per contact. The sum of |f| |b| W over the
      contacts near a point is bounded by a small multiple of the largest stress component of the
      frame (forces are mostly compressive, |ft| <= 0.5 fn), so the bound is taken as 1e-8 times
      the largest |component| of the field in the frame.
  Stress: the kinetic and contact bounds added.
  Cylindrical coordinates (RZ, R): a particle's radial and azimuthal velocities u_r, u_t come
      from its two lab components across the axis (each printed to 5e-10 of itself: an error of
      at most 5e-10 sqrt(2) |u|, |u|^2 = u_r^2 + u_t^2), and they enter the angular average with
      the weights <W cos phi>, <W sin phi>, at most <W> in size. So Cauchy-Schwarz runs over the
      weights <W> and |u|^2: K_RR and K_ThetaTheta in the bounds above are replaced by
      2 (K_RR + K_ThetaTheta) (= 2 sum m |u|^2 <W>); the axial component is bounded as a lab
      one. AngularVelocity = VelocityTheta / r: its bound divided by r.
Positions printed with 15 digits (|x| <= 11 here: 6e-14) move each kernel value by at most
|dW/dx| 6e-14 <= 1.8 W(0) / w 6e-14 (Lucy's largest slope is 16/9 W(0) / w, Gauss's 0.61),
2.2e-13 W(0) for w = 0.5: an absolute 1e-12 times the frame's largest |value| of the column,
which holds at least one particle's W(0)-sized contribution in these frames.
Time averages (INRUN.csv averaged over the run, FILES.csv by talus-cg --time-average, FRAMES.csv
the same frames one by one): the sums are averaged before the fields are derived, so each sum's
error is the mean of the frames' errors. The Cauchy-Schwarz bounds hold for the averaged sums
themselves (the mean of sqrt(a_f b_f) is at most sqrt(mean a mean b), and |<p_a>| is at most
sqrt(<rho> <K_aa>)); the contact bound is 1e-8 times the mean over the frames of each frame's
largest |component|, taken from FRAMES.csv. Every bound is doubled for margin, and 1e-11 |F| is added for the two csv files' 12 digits. The script
prints the largest ratio |difference| / bound over all numbers (it must stay below 1) and the
largest relative difference of the density.
"""
import math
import sys


def read(path):
    names, rows = None, []
    for line in open(path):
        if line.startswith('#'):
            continue
        if names is None:
            names = line.strip().split(',')
            continue
        rows.append([float(v) for v in line.split(',')])
    return names, rows


def pair(suffix, axes):
    """The two components a tensor column's suffix names ('XZ', 'RTheta', 'ThetaAxial', ...)."""
    for first in axes:
        if suffix.startswith(first) and suffix[len(first):] in axes:
            return first, suffix[len(first):]
    sys.exit(f'FAIL: no components in {suffix!r}')


def blocks(names, rows):
    """Rows grouped by the time column (one block for a time average, which has none)."""
    if 't' not in names:
        return {'average': rows}
    t = names.index('t')
    out = {}
    for r in rows:
        out.setdefault(r[t], []).append(r)
    return out


def main():
    inrun_path, files_path = sys.argv[1], sys.argv[2]
    frames_path = sys.argv[4] if len(sys.argv) > 4 and sys.argv[3] == '--frames' else None
    names, inrun = read(inrun_path)
    names_files, files = read(files_path)
    if names != names_files:
        sys.exit(f'FAIL: the columns differ:\n{names}\n{names_files}')
    a, b = blocks(names, inrun), blocks(names, files)
    if sorted(a) != sorted(b):
        sys.exit(f'FAIL: the frames differ: in-run {sorted(a)}, files {sorted(b)}')
    col = {n: k for k, n in enumerate(names)}
    # The components of vectors and tensors: lab axes, or the local cylindrical basis (r, theta,
    # along the axis) of coordinates RZ and R.
    axes = ('R', 'Theta', 'Axial') if 'MomentumR' in col else ('X', 'Y', 'Z')
    worst, worst_where, density_rel, contacts_seen = 0.0, '', 0.0, False
    for time in sorted(a):
        ra, rb = a[time], b[time]
        if len(ra) != len(rb):
            sys.exit(f'FAIL: t = {time}: {len(ra)} points in-run, {len(rb)} from the files')
        column_max = [max(abs(r[k]) for r in rb) for k in range(len(names))]
        family_max = {}
        for fam in ('ContactStress', 'InteractionForce'):
            cols = [k for n, k in col.items() if n.startswith(fam)]
            if frames_path:  # (the mean over the averaged frames of each frame's largest value)
                frame_names, frame_rows = read(frames_path)
                per_frame = list(blocks(frame_names, frame_rows).values())
                fcols = [k for k, n in enumerate(frame_names) if n.startswith(fam)]
                family_max[fam] = sum(max(abs(r[k]) for r in rows for k in fcols) for rows in per_frame) / len(per_frame)
            else:
                family_max[fam] = max((abs(r[k]) for r in rb for k in cols), default=0.0)
        contacts_seen = contacts_seen or family_max.get('ContactStress', 0) > 0
        for x, y in zip(ra, rb):
            for n in ('r', 'x', 'y', 'z'):
                if n in col and x[col[n]] != y[col[n]]:
                    sys.exit(f'FAIL: t = {time}: the points differ')
            rho = y[col['Density']]
            K = {}
            for i, c in enumerate(axes):
                p = y[col['Momentum' + c]]
                K[c] = y[col['KineticStress' + c + c]] + (p * p / rho if rho > 0 else 0.0)
            if 'R' in K:  # (cylindrical: the bounds of the components across the axis, below)
                K['R'] = K['Theta'] = 2 * (K['R'] + K['Theta'])
            for name, k in col.items():
                if name in ('t', 'r', 'x', 'y', 'z'):
                    continue
                F = y[k]
                if name in ('Density', 'VolumeFraction'):
                    bound = 0.0  # (exact inputs: positions only)
                elif name.startswith('Momentum'):
                    c = name[len('Momentum'):]
                    bound = 5e-10 * math.sqrt(max(rho * K[c], 0.0))
                elif name == 'AngularVelocity':  # (VelocityTheta / r, at r > 0)
                    bound = 5e-10 * math.sqrt(max(rho * K['Theta'], 0.0)) / rho / y[col['r']] if rho > 0 else 0.0
                elif name.startswith('Velocity'):
                    c = name[len('Velocity'):]
                    bound = 5e-10 * math.sqrt(max(rho * K[c], 0.0)) / rho if rho > 0 else 0.0
                elif name.startswith('KineticStress'):
                    c1, c2 = pair(name[len('KineticStress'):], axes)
                    bound = 2e-9 * math.sqrt(max(K[c1] * K[c2], 0.0))
                elif name.startswith('ContactStress'):
                    bound = 1e-8 * family_max['ContactStress']
                elif name.startswith('InteractionForce'):
                    bound = 1e-8 * family_max['InteractionForce']
                elif name.startswith('Stress'):
                    c1, c2 = pair(name[len('Stress'):], axes)
                    bound = 2e-9 * math.sqrt(max(K[c1] * K[c2], 0.0)) + 1e-8 * family_max['ContactStress']
                elif name.startswith('Concentration') or name.startswith('Density'):
                    bound = 0.0
                else:
                    sys.exit(f'FAIL: no bound for column {name}')
                tol = 2 * bound + 1e-11 * abs(F) + 1e-12 * column_max[k] + 1e-300
                diff = abs(x[k] - F)
                if diff / tol > worst:
                    worst, worst_where = diff / tol, f'{name} at t = {time}: {x[k]!r} in-run, {F!r} from the files'
                if name == 'Density' and F != 0:
                    density_rel = max(density_rel, diff / abs(F))
    print(f'{len(a)} frames of {len(next(iter(a.values())))} points, {len(names)} columns; largest |difference| / bound '
          f'{worst:.3g} ({worst_where}); largest relative difference of the density {density_rel:.3g}')
    if not contacts_seen:
        sys.exit('FAIL: no contact stress in any frame (the comparison would not test the contacts)')
    if worst > 1:
        sys.exit('FAIL: in-run and talus-cg differ beyond the printed precision')
    print('in-run fields agree with talus-cg')


main()
