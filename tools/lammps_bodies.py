"""Rounded polyhedra for LAMMPS's atom_style body rounded/polyhedron, shared by the
examples and the integration tests."""


def box_body(h):
    """A box of half-extents h about its centre: its 8 vertices, 12 edges and 6
    quadrilateral faces (right-handed, outward)."""
    V = [(sx * h[0], sy * h[1], sz * h[2]) for sz in (-1, 1) for sy in (-1, 1)
         for sx in (-1, 1)]
    E = [(0, 1), (2, 3), (4, 5), (6, 7), (0, 2), (1, 3), (4, 6), (5, 7), (0, 4), (1, 5),
         (2, 6), (3, 7)]
    F = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return V, E, F
