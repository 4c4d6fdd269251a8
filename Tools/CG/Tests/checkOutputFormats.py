#!/usr/bin/python3
"""Checks that talus-cg's HDF5/XDMF and .stat outputs hold the same numbers as its CSV output
(Documentation/CoarseGraining.md "Output formats", Documentation/FileFormats/stat.md).

usage: checkOutputFormats.py FIELDS.csv FIELDS.h5 FIELDS.stat

- FIELDS.h5 (read with h5py): every CSV field column equals its dataset, point by point
  and frame by frame; a grid's datasets are (nz, ny, nx) with x fastest, so point (i, j, k)
  of the CSV's order (x slowest) is [k, j, i]; /grid/x,y,z or /points give the coordinates.
- FIELDS.xmf: well-formed XML; one grid per frame with the frame's time; the topology's
  dimensions are the datasets' shapes; every DataItem names a dataset of FIELDS.h5 with
  the stated dimensions.
- FIELDS.stat: MercuryDPM's layout: 85 names and Talus's InteractionForceX Y Z, a parameter
  line, per frame a time line (t, or tmin tmax for a time average) and one line of 3 + 88
  numbers per point; VolumeFraction, Density, Momentum and InteractionForce equal the CSV's,
  NormalStress its ContactStress, and MomentumFlux - p p / rho its KineticStress.

The CSV values have 12 significant digits (%.12g), so values agree to a relative 1e-11 of
the column's largest magnitude (the HDF5 and .stat values have 17 and 16 digits).
Prints "output formats ok" when all agree.
"""
import sys
import xml.etree.ElementTree as ElementTree

import h5py
import numpy as np

from cgCsv import read_csv, relative_difference

TOLERANCE = 1e-11


def fail(message):
    sys.exit(f"checkOutputFormats.py: {message}")


def frames_of(names, data):
    """The CSV rows split per frame: a list of (time or None, rows)."""
    if 't' not in names:
        return [(None, data)]
    t = data[:, names.index('t')]
    return [(time, data[t == time]) for time in np.unique(t)]


def agree(what, expected, found):
    error = relative_difference(expected, found)
    if not error <= TOLERANCE:
        fail(f"{what}: differs from the CSV by {error:.3g} of its largest value")
    return error


def check_hdf5(names, frames, path):
    worst = 0.0
    xmf_path = path.rsplit('.', 1)[0] + '.xmf'
    with h5py.File(path, 'r') as h5:
        times = h5['time'][()]
        if len(times) != len(frames):
            fail(f"{path}: {len(times)} frames, the CSV has {len(frames)}")
        grid = 'grid' in h5
        axes = [a for a in 'xyz' if a in names]
        for f, (time, rows) in enumerate(frames):
            if time is not None and abs(times[f] - time) > 1e-9 * max(1, abs(time)):
                fail(f"{path}: frame {f} at t = {times[f]}, the CSV's at {time}")
            group = h5[f'frames/{f:06d}']
            if grid:
                n = [len(h5[f'grid/{a}']) for a in 'xyz']
                # CSV order: x slowest, z fastest; the datasets are (nz, ny, nx).
                def to_csv_order(array):
                    return np.transpose(array, (2, 1, 0)).reshape(-1)
                for k, a in enumerate('xyz'):
                    if a in axes:
                        coordinate = np.broadcast_to(h5[f'grid/{a}'][()].reshape([-1 if m == k else 1 for m in range(3)]), n)
                        worst = max(worst, agree(f"{path} /grid/{a}", rows[:, names.index(a)], coordinate.reshape(-1)))
            else:
                def to_csv_order(array):
                    return array
                points = h5['points'][()]
                for k, a in enumerate('xyz'):
                    if a in axes:
                        worst = max(worst, agree(f"{path} /points {a}", rows[:, names.index(a)], points[:, k]))
            fields = [c for c in names if c not in ('t', 'x', 'y', 'z')]
            if sorted(fields) != sorted(group.keys()):
                fail(f"{path}: frame {f} has datasets {sorted(group.keys())}, the CSV columns {fields}")
            for c in fields:
                worst = max(worst, agree(f"{path} frame {f} {c}", rows[:, names.index(c)], to_csv_order(group[c][()])))
        check_xdmf(xmf_path, h5, times)
    return worst


def check_xdmf(path, h5, times):
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as error:
        fail(f"{path}: not well-formed XML: {error}")
    grids = root.findall('./Domain/Grid/Grid')
    if len(grids) != len(times):
        fail(f"{path}: {len(grids)} grids, the HDF5 file has {len(times)} frames")
    for grid, time in zip(grids, times):
        if abs(float(grid.find('Time').get('Value')) - time) > 1e-9 * max(1, abs(time)):
            fail(f"{path}: grid {grid.get('Name')} at t = {grid.find('Time').get('Value')}, the HDF5 frame at {time}")
        topology = grid.find('Topology')
        items = grid.findall('.//DataItem')
        for item in items:
            file_name, dataset = item.text.strip().split(':', 1)
            if dataset not in h5:
                fail(f"{path}: {dataset} is not in {file_name}")
            dims = tuple(int(d) for d in item.get('Dimensions').split())
            if h5[dataset].shape != dims:
                fail(f"{path}: {dataset} has shape {h5[dataset].shape}, the XDMF says {dims}")
        attributes = grid.findall('Attribute')
        if topology.get('TopologyType') == '3DRectMesh':
            shape = tuple(int(d) for d in topology.get('Dimensions').split())
            for a in attributes:
                if tuple(int(d) for d in a.find('DataItem').get('Dimensions').split()) != shape:
                    fail(f"{path}: attribute {a.get('Name')} does not have the topology's dimensions {shape}")
        elif topology.get('TopologyType') == 'Polyvertex':
            if int(topology.get('NumberOfElements')) != h5['points'].shape[0]:
                fail(f"{path}: Polyvertex with {topology.get('NumberOfElements')} elements, {h5['points'].shape[0]} points")
        else:
            fail(f"{path}: unexpected topology {topology.get('TopologyType')}")


