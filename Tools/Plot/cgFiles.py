"""Reading talus-cg's field files for the plotting scripts (Documentation/CoarseGraining.md
"Files" and "Output formats"): the CSV file and the HDF5 file, both as one dictionary of
columns in the CSV's point order (x slowest, z fastest for a grid)."""
import sys

import numpy as np


def read_cg_csv(path, program):
    """(columns, comments): columns maps each CSV column name to its values; comments are the
    '#' lines. `program` names the caller in error messages."""
    with open(path) as f:
        comments, lines = [], []
        for line in f:
            (comments if line.startswith('#') else lines).append(line)
    if not lines:
        sys.exit(f"{program}: {path}: no column names (not a talus-cg CSV file)")
    names = lines[0].strip().split(',')
    data = np.loadtxt(lines[1:], delimiter=',', ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}, comments


def read_cg_hdf5(path, program, frame=-1):
    """The columns of one frame (default the last) of a talus-cg HDF5 file, in the CSV's order,
    with 't' and the coordinates of the resolved directions."""
    import h5py
    with h5py.File(path, 'r') as h5:
        if 'frames' not in h5:
            sys.exit(f"{program}: {path}: no /frames group (not a talus-cg HDF5 file)")
        times = h5['time'][()]
        index = range(len(times))[frame]
        group = h5[f'frames/{index:06d}']
        resolved = h5.attrs['coordinates']
        resolved = resolved.decode() if isinstance(resolved, bytes) else str(resolved)
        columns = {}
        if 'grid' in h5:
            axes = [h5[f'grid/{a}'][()] for a in 'xyz']
            mesh = np.meshgrid(*axes, indexing='ij')  # x slowest, z fastest
            for a, values in zip('xyz', mesh):
                if a.upper() in resolved:
                    columns[a] = values.reshape(-1)
            # The datasets are (nz, ny, nx), x fastest: back to the CSV order.
            for name in group:
                columns[name] = np.transpose(group[name][()], (2, 1, 0)).reshape(-1)
        else:
            points = h5['points'][()]
            for k, a in enumerate('xyz'):
                if a.upper() in resolved:
                    columns[a] = points[:, k]
            for name in group:
                columns[name] = group[name][()]
        columns['t'] = np.full(len(columns[next(iter(group))]), times[index])
    return columns


def read_cg_fields(path, program):
    """The columns of a CSV or HDF5 (.h5, .hdf5) file; for a CSV file with several frames
    (a 't' column) only the last frame."""
    if path.endswith(('.h5', '.hdf5')):
        return read_cg_hdf5(path, program)
    columns, _ = read_cg_csv(path, program)
    if 't' in columns:
        last = columns['t'] == columns['t'].max()
        columns = {name: values[last] for name, values in columns.items()}
    return columns
