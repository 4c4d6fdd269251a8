#!/usr/bin/python3
"""Self-test: the ParaView files of a run, read with VTK's own readers (Debian python3-vtk9), hold
what the .data frames hold.

- NAME.pvd, parsed by vtkXMLDataParser (the parser of VTK's collection readers), lists one
  DataSet per .data frame, at the .data frame's time, each naming an existing .vtu file.
- Each .vtu frame, read by vtkXMLUnstructuredGridReader without an error or warning, has one
  point and one VTK_VERTEX cell (type 1, holding point k) per particle of its .data frame.
- Its point arrays equal the .data columns: Radius, Velocity, AngularVelocity and Species are
  written with the same 10 significant digits as .data and must read back identical; Position
  (15 digits in .data, 10 in .vtu) to within half a unit in the 10th digit; Id increases (both
  files list particles in id order). With superquadrics, the rotation matrix of Orientation
  equals the one of the .data roll, pitch and yaw angles (Tait-Bryan Z-Y-X) to 1e-8 (the
  angles' 10 digits move the matrix by at most ~5e-9), and ShapeTensor turned into the body
  frame, R^T T R, is diagonal (to 1e-8 of the radius) with positive semi-axes no larger than
  the bounding radius.

usage: checkVtu.py NAME   (run in the folder of the run); prints "vtu ok: F frames" or exits 1.
"""
import math
import os
import sys

import numpy
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import vtkFiles

VTK_VERTEX = 1


def fail(message):
    sys.exit("checkVtu: " + message)


def data_frames(path):
    """The .data frames: (time, rows of x y z vx vy vz r thx thy thz wx wy wz species)."""
    with open(path) as f:
        rows = [line.split() for line in f]
    frames, k = [], 0
    while k < len(rows):
        n, time = int(rows[k][0]), float(rows[k][1])
        frames.append((time, numpy.array([[float(x) for x in r] for r in rows[k + 1:k + 1 + n]]).reshape(n, 14)))
        k += n + 1
    return frames


def pvd_entries(path):
    return vtkFiles.pvd_entries(path, fail)


def read_vtu(path):
    return vtkFiles.read_without_complaint(vtk.vtkXMLUnstructuredGridReader(), path, fail)


def rotation_of_quaternion(w, x, y, z):
    return numpy.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def rotation_of_angles(roll, pitch, yaw):
    cx, sx, cy, sy, cz, sz = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    rx = numpy.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    ry = numpy.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    rz = numpy.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    return rz @ ry @ rx


def check_frame(file, rows):
    grid = read_vtu(file)
    n = len(rows)
    if grid.GetNumberOfPoints() != n or grid.GetNumberOfCells() != n:
        fail(f"{file}: {grid.GetNumberOfPoints()} points and {grid.GetNumberOfCells()} cells, "
             f"the .data frame has {n} particles")
    types = vtk_to_numpy(grid.GetCellTypesArray()) if n else numpy.array([])
    if n and not (types == VTK_VERTEX).all():
        fail(f"{file}: cell types {sorted(set(types.tolist()))}, expected only VTK_VERTEX (1)")
    cells = grid.GetCells()
    connectivity = vtk_to_numpy(cells.GetConnectivityArray()) if n else numpy.array([])
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    if not (numpy.array_equal(connectivity, numpy.arange(n)) and numpy.array_equal(offsets, numpy.arange(n + 1))):
        fail(f"{file}: cell k must hold point k alone")
    if n == 0:
        return
    points = vtk_to_numpy(grid.GetPoints().GetData())
    data = grid.GetPointData()

    def array(name, width):
        a = data.GetArray(name)
        if a is None:
            fail(f"{file}: no point array {name}")
        values = vtk_to_numpy(a).reshape(n, width) if width > 1 else vtk_to_numpy(a)
        return values

    # Position: |vtu - data| <= half a unit in the 10th significant digit (5e-10 |x|) plus the
    # 15-digit rounding of .data.
    bound = 5.01e-10 * numpy.abs(rows[:, 0:3])
    if (numpy.abs(points - rows[:, 0:3]) > bound).any():
        fail(f"{file}: a position differs from the .data frame by more than the 10-digit rounding")
    for name, columns in (("Radius", [6]), ("Velocity", [3, 4, 5]), ("AngularVelocity", [10, 11, 12]),
                          ("Species", [13])):
        values = array(name, len(columns))
        expected = rows[:, columns[0]] if len(columns) == 1 else rows[:, columns]
        if not numpy.array_equal(values.astype(float), expected):
            fail(f"{file}: {name} differs from the .data frame")
    ids = array("Id", 1)
    if not (numpy.diff(ids.astype(numpy.int64)) > 0).all():
        fail(f"{file}: Id does not increase (the order of .data)")
    if data.GetArray("Orientation") is None:
        return
    orientation, tensor, radius = array("Orientation", 4), array("ShapeTensor", 9), rows[:, 6]
    for k in range(n):
        r = rotation_of_quaternion(*orientation[k])
        if numpy.abs(r - rotation_of_angles(*rows[k, 7:10])).max() > 1e-8:
            fail(f"{file}: the orientation of point {k} differs from the .data angles")
        body = r.T @ tensor[k].reshape(3, 3) @ r
        axes = numpy.diag(body)
        if numpy.abs(body - numpy.diag(axes)).max() > 1e-8 * radius[k] or not (
                (axes > 0).all() and (axes <= radius[k] * (1 + 1e-9)).all()):
            fail(f"{file}: ShapeTensor of point {k} is not R diag(a, b, c) R^T with 0 < a, b, c <= the radius")


def main(name):
    frames = data_frames(name + ".data")
    entries = pvd_entries(name + ".pvd")
    if len(entries) != len(frames):
        fail(f"{name}.pvd lists {len(entries)} frames, {name}.data has {len(frames)}")
    for k, ((time, file), (data_time, rows)) in enumerate(zip(entries, frames)):
        # .pvd times have 12 digits, .data times 10.
        if abs(time - data_time) > 5.01e-10 * abs(data_time):
            fail(f"{name}.pvd: frame {k} at t = {time}, the .data frame at {data_time}")
        if file != f"{name}_{k}.vtu" or not os.path.exists(file):
            fail(f"{name}.pvd: frame {k} is '{file}', expected an existing {name}_{k}.vtu")
        check_frame(file, rows)
    print(f"vtu ok: {len(entries)} frames")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
