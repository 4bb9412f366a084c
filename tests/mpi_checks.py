"""What the tests of distributed meshes (mpi_distributed_mesh.sh,
mpi_distributed_section.sh) check alike: the run directories' summary.json,
located events against their resolution, and the .pvtu records against a
serial run's VTU."""
import json, os, re

failures = 0


def check(cond, what):
    global failures
    print(("  ok    " if cond else "  FAIL  ") + what)
    failures += not cond


def load(directory):
    return json.load(open(f"{directory}/summary.json"))


def same_events(name, a, b):
    """The same events (kind, inertia before and after) at loads equal to the larger
    of their two resolutions (summary.json location.resolution)."""
    e1, e2 = a["events"], b["events"]
    check(len(e1) == len(e2) and len(e1) >= 1, f"{name}: {len(e1)} and {len(e2)} events")
    for x, y in zip(e1, e2):
        res = max(x["location"]["resolution"], y["location"]["resolution"])
        same = (x["kind"], x["n_negative_before"], x["n_negative_after"]) == (y["kind"], y["n_negative_before"], y["n_negative_after"])
        check(same and abs(x["t"] - y["t"]) <= res,
              f"{name}: {x['kind']} at t = {x['t']:.13g} and {y['t']:.13g}, |difference| {abs(x['t'] - y['t']):.1e} <= resolution {res:.1e}, inertia {x['n_negative_before']} -> {x['n_negative_after']} on both")


def same_section_state(name, a, b):
    """The section's 6x6 stiffness (of its largest entry) and strains the same to 1e-10,
    Newton's stopping test, and the same inertia."""
    ka = [x for r in a["stiffness"] for x in r]; kb = [x for r in b["stiffness"] for x in r]
    dk = max(abs(x - y) for x, y in zip(ka, kb)) / max(abs(x) for x in ka)
    ds = max(abs(a["strains"][k] - b["strains"][k]) for k in a["strains"])
    check(dk <= 1e-10 and ds <= 1e-10 and a["stability"] == b["stability"],
          f"{name}: stiffness the same to {dk:.1e} of its scale, strains to {ds:.1e} (<= 1e-10), inertia {b['stability']['n_negative_eigenvalues']} on both")


def read_vtk(path, field):
    """Cells and the largest |field| of a .vtu or .pvtu, read by VTK (ParaView's library)."""
    import numpy as np
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    r = vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    return g.GetNumberOfCells(), np.abs(vtk_to_numpy(g.GetPointData().GetArray(field))).max()


def pieces_present(directory, stem, ranks):
    """The record stem.pvtu lists the pieces stem.0000.vtu ... of `ranks` ranks, all present."""
    pieces = re.findall(r'Source="([^"]+)"', open(f"{directory}/{stem}.pvtu").read())
    return (sorted(pieces) == [f"{stem}.{r:04d}.vtu" for r in range(ranks)] and
            all(os.path.isfile(f"{directory}/{p}") for p in pieces))


def same_as_serial_vtu(serial_directory, directory, stem, field):
    """stem.pvtu has the serial stem.vtu's cells and largest |field| (Float32: to 1e-6 of it)."""
    c1, u1 = read_vtk(f"{serial_directory}/{stem}.vtu", field)
    c2, u2 = read_vtk(f"{directory}/{stem}.pvtu", field)
    check(c1 == c2 and abs(u1 - u2) <= 1e-6 * u1,
          f"{stem}.pvtu: {c2} cells as the serial VTU's {c1}, largest |{field}| {u2:.7g} against {u1:.7g}")