def check_stat(names, frames, path):
    with open(path) as f:
        lines = f.read().split('\n')
    stat_names = lines[0].split()
    if len(stat_names) != 88 or stat_names[0] != 'VolumeFraction' or stat_names[84] != 'ContactCoupleStressZZ' \
            or stat_names[85:] != ['InteractionForceX', 'InteractionForceY', 'InteractionForceZ']:
        fail(f"{path}: line 1 does not hold MercuryDPM's 85 field names and InteractionForceX Y Z")
    parameters = lines[1].split()
    if parameters[0] != 'w' or parameters[2] != 'dim' or parameters[4] != 'domainStat' or parameters[11] != 'n' or parameters[15] != 'statType':
        fail(f"{path}: line 2 is not MercuryDPM's parameter line: {lines[1]}")
    blocks, at = [], 2
    while at < len(lines) and lines[at].strip():
        head = [float(v) for v in lines[at].split()]
        rows = [[float(v) for v in line.split()] for line in lines[at + 1:at + 1 + len(frames[0][1])]]
        if len(head) not in (1, 2) or any(len(r) != 91 for r in rows):
            fail(f"{path} line {at + 1}: expected a time line and rows of 91 numbers")
        blocks.append((head, np.array(rows)))
        at += 1 + len(rows)
    if len(blocks) != len(frames):
        fail(f"{path}: {len(blocks)} time blocks, the CSV has {len(frames)} frames")
    worst = 0.0
    column = {name: 3 + k for k, name in enumerate(stat_names)}
    for (head, stat), (time, rows) in zip(blocks, frames):
        if time is not None and abs(head[-1] - time) > 1e-9 * max(1, abs(time)):
            fail(f"{path}: block at t = {head[-1]}, the CSV frame at {time}")
        for k, a in enumerate('xyz'):
            if a in names:
                worst = max(worst, agree(f"{path} {a}", rows[:, names.index(a)], stat[:, k]))
        for ours, theirs in [('Density', 'Density'), ('VolumeFraction', 'VolumeFraction'),
                             ('MomentumX', 'MomentumX'), ('MomentumY', 'MomentumY'), ('MomentumZ', 'MomentumZ')]:
            worst = max(worst, agree(f"{path} {theirs}", rows[:, names.index(ours)], stat[:, column[theirs]]))
        if 'ContactStressXX' in names:
            for c in ['XX', 'XY', 'XZ', 'YX', 'YY', 'YZ', 'ZX', 'ZY', 'ZZ']:
                worst = max(worst, agree(f"{path} NormalStress{c}", rows[:, names.index('ContactStress' + c)], stat[:, column['NormalStress' + c]]))
            for c in 'XYZ':
                worst = max(worst, agree(f"{path} InteractionForce{c}", rows[:, names.index('InteractionForce' + c)],
                                         stat[:, column['InteractionForce' + c]]))
        rho = stat[:, column['Density']]
        p = [stat[:, column['Momentum' + a]] for a in 'XYZ']
        for c in ['XX', 'XY', 'XZ', 'YY', 'YZ', 'ZZ']:
            a, b = 'XYZ'.index(c[0]), 'XYZ'.index(c[1])
            kinetic = np.where(rho > 0, stat[:, column['MomentumFlux' + c]] - p[a] * p[b] / np.where(rho > 0, rho, 1), 0.0)
            # K - p p / rho cancels where the flow is uniform: compare with the scale of K itself.
            scale = max(np.max(np.abs(stat[:, column['MomentumFlux' + c]])), 1e-300)
            error = np.max(np.abs(kinetic - rows[:, names.index('KineticStress' + c)])) / scale
            if not error <= TOLERANCE:
                fail(f"{path}: MomentumFlux{c} - p p / rho differs from KineticStress{c} by {error:.3g}")
    return worst


def main():
    if len(sys.argv) != 4:
        fail(__doc__.split('\n\n')[1])
    names, data = read_csv(sys.argv[1])
    frames = frames_of(names, data)
    hdf5_error = check_hdf5(names, frames, sys.argv[2])
    stat_error = check_stat(names, frames, sys.argv[3])
    print(f"{len(frames)} frames of {len(frames[0][1])} points: HDF5 within {hdf5_error:.2g}, .stat within {stat_error:.2g} "
          f"of the CSV (relative to each column's largest value)")
    print("output formats ok")


if __name__ == '__main__':
    main()
