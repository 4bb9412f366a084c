#!/usr/bin/env python3
"""Plot a deformed cross-section of a rod_cross_section run, coloured by a
point field of its solution-NNNN.vtu (default von_Mises_stress).

Usage: python3 scripts/plot_section.py RUN_DIR_OR_VTU OUT.png [FIELD]

RUN_DIR_OR_VTU is a run's output directory (the last file of its
solution.pvd is used) or one solution-NNNN.vtu. The section is drawn at its
deformed in-plane position (the first two components of the `position`
field, true scale), the out-of-plane warping is not shown. One line is
printed per PNG written.

Reads the VTU with the standard library (xml, base64, zlib): ASCII, base64
binary and zlib-compressed base64 binary (what deal.II writes) data arrays,
UInt32 headers. Needs matplotlib (Agg backend).
Exit status: 0, 1 bad usage or unreadable file, 2 matplotlib cannot be
imported.
If the interpreter running this script has no matplotlib but the system
interpreter /usr/bin/python3 has it (Debian's python3-matplotlib), the
script re-runs itself with that interpreter (as plot_steps.py does).
"""

import base64
import os
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
import zlib

USAGE = "usage: python3 scripts/plot_section.py RUN_DIR_OR_VTU OUT.png [FIELD]\n"
FORMATS = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt32": "I",
           "Int64": "q", "UInt64": "Q", "UInt8": "B", "Int8": "b"}


