#!/usr/bin/python3
"""Self-test: the .pvd index and every .vtu frame of a run are well-formed VTK XML that ParaView
reads: each frame lists as many points as the matching .data frame has particles, every data
array holds one value (or 3-vector) per point, and the positions equal the .data positions.

usage: checkVtu.py NAME   (run in the folder of the run)
"""
import sys
import xml.etree.ElementTree as ET


def data_frames(path):
    with open(path) as f:
        rows = [line.split() for line in f]
    frames, k = [], 0
    while k < len(rows):
        n = int(rows[k][0])
        frames.append([[float(x) for x in r[:3]] for r in rows[k + 1:k + 1 + n]])
        k += n + 1
    return frames


def main(name):
    frames = data_frames(name + ".data")
    collection = ET.parse(name + ".pvd").getroot().find("Collection")
    files = [d.get("file") for d in collection.findall("DataSet")]
    if len(files) != len(frames):
        sys.exit(f"{name}.pvd lists {len(files)} frames, {name}.data has {len(frames)}")
    for file, positions in zip(files, frames):
        piece = ET.parse(file).getroot().find("UnstructuredGrid/Piece")
        n = int(piece.get("NumberOfPoints"))
        if n != len(positions):
            sys.exit(f"{file}: {n} points, the .data frame has {len(positions)} particles")
        for array in piece.iter("DataArray"):
            if array.get("Name") in ("connectivity", "offsets", "types"):
                continue
            values = (array.text or "").split()
            width = int(array.get("NumberOfComponents"))
            if len(values) != n * width:
                sys.exit(f"{file}: array {array.get('Name')} has {len(values)} values for {n} points")
            if array.get("Name") == "Position":
                for k in range(n):
                    for a in range(3):
                        if abs(float(values[3 * k + a]) - positions[k][a]) > 1e-8 * max(1, abs(positions[k][a])):
                            sys.exit(f"{file}: position of point {k} differs from the .data frame")
    print(f"vtu ok: {len(files)} frames")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
