#!/usr/bin/python3
"""Checks talus-cg's VTK output (--output-format vtk, App/VtkFieldWriter.h) with VTK's own readers
(Debian python3-vtk9) against its CSV output of the same run.

usage: checkVtkOutput.py FIELDS.csv FIELDS.pvd

- FIELDS.pvd, parsed by vtkXMLDataParser, is a Collection with one DataSet per CSV frame, at the
  frame's time, naming a .vti file beside it.
- Each .vti file, read by vtkXMLImageDataReader without an error or a warning, is an image of
  nx x ny x nz points (1 on averaged axes) whose point coordinates (origin + index x spacing)
  are the CSV's coordinate columns (x, y, z; r and the axis coordinate in cylindrical
  coordinates, in image axes 0 and 2); its TimeValue is the frame's time.
- A point list (--points) is written as .vtu files instead, read by vtkXMLUnstructuredGridReader:
  one vertex cell (VTK type 1) per point, the points in the CSV's order, their coordinates the
  CSV's coordinate columns.
- Its point arrays hold every CSV field column, none left out and nothing else: a scalar as a
  1-component array named like the column; Momentum, Velocity, InteractionForce with 3
  components; KineticStress, ContactStress and Stress with 9 (row-major; the symmetric
  KineticStress's YX equals the CSV's XY). Component names come from the arrays' ComponentName
  attributes. Every value equals the CSV's.

VTK numbers points x fastest (id = i + nx (j + ny k)), the CSV z fastest; the CSV prints 12
significant digits (%.12g) and the .vti holds the doubles' bits, so values agree to 1e-11 of the
column's largest magnitude.
Prints "vtk output ok" when all agree. Without VTK's Python module it prints
"checkVtkOutput: skipped: ..." (ctest marks the test skipped by that line) and exits 0.
"""
import os
import sys

import numpy as np

from cgCsv import read_csv, relative_difference

try:
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError as error:
    print(f"checkVtkOutput: skipped: VTK's Python module is not installed ({error}); "
          "install python3-vtk9 (Scripts/setup.sh) to run this test")
    sys.exit(0)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "SelfTests"))
import vtkFiles  # noqa: E402 (after the check that VTK is there)

TOLERANCE = 1e-11
VECTORS = ('Momentum', 'Velocity', 'InteractionForce')
TENSORS = ('KineticStress', 'ContactStress', 'Stress')


def fail(message):
    sys.exit(f"checkVtkOutput: {message}")


def pvd_entries(path):
    return vtkFiles.pvd_entries(path, fail)


def read_dataset(path):
    reader = vtk.vtkXMLUnstructuredGridReader() if path.endswith('.vtu') else vtk.vtkXMLImageDataReader()
    return vtkFiles.read_without_complaint(reader, path, fail)


def agree(what, expected, found):
    error = relative_difference(expected, found)
    if not error <= TOLERANCE:
        fail(f"{what}: differs from the CSV by {error:.3g} of its largest value")
    return error


def transposed(component):
    """XY -> YX, RTheta -> ThetaR (components are two axis names)."""
    for first in ('Theta', 'Axial', 'R', 'X', 'Y', 'Z'):
        if component.startswith(first) and component != first:
            return component[len(first):] + first
    return component


