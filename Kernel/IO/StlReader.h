// Triangle meshes (Walls/TriangleMesh.h) from files, and back:
//   - STL, ASCII ("solid / facet normal / outer loop / vertex x3 / endloop / endfacet / endsolid")
//     or binary (an 80-byte header, a 32-bit triangle count, then 50 bytes per triangle: normal and
//     three corners as 32-bit floats, a 16-bit attribute). A file is binary when its size is
//     84 + 50 x its count, or when it holds a zero byte, or when it does not start with "solid"
//     (binary headers may start with "solid" too); else ASCII. The facet normals are not read: a
//     triangle's normal follows from its corner order (right-hand rule).
//   - the triangle tables of the 2024 open-source DEM benchmark: a header line, then one triangle
//     per line, the nine coordinates x y z of its three corners separated by tabs or spaces (a
//     first line of nine numbers is read as a triangle, not as the header).
// Coordinates are multiplied by `scale` (0.001 for a file in millimetres). Every problem is a
// talus::Error naming the file and the line (text) or the triangle (binary, from 1).
#pragma once

#include <string>

#include "Walls/TriangleMesh.h"

namespace talus {

enum class StlEncoding { ascii, binary };

TriangleMesh readStl(const std::string& path, double scale = 1);
TriangleMesh readTriangleTable(const std::string& path, double scale = 1);

// Writes `mesh` as STL (replacing the file as a whole, IO/DurableFile.h). ASCII keeps every double
// to the bit; binary rounds the coordinates to 32-bit floats. `solidName` is one word.
void writeStl(const std::string& path, const TriangleMesh& mesh, StlEncoding encoding,
              const std::string& solidName = "talus");

}  // namespace talus
