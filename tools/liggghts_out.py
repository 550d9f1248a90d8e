"""Readers for LIGGGHTS output files, shared by the examples and the integration tests."""


def read_dump(path):
    """Reads a 'dump custom' text file: a list of (step, {id: {column: value}}), in file
    order (atoms keep the order of the file)."""
    frames = []
    with open(path) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            cols = lines[i + 8].split()[2:]
            atoms = {}
            for line in lines[i + 9:i + 9 + n]:
                row = {c: float(v) for c, v in zip(cols, line.split())}
                atoms[int(row["id"])] = row
            frames.append((step, atoms))
            i += 9 + n
        else:
            i += 1
    return frames


def read_table(path):
    """Rows of floats from a 'fix print' or similar file ('#' lines and blanks skipped)."""
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append([float(v) for v in line.split()])
    return rows