def decode_array(element, compressed):
    """The values of one <DataArray> as a flat list."""
    kind = FORMATS[element.get("type")]
    text = "".join((element.text or "").split())
    if element.get("format", "ascii") == "ascii":
        conv = float if kind in "fd" else int
        return [conv(v) for v in text.split()] if text else []
    size = struct.calcsize(kind)
    if not compressed:
        raw = base64.b64decode(text)
        (nbytes,) = struct.unpack("<I", raw[:4])
        raw = raw[4:4 + nbytes]
    else:
        # Header (base64 on its own): nblocks, block size, last block size,
        # then the compressed size of every block; then the blocks.
        (nblocks,) = struct.unpack("<I", base64.b64decode(text[:8])[:4])
        header_len = 4 * ((4 * (3 + nblocks) + 2) // 3)
        header = struct.unpack("<%dI" % (3 + nblocks),
                               base64.b64decode(text[:header_len]))
        data = base64.b64decode(text[header_len:])
        raw, pos = b"", 0
        for csize in header[3:]:
            raw += zlib.decompress(data[pos:pos + csize])
            pos += csize
    return list(struct.unpack("<%d%s" % (len(raw) // size, kind), raw))


def read_vtu(path):
    root = ET.parse(path).getroot()
    compressed = root.get("compressor") is not None
    if root.get("header_type", "UInt32") != "UInt32":
        raise ValueError("only UInt32 headers are supported")
    piece = root.find("UnstructuredGrid/Piece")
    points = decode_array(piece.find("Points/DataArray"), compressed)
    cells = {a.get("Name"): decode_array(a, compressed)
             for a in piece.find("Cells").findall("DataArray")}
    fields = {}
    for a in piece.find("PointData").findall("DataArray"):
        n = int(a.get("NumberOfComponents", "1"))
        values = decode_array(a, compressed)
        fields[a.get("Name")] = [values[i::n] for i in range(n)]
    return points, cells, fields


def last_vtu(run_dir):
    pvd = os.path.join(run_dir, "solution.pvd")
    files = [d.get("file") for d in ET.parse(pvd).getroot().iter("DataSet")]
    if not files:
        raise ValueError("%s lists no files" % pvd)
    return os.path.join(run_dir, files[-1])


def reexec_with_system_python():
    """Re-run this script with /usr/bin/python3 if it has matplotlib."""
    system = "/usr/bin/python3"
    if os.environ.get("PLOT_SECTION_REEXEC") or not os.access(system, os.X_OK):
        return
    if os.path.realpath(system) == os.path.realpath(sys.executable):
        return
    if subprocess.call([system, "-c", "import matplotlib"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL) != 0:
        return
    env = dict(os.environ, PLOT_SECTION_REEXEC="1")
    sys.stdout.flush()
    os.execve(system, [system, os.path.abspath(sys.argv[0])] + sys.argv[1:], env)


def lagrange_quad_grid(c):
    """The point ids of a VTK Lagrange quadrilateral as grid[j][i], i, j = 0..p:
    VTK orders its corners, then the edges (0-1, 1-2, 3-2, 0-3, each in
    increasing parameter), then the interior (i fastest)."""
    p = int(round(len(c) ** 0.5)) - 1
    g = [[None] * (p + 1) for _ in range(p + 1)]
    g[0][0], g[0][p], g[p][p], g[p][0] = c[0], c[1], c[2], c[3]
    k = 4
    for i in range(1, p):
        g[0][i] = c[k]; k += 1
    for j in range(1, p):
        g[j][p] = c[k]; k += 1
    for i in range(1, p):
        g[p][i] = c[k]; k += 1
    for j in range(1, p):
        g[j][0] = c[k]; k += 1
    for j in range(1, p):
        for i in range(1, p):
            g[j][i] = c[k]; k += 1
    return g


def main(argv):
    if len(argv) not in (3, 4):
        sys.stderr.write(USAGE)
        return 1
    source, out = argv[1], argv[2]
    field = argv[3] if len(argv) == 4 else "von_Mises_stress"
    try:
        vtu = last_vtu(source) if os.path.isdir(source) else source
        points, cells, fields = read_vtu(vtu)
    except (OSError, ValueError, KeyError, AttributeError, ET.ParseError,
            struct.error, zlib.error) as e:
        sys.stderr.write("plot_section.py: cannot read %s: %s\n" % (source, e))
        return 1
    if field not in fields:
        sys.stderr.write("plot_section.py: %s has no point field '%s' (it has: %s)\n"
                         % (vtu, field, ", ".join(sorted(fields))))
        return 1
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.tri as mtri
    except ImportError:
        reexec_with_system_python()
        sys.stderr.write("plot_section.py: matplotlib cannot be imported\n")
        return 2
    if "position" in fields:
        x, y = fields["position"][0], fields["position"][1]
        where = "deformed section"
    else:
        x, y = points[0::3], points[1::3]
        where = "reference section"
    # Quadrilaterals (VTK type 9) split into two triangles each; Lagrange
    # quadrilaterals (type 70, the suite's Q_p cells) into their p x p
    # sub-quadrilaterals first.
    triangles, start = [], 0
    conn = cells["connectivity"]
    for end, kind in zip(cells["offsets"], cells["types"]):
        c = conn[start:end]
        if kind == 9 and len(c) == 4:
            triangles += [(c[0], c[1], c[2]), (c[0], c[2], c[3])]
        elif kind == 70:
            grid = lagrange_quad_grid(c)
            p = len(grid) - 1
            for j in range(p):
                for i in range(p):
                    a, b, d, e = grid[j][i], grid[j][i + 1], grid[j + 1][i + 1], grid[j + 1][i]
                    triangles += [(a, b, d), (a, d, e)]
        start = end
    tri = mtri.Triangulation(x, y, triangles)
    values = fields[field][0]
    fig, ax = plt.subplots(figsize=(5.6, 4.6))
    image = ax.tripcolor(tri, values, shading="gouraud", cmap="viridis")
    fig.colorbar(image, ax=ax, label=field.replace("_", " "))
    ax.set_aspect("equal")
    ax.set_xlabel("x1 (deformed)")
    ax.set_ylabel("x2 (deformed)")
    run = os.path.basename(os.path.dirname(os.path.abspath(vtu)))
    ax.set_title("%s: %s, %s" % (run, where, os.path.basename(vtu)), fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)
    print("wrote %s" % out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
