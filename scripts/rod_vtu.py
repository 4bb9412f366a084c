#!/usr/bin/env python3
"""Reading the rod's VTU files (deal.II's zlib-compressed binary VTU) with
numpy alone: the arrays by name, the centreline's nodes, each element's
strains. Used by tests/rod_validation.py and scripts/plot_overwinding.py.
"""
import base64
import re
import struct
import zlib

import numpy as np

_ARRAY = re.compile(r'<DataArray type="(\w+)"(?: Name="([^"]*)")?(?: NumberOfComponents="(\d+)")? '
                    r'format="binary"[^>]*>\s*(.*?)\s*</DataArray>', re.S)
_TYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32, "Int64": np.int64, "UInt8": np.uint8}


def vtu_arrays(path):
    """Every array of the VTU by name ('points' for the points), as floats;
    arrays of several components as rows."""
    arrays = {}
    for m in _ARRAY.finditer(open(path).read()):
        kind, name, components, data = m.groups()
        # one zlib block header of (3 + blocks) 32-bit words, base64 on its own
        blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
        encoded = (4 * (3 + blocks) + 2) // 3 * 4
        a = np.frombuffer(zlib.decompress(base64.b64decode(data[encoded:])), dtype=_TYPES[kind]).astype(float)
        arrays[name or "points"] = a.reshape(-1, int(components)) if components else a
    return arrays


def rod_nodes(arrays):
    """The nodes of a rod-NNNN.vtu's arrays (each cell a quadratic edge whose
    first two points are its nodes)."""
    cells = arrays["connectivity"].astype(int).reshape(-1, 3)
    return np.vstack([arrays["points"][cells[:, 0]], arrays["points"][cells[-1, 1]]])


def element_strains(arrays, names=("kappa1", "kappa2", "kappa3")):
    """Each element's strains (constant on it) from a rod-NNNN.vtu's arrays,
    one row per element in the order of the arclength."""
    first = arrays["connectivity"].astype(int).reshape(-1, 3)[:, 0]
    return np.stack([arrays[n] for n in names], 1)[first]