def main():
    if len(sys.argv) != 3:
        fail(__doc__.split('\n\n')[1])
    names, data = read_csv(sys.argv[1])
    frames = [(None, data)] if 't' not in names else [(t, data[data[:, 0] == t]) for t in np.unique(data[:, 0])]
    cylindrical = 'r' in names
    axis_names = ['r', None, next((a for a in 'xyz' if a in names), None)] if cylindrical else ['x', 'y', 'z']
    fields = [c for c in names if c not in ('t', 'r', 'x', 'y', 'z')]
    entries = pvd_entries(sys.argv[2])
    if len(entries) != len(frames):
        fail(f"{sys.argv[2]}: {len(entries)} data sets, the CSV has {len(frames)} frames")
    folder = os.path.dirname(sys.argv[2])
    worst, arrays_seen = 0.0, 0
    for (timestep, file_name), (time, rows) in zip(entries, frames):
        if time is not None and timestep != time and abs(timestep - time) > 1e-11 * max(1, abs(time)):
            fail(f"{file_name}: timestep {timestep}, the CSV frame's time {time}")
        image = read_dataset(os.path.join(folder, file_name))
        time_value = vtk_to_numpy(image.GetFieldData().GetArray("TimeValue"))[0]
        if time_value != timestep:
            fail(f"{file_name}: TimeValue {time_value}, the .pvd says {timestep}")
        if file_name.endswith('.vtu'):
            # A point list: the points in the CSV's order, one vertex each.
            if image.GetNumberOfPoints() != len(rows):
                fail(f"{file_name}: {image.GetNumberOfPoints()} points, the CSV frame has {len(rows)} rows")
            types = vtk_to_numpy(image.GetCellTypesArray()) if image.GetNumberOfCells() else np.array([])
            if image.GetNumberOfCells() != len(rows) or not np.all(types == vtk.VTK_VERTEX):
                fail(f"{file_name}: {image.GetNumberOfCells()} cells, not one vertex per point")
            n = (len(rows), 1, 1)
            points = vtk_to_numpy(image.GetPoints().GetData())

            def vtk_order(column):
                return column

            def coordinate_of(k):
                return points[:, k]
        else:
            n = image.GetDimensions()
            if n[0] * n[1] * n[2] != len(rows):
                fail(f"{file_name}: {n} points, the CSV frame has {len(rows)} rows")

            def vtk_order(column):
                return column.reshape(n[0], n[1], n[2]).transpose(2, 1, 0).reshape(-1)

            origin, spacing = image.GetOrigin(), image.GetSpacing()
            index = np.indices((n[2], n[1], n[0])).reshape(3, -1)[::-1]  # (i, j, k) per VTK id

            def coordinate_of(k):
                return origin[k] + spacing[k] * index[k]
        for k in range(3):
            coordinate = coordinate_of(k)
            if axis_names[k] in names:
                worst = max(worst, agree(f"{file_name} coordinate {axis_names[k]}", vtk_order(rows[:, names.index(axis_names[k])]), coordinate))
            elif n[k] != 1 and not file_name.endswith('.vtu'):
                fail(f"{file_name}: {n[k]} points along image axis {k}, which the CSV does not resolve")
        point_data = image.GetPointData()
        covered = set()
        for a in range(point_data.GetNumberOfArrays()):
            array = point_data.GetArray(a)
            name, count = array.GetName(), array.GetNumberOfComponents()
            expected = 3 if name in VECTORS else 9 if name in TENSORS else 1
            if count != expected:
                fail(f"{file_name}: array {name} has {count} components, expected {expected}")
            values = vtk_to_numpy(array).reshape(len(rows), count)
            for c in range(count):
                column = name + (array.GetComponentName(c) if count > 1 else '')
                if column not in names and count == 9:
                    column = name + transposed(array.GetComponentName(c))
                if column not in fields:
                    fail(f"{file_name}: array {name} component {c} ({column}) is not a CSV column")
                covered.add(column)
                worst = max(worst, agree(f"{file_name} {name}[{c}]", vtk_order(rows[:, names.index(column)]), values[:, c]))
            arrays_seen = point_data.GetNumberOfArrays()
        if covered != set(fields):
            fail(f"{file_name}: CSV columns without an array: {sorted(set(fields) - covered)}")
    print(f"{len(frames)} frames of {len(frames[0][1])} points, {arrays_seen} arrays: VTK within {worst:.2g} of the CSV "
          f"(relative to each column's largest value)")
    print("vtk output ok")


if __name__ == '__main__':
    main()
