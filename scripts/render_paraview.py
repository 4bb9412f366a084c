"""Render a run directory of any cosmo application with ParaView, as a
researcher would open it: the last state of a branch, warped by its
displacement (every application writes reference points + `displacement`),
coloured by the quantity that tells the story.

    xvfb-run -a pvbatch scripts/render_paraview.py RUN_DIR OUT.png [BRANCH]

(`pvpython` works the same; `xvfb-run -a` only where there is no display.)
The application is read from RUN_DIR/summary.json:

- rod_cross_section: solution.pvd, coloured by von_Mises_stress, seen along
  the rod axis, with the rod piece (rod.pvd) beside it when written;
- strip: strip-branch-K.pvd (K = BRANCH, default the last branch written),
  coloured by the Z component of the director;
- plate_rod: plate-branch-K.pvd coloured by the deflection (displacement Z),
  with the rim (rim-branch-K.pvd) as a tube;
- rod: body-branch-K.pvd (its cross-section swept along it, 'Output / Body =
  section') or tube-branch-K.pvd (a tube about its centreline), or
  rod-branch-K.pvd drawn as a thick shaded line, coloured by the curvature
  component of largest magnitude.

Debian: apt-get install paraview python3-paraview xvfb xauth (scripts/setup.sh
installs them). tests/vtu_readable.py runs it on one example of each
application. Exit status 1 for a directory it cannot render.
"""
import glob
import json
import os
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, PVDReader, SaveScreenshot,
                             Show, Tube, WarpByVector)


class NoRender(Exception):
    pass


def last_time(reader):
    times = reader.TimestepValues
    if isinstance(times, (int, float)):
        return float(times)
    return max(times) if times else 0.0


def warped(pvd, view):
    reader = PVDReader(FileName=pvd)
    t = last_time(reader)
    reader.UpdatePipeline(t)
    warp = WarpByVector(Input=reader)
    warp.Vectors = ["POINTS", "displacement"]
    view.ViewTime = t
    return warp, t


def branch_file(run, stem, branch):
    """stem-branch-K.pvd (K = branch, else the last one), else stem.pvd;
    NoRender if there is none."""
    files = sorted(glob.glob(os.path.join(run, stem + "-branch-*.pvd")),
                   key=lambda f: int(f.rsplit("-", 1)[1][:-4]))
    f = (os.path.join(run, "%s-branch-%d.pvd" % (stem, branch)) if branch is not None else
         files[-1] if files else os.path.join(run, stem + ".pvd"))
    if not os.path.exists(f):
        raise NoRender("no %s PVD (%s) in %s" % (stem, os.path.basename(f), run))
    return f


def main(argv):
    if len(argv) not in (3, 4):
        sys.stderr.write(__doc__)
        return 1
    run, out = argv[1], argv[2]
    branch = int(argv[3]) if len(argv) == 4 else None
    try:
        app = json.load(open(os.path.join(run, "summary.json")))["application"]
    except (OSError, ValueError, KeyError) as e:
        sys.stderr.write("render_paraview.py: %s has no readable summary.json (%s)\n" % (run, e))
        return 1
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [900, 700]
    view.OrientationAxesVisibility = 1
    if app == "rod_cross_section":
        section, t = warped(os.path.join(run, "solution.pvd"), view)
        d = Show(section, view)
        ColorBy(d, ("POINTS", "von_Mises_stress"))
        d.NonlinearSubdivisionLevel = 2
        what = "section at t = %g, von Mises stress" % t
    elif app == "strip":
        pvd = branch_file(run, "strip", branch)
        strip, t = warped(pvd, view)
        d = Show(strip, view)
        ColorBy(d, ("POINTS", "director", "Z"))
        view.CameraPosition = [3, -4, 3]
        view.CameraViewUp = [0, 0, 1]
        what = "%s at t = %g, director Z" % (os.path.basename(pvd), t)
    elif app == "plate_rod":
        pvd = branch_file(run, "plate", branch)
        plate, t = warped(pvd, view)
        d = Show(plate, view)
        ColorBy(d, ("POINTS", "displacement", "Z"))
        d.NonlinearSubdivisionLevel = 2
        rim_pvd = pvd.replace("plate", "rim")
        if os.path.exists(rim_pvd):
            rim, _ = warped(rim_pvd, view)
            tube = Tube(Input=rim)
            tube.Radius = 0.01
            Show(tube, view)
        view.CameraPosition = [1.5, -2.5, 2.0]
        view.CameraViewUp = [0, 0, 1]
        what = "%s at t = %g, deflection" % (os.path.basename(pvd), t)
    elif app == "rod":
        # The body the rod writes (body- or tube-branch-K.pvd), else the centreline
        # as thick shaded lines (ParaView's Render Lines As Tubes; its Tube
        # filter would draw each element as a piece of its own).
        pvd = None
        for name in ("body", "tube"):  # the swept section, else the tube
            try:
                pvd, body = branch_file(run, name, branch), True
                break
            except NoRender:
                pass
        if pvd is None:
            pvd, body = branch_file(run, "rod", branch), False
        reader = PVDReader(FileName=pvd)
        t = last_time(reader)
        reader.UpdatePipeline(t)
        view.ViewTime = t
        d = Show(reader, view)
        d.SetRepresentationType("Surface")
        if not body:
            d.LineWidth = 8
            d.RenderLinesAsTubes = 1
        # Coloured by the curvature the shape has most of (a helix bent about
        # d1 is coloured by kappa1, not by a kappa2 at round-off).
        def largest(name):
            lo, hi = reader.PointData[name].GetRange()
            return max(abs(lo), abs(hi))
        field = max(["kappa1", "kappa2", "kappa3"], key=largest)
        # A part-1 section's body: its stress at the rod's strains, if any.
        if body and "section_stress" in reader.PointData.keys() and largest("section_stress") > 0:
            field = "section_stress"
        ColorBy(d, ("POINTS", field))
        view.CameraPosition = [3, -4, 3]
        view.CameraViewUp = [0, 0, 1]
        what = "%s at t = %g, %s" % (os.path.basename(pvd), t, field)
    else:
        sys.stderr.write("render_paraview.py: unknown application '%s'\n" % app)
        return 1
    d.SetScalarBarVisibility(view, True)
    view.ResetCamera()
    SaveScreenshot(out, view)
    print("wrote %s (%s: %s)" % (out, app, what))
    return 0


if __name__ == "__main__":
    try:
        status = main(sys.argv)
    except NoRender as e:
        sys.stderr.write("render_paraview.py: %s\n" % e)
        status = 1
    sys.stdout.flush()
    sys.stderr.flush()
    # Debian's pvbatch 5.11 crashes in its teardown after the work is done
    # (SIGSEGV at exit, measured here): leave without it.
    os._exit(status)
