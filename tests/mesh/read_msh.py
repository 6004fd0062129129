"""Reads a gmsh .msh file with meshio (not our code, not gmsh's) and prints what tests/mesh checks, as JSON:

  nodes                         number of nodes in the file
  physical_names                {name: dimension}
  tetrahedra, triangles         {physical name: count}
  inverted                      tetrahedra whose signed volume det[p1-p0, p2-p0, p3-p0] / 6 is <= 0
                                (gmsh's node order gives valid tetrahedra a positive volume)
  volume                        {physical volume name: sum of the tetrahedra's signed volumes, mm^3}
  triangles_in_no_region        boundary triangles that are no face of any tetrahedron
  triangles_between_regions     boundary triangles that are a face of tetrahedra of two regions

Usage: read_msh.py MESH.msh OUT.json
"""
import json
import sys

import meshio
import numpy as np


def blocks_of(mesh, cell_type):
    """(connectivity, physical tag per cell) of every block of one cell type."""
    physical = mesh.cell_data["gmsh:physical"]
    return [(block.data, physical[i]) for i, block in enumerate(mesh.cells) if block.type == cell_type]


def face_keys(triangles, n):
    """One int64 per triangle, the same for any order of its nodes."""
    t = np.sort(triangles, axis=1).astype(np.int64)
    return (t[:, 0] * n + t[:, 1]) * n + t[:, 2]


def main(path, out):
    mesh = meshio.read(path)
    n = len(mesh.points)
    if float(n) ** 3 >= 2.0**63:
        raise SystemExit("too many nodes for the int64 triangle keys")
    names = {int(tag): str(name) for name, (tag, dim) in mesh.field_data.items() if dim == 3}
    surface_names = {int(tag): str(name) for name, (tag, dim) in mesh.field_data.items() if dim == 2}
    result = {
        "nodes": n,
        "physical_names": {str(name): int(dim) for name, (tag, dim) in mesh.field_data.items()},
        "tetrahedra": {},
        "triangles": {},
        "volume": {},
        "inverted": 0,
    }
    region_faces = {}
    for cells, tags in blocks_of(mesh, "tetra"):
        p = mesh.points[cells]
        signed = np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6
        result["inverted"] += int(np.count_nonzero(signed <= 0))
        for tag in np.unique(tags):
            name = names[int(tag)]
            mine = tags == tag
            result["tetrahedra"][name] = result["tetrahedra"].get(name, 0) + int(np.count_nonzero(mine))
            result["volume"][name] = result["volume"].get(name, 0.0) + float(signed[mine].sum())
            faces = np.concatenate([cells[mine][:, [0, 1, 2]], cells[mine][:, [0, 1, 3]],
                                    cells[mine][:, [0, 2, 3]], cells[mine][:, [1, 2, 3]]])
            region_faces.setdefault(name, []).append(face_keys(faces, n))
    region_faces = {name: np.unique(np.concatenate(k)) for name, k in region_faces.items()}
    boundary = []
    for cells, tags in blocks_of(mesh, "triangle"):
        for tag in np.unique(tags):
            name = surface_names[int(tag)]
            result["triangles"][name] = result["triangles"].get(name, 0) + int(np.count_nonzero(tags == tag))
        boundary.append(face_keys(cells, n))
    boundary = np.concatenate(boundary)
    sides = np.zeros(len(boundary), dtype=np.int64)
    for keys in region_faces.values():
        sides += np.isin(boundary, keys)
    result["triangles_in_no_region"] = int(np.count_nonzero(sides == 0))
    result["triangles_between_regions"] = int(np.count_nonzero(sides == 2))
    with open(out, "w") as f:
        json.dump(result, f)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
