#!/usr/bin/python3
"""Self-test: the ParaView file of a run's triangle meshes (NAME_mesh.vtu, Kernel/IO/VtuWriter.h),
read with VTK's own reader (Debian python3-vtk9), holds the triangles of the table the run read:
one VTK_TRIANGLE cell (type 5) per line of the table, in its order, whose three points are the
line's three corners in order (to 1e-9 of the mesh's size: corners that coincide are one vertex,
kept as first read), and whose Wall array counts up from FIRST (the mesh's first wall). With
ANGLE AX AY AZ, the table's corners turned by ANGLE (radians, right-hand rule) about the axis
(AX, AY, AZ) through the origin: a frame of a turning mesh (NAME_mesh_K.vtu).

usage: checkMeshVtu.py NAME_mesh.vtu TABLE FIRST [ANGLE AX AY AZ]
prints "mesh vtu ok: T triangles" or exits 1.
"""
import sys

import numpy
import vtk
from vtk.util.numpy_support import vtk_to_numpy

path, table, first = sys.argv[1], sys.argv[2], int(sys.argv[3])
rows = []
for line in open(table).read().splitlines()[1:]:
    if line.strip():
        rows.append([float(v) for v in line.split()])
corners = numpy.array(rows).reshape(-1, 3, 3)
if len(sys.argv) == 8:
    # Rodrigues' rotation of every corner about the unit axis u.
    angle = float(sys.argv[4])
    u = numpy.array([float(v) for v in sys.argv[5:8]])
    u /= numpy.linalg.norm(u)
    c, s = numpy.cos(angle), numpy.sin(angle)
    x = corners.reshape(-1, 3)
    turned = x * c + numpy.cross(u, x) * s + numpy.outer(x @ u, u) * (1 - c)
    corners = turned.reshape(-1, 3, 3)

reader = vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName(path)
reader.Update()
grid = reader.GetOutput()
failures = []
cells = grid.GetNumberOfCells()
if cells != len(corners):
    failures.append(f"{cells} cells, the table has {len(corners)} triangles")
points = vtk_to_numpy(grid.GetPoints().GetData())
size = numpy.linalg.norm(corners.reshape(-1, 3).max(axis=0) - corners.reshape(-1, 3).min(axis=0))
walls = vtk_to_numpy(grid.GetCellData().GetArray("Wall"))
worst = 0.0
for k in range(min(cells, len(corners))):
    cell = grid.GetCell(k)
    if cell.GetCellType() != vtk.VTK_TRIANGLE:
        failures.append(f"cell {k} is of type {cell.GetCellType()}, not a triangle")
        break
    ids = [cell.GetPointId(c) for c in range(3)]
    worst = max(worst, float(numpy.abs(points[ids] - corners[k]).max()))
    if walls[k] != first + k:
        failures.append(f"cell {k} has wall {walls[k]}, expected {first + k}")
        break
if worst > 1e-9 * size:
    failures.append(f"corners differ from the table's by up to {worst:.3g} (mesh size {size:.3g})")
for f in failures:
    print("FAILED:", f)
if failures:
    sys.exit(1)
print(f"mesh vtu ok: {cells} triangles, corners within {worst:.1e} of the table's")
