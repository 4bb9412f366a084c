#!/usr/bin/env python3
"""Fuzz test of the input files (ctest robustness.fuzz_inputs).

Every example .prm of the three applications (parameter_files/<app>/*.prm and
parameter_files/<app>/studies/*.prm) is first made cheap (coarse meshes, few
continuation steps, two values per study, output into a scratch directory),
then mutated one entry at a time: every number (every component of a list)
becomes 0, a negative value, nan, inf, 1e300 and 99999999999, every
expression (a muparser function of x, y, r, ...) one that does not parse.
Each mutant runs in its own scratch directory, and must

  - end with exit status 0, 1 or 2 (143 only after the SIGTERM this script
    sends when a run exceeds --timeout; the run must then end within --grace
    seconds, or it is a hang and is SIGKILLed);
  - on exit 1 (bad input), name the mutated entry in what it prints;
  - print no library or assertion text (deal.II's "An error occurred in
    line", "terminate called", "what():", KINSOL's or MUMPS's error prints...);
  - leave complete files: no *.tmp file, every summary.json valid JSON
    (no NaN/Infinity), the top one's "status" that of the exit status
    (0 converged, 2 failed, 143 interrupted; absent or not "running"/
    "converged" on exit 1).

The default run is a deterministic sample (--seed, --count, spread over the
example files) plus every example's shrunk base file; --all (or the
environment variable COSMO_FUZZ_FULL=1) runs the full set. To reproduce one
failure, use the command printed with it, e.g.
  python3 tests/fuzz_inputs.py --app plate_rod --file dome.prm \
      --entry 'Rim rod/Stiffnesses[3]' --value nan --keep
Exit status 0 only if every run passed (77: skipped, see --only-if-env).
"""

import argparse
import concurrent.futures
import json
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

APPS = ("rod_cross_section", "strip", "plate_rod")
NUMERIC_MUTATIONS = ("0", "NEG", "nan", "inf", "1e300", "99999999999")
BAD_EXPRESSION = "1 + * x)"

# Text that must never reach the user: library assertions, uncaught
# exceptions, solver libraries' own error prints, crashes.
FORBIDDEN = [
    ("deal.II exception", re.compile(r"An error occurred in line|Additional information:|"
                                     r"you have not yet declared|You can't ask for entry|"
                                     r"Stacktrace:|The violated condition was|"
                                     r"\bExc[A-Z][A-Za-z]*\b|ExcMessage")),
    ("assertion", re.compile(r"Assertion `|Assertion failed|\bassert(ion)? .*failed")),
    ("uncaught exception", re.compile(r"terminate called|what\(\):|std::bad_alloc|"
                                      r"std::[a-z_]+(_error|_argument|_range|exception)|"
                                      r"basic_string|_M_range_check|bad_function_call|"
                                      r"bad_optional_access|bad_variant_access")),
    ("solver library", re.compile(r"(?<!KINSOL said: )\[KINSOL ERROR\]|\[IDA ERROR\]|\[ARKODE ERROR\]|"
                                  r"ERROR RETURN \*\* FROM [SDCZ]MUMPS|On return from [SDCZ]MUMPS|"
                                  r"\bMUMPS\b.*[Ee]rror|UMFPACK|"
                                  r"Intel MKL ERROR|BLAS : Program is Terminated|"
                                  r"\*\* On entry to [A-Z]+")),
    # io/parameters.cc's last resort: an exception that is neither bad
    # input nor a failed run (a deal.II ExceptionBase or std::exception)
    ("uncaught exception (catch-all 'error:')",
     re.compile(r"^(rod_cross_section|strip|plate_rod): error:")),
    ("crash", re.compile(r"Segmentation fault|\bAborted\b|core dumped|double free|"
                         r"corrupted (size|double|top)|malloc\(\)|free\(\): invalid|"
                         r"\*\*\* Process received signal|MPI_ABORT|mpirun has exited|"
                         r"stack smashing|Floating point exception|AddressSanitizer|"
                         r"runtime error:")),
]

EXPR_FUNCTIONS = {"x", "y", "z", "r", "t", "pi", "e", "sqrt", "sin", "cos", "tan", "exp", "log",
                  "ln", "abs", "atan", "asin", "acos", "atan2", "sinh", "cosh", "tanh", "pow",
                  "min", "max", "if", "floor", "ceil", "sign", "rint", "log10", "log2",
                  "theta", "phi"}


def number(token):
    try:
        return float(token)
    except ValueError:
        return None


def looks_like_expression(token):
    """A muparser function of the position: operators and known names only."""
    t = token.strip()
    if not t or number(t) is not None:
        return False
    if "{}" in t:  # a study's Template
        return True
    names = re.findall(r"[A-Za-z_][A-Za-z_0-9]*", t)
    if not names or any(n not in EXPR_FUNCTIONS for n in names):
        return False
    return bool(re.search(r"[-+*/^()<>]", t))


# ---------------------------------------------------------------- prm files


class Prm:
    """A .prm as lines, with the entries' (section path, name, line index)."""

    SET = re.compile(r"^(\s*set\s+)([^=]*?)(\s*=\s*)(.*?)(\s*)$")

    def __init__(self, text):
        self.lines = []
        # join continuation lines (a trailing backslash)
        pending = ""
        for raw in text.splitlines():
            line = pending + raw
            if line.rstrip().endswith("\\"):
                pending = line.rstrip()[:-1] + " "
                continue
            pending = ""
            self.lines.append(line)
        self.entries = []  # (path tuple, name, line index)
        stack = []
        for i, line in enumerate(self.lines):
            body = line.split("#", 1)[0]
            s = body.strip()
            if s.startswith("subsection "):
                stack.append(s[len("subsection "):].strip())
            elif s == "end":
                if stack:
                    stack.pop()
            elif s.startswith("set "):
                m = self.SET.match(body)
                if m:
                    self.entries.append((tuple(stack), m.group(2).strip(), i))

    def copy(self):
        c = Prm.__new__(Prm)
        c.lines = list(self.lines)
        c.entries = list(self.entries)
        return c

    def find(self, path, name):
        found = None
        for p, n, i in self.entries:
            if p == tuple(path) and n == name:
                found = i  # the last one counts
        return found

    def value_at(self, i):
        return self.SET.match(self.lines[i].split("#", 1)[0]).group(4)

    def get(self, path, name):
        i = self.find(path, name)
        return None if i is None else self.value_at(i)

    def set_at(self, i, value):
        m = self.SET.match(self.lines[i].split("#", 1)[0])
        self.lines[i] = m.group(1) + m.group(2) + m.group(3) + value

    def set(self, path, name, value, add=True):
        i = self.find(path, name)
        if i is not None:
            self.set_at(i, value)
        elif add:
            block = ["subsection " + s for s in path] + ["  set %s = %s" % (name, value)] + \
                    ["end"] * len(path)
            start = len(self.lines)
            self.lines += block
            self.entries.append((tuple(path), name, start + len(path)))

    def text(self):
        return "\n".join(self.lines) + "\n"


def components(value):
    """Split a list value into tokens, keeping the separators: [(text, is_sep)]."""
    return [(t, bool(re.fullmatch(r"\s*[,;]\s*", t))) for t in re.split(r"(\s*[,;]\s*)", value) if t != ""]


def replace_component(value, k, new):
    parts = components(value)
    idx = [j for j, (_, sep) in enumerate(parts) if not sep]
    parts[idx[k]] = (new, False)
    return "".join(t for t, _ in parts)


def value_tokens(value):
    return [t for t, sep in components(value) if not sep]


# -------------------------------------------------------------- the shrink


def shrink(app, prm, source_dir, scratch_out):
    """Make an example cheap and write into scratch_out; returns the entries
    (path, name) set here that were not in the example (not mutated)."""
    added = []

    def cap(path, name, limit, add=False):
        v = prm.get(path, name)
        if v is None:
            if add:
                prm.set(path, name, str(limit))
                added.append((tuple(path), name))
            return
        x = number(v)
        if x is not None and x > limit:
            prm.set(path, name, str(limit))

    prm.set(["Output"], "Output directory", scratch_out)
    # relative file names are the repository's
    for p, n, i in list(prm.entries):
        if n in ("Mesh file", "Stiffness file"):
            v = prm.value_at(i).strip()
            if v and not os.path.isabs(v) and os.path.exists(os.path.join(source_dir, v)):
                prm.set_at(i, os.path.join(source_dir, v))
    if app == "plate_rod":
        cap(["Mesh"], "Global refinements", 1, add=True)
        cap(["Arclength continuation"], "Maximum number of steps", 12, add=True)
        cap(["Arclength continuation"], "Maximum number of branches", 2)
    elif app == "strip":
        cap(["Strip"], "Number of cells", 8, add=True)
        cap(["Arclength continuation"], "Maximum number of steps", 12)
        cap(["Arclength continuation"], "Maximum number of branches", 2)
    else:
        cap(["Cross-section"], "Global refinements", 1, add=True)
        cap(["Arclength continuation"], "Maximum number of steps", 12)
        cap(["Arclength continuation"], "Maximum number of branches", 2)
        for rng in ("First range", "Second range"):
            v = prm.get(["Constitutive table"], rng)
            if v is not None:
                t = value_tokens(v)
                if len(t) == 3 and number(t[2]) is not None and number(t[2]) > 3:
                    prm.set(["Constitutive table"], rng, "%s, %s, 3" % (t[0], t[1]))
    # a study: two values
    v = prm.get(["Parameter sweep"], "Values")
    if v is not None and v.strip():
        prm.set(["Parameter sweep"], "Values", ", ".join(value_tokens(v)[:2]))
    v = prm.get(["Parameter sweep"], "Range")
    if v is not None:
        t = value_tokens(v)
        if len(t) == 3 and number(t[2]) is not None and number(t[2]) > 2:
            prm.set(["Parameter sweep"], "Range", "%s, %s, 2" % (t[0], t[1]))
    return added


# ------------------------------------------------------------ the mutants


def expression_entries(print_parameters_text):
    """(path, name) of the entries documented as muparser expressions."""
    out = set()
    stack, comment = [], []
    for line in print_parameters_text.splitlines():
        s = line.strip()
        if s.startswith("#"):
            comment.append(s)
            continue
        body = s.split("#", 1)[0].strip()
        if body.startswith("subsection "):
            stack.append(body[len("subsection "):].strip())
        elif body == "end":
            if stack:
                stack.pop()
        elif body.startswith("set "):
            m = re.match(r"set\s+(.*?)\s*=", body)
            doc = " ".join(comment)
            if m and re.search(r"muparser|expression|function of", doc, re.IGNORECASE):
                out.add((normalize_path(stack), m.group(1)))
        comment = [] if not s.startswith("#") else comment
    return out


def normalize_path(path):
    return tuple(re.sub(r"\s+\d+$", " N", s) for s in path)


class Mutant:
    def __init__(self, app, rel, path, name, k, value, new_value):
        self.app, self.rel, self.path, self.name, self.k = app, rel, path, name, k
        self.value, self.new_value = value, new_value  # the mutation, the entry's new text

    @property
    def entry(self):
        e = "/".join(self.path + (self.name,))
        return e if self.k is None else "%s[%d]" % (e, self.k)

    def key(self):
        return (self.app, self.rel, self.entry, self.value)


def mutants_of(app, rel, base, expr_entries, fixed):
    out = []
    for path, name, i in base.entries:
        if (path, name) in fixed or name == "Output directory":
            continue
        value = base.value_at(i)
        tokens = value_tokens(value)
        is_expr_entry = (normalize_path(path), name) in expr_entries
        for k, tok in enumerate(tokens):
            kk = None if len(tokens) == 1 else k
            x = number(tok.strip())
            seen = {tok.strip()}
            if x is not None:
                for m in NUMERIC_MUTATIONS:
                    if m == "NEG":
                        m = "-" + tok.strip() if x > 0 else "-1"
                    if m in seen or (number(m) is not None and number(m) == x and not math.isnan(number(m))):
                        continue
                    seen.add(m)
                    out.append(Mutant(app, rel, path, name, kk, m, replace_component(value, k, m)))
            if looks_like_expression(tok) or (is_expr_entry and x is not None):
                out.append(Mutant(app, rel, path, name, kk, BAD_EXPRESSION,
                                  replace_component(value, k, BAD_EXPRESSION)))
    return out


# ---------------------------------------------------------------- running


class Runner:
    def __init__(self, args):
        self.args = args
        self.exes = {a: getattr(args, a) for a in APPS}
        self.lock = threading.Lock()
        self.live = set()  # the runs in progress (ended with us on a signal)
        self.stopping = False

    def kill_all(self):
        with self.lock:
            self.stopping = True
            for p in list(self.live):
                try:
                    os.killpg(p.pid, signal.SIGKILL)
                except (ProcessLookupError, PermissionError):
                    pass

    def exe(self, app):
        """The executable; it may be relinked under us: wait for it."""
        deadline = time.time() + self.args.exe_wait
        while True:
            e = self.exes[app]
            if os.path.isfile(e) and os.access(e, os.X_OK):
                return e
            if time.time() > deadline:
                return None
            time.sleep(2)

    def run(self, app, text, scratch, entry_name):
        """Run one parameter file; returns a result dict."""
        os.makedirs(scratch, exist_ok=True)
        prm_file = os.path.join(scratch, "input.prm")
        with open(prm_file, "w") as f:
            f.write(text)
        # TMPDIR: Open MPI's session directory of its own (singletons
        # started together race on a shared one: "A call to mkdir was unable
        # to create the desired directory")
        tmpdir = os.path.join(scratch, "t")
        os.makedirs(tmpdir, exist_ok=True)
        env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", TMPDIR=tmpdir,
                   OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", LC_ALL="C")
        res = {"rc": None, "sent_term": False, "hang": False, "time": 0.0, "launch": None}
        for attempt in range(3):
            exe = self.exe(app)
            if exe is None:
                res["launch"] = "executable %s missing" % self.exes[app]
                return res
            limit = ""
            if self.args.memory_limit_gb > 0:
                limit = "ulimit -v %d 2>/dev/null; " % int(self.args.memory_limit_gb * 1024 * 1024)
            cmd = ["/bin/sh", "-c", limit + 'exec "$0" "$@"', exe, "input.prm"]
            t0 = time.time()
            with open(os.path.join(scratch, "stdout.txt"), "wb") as out, \
                    open(os.path.join(scratch, "stderr.txt"), "wb") as err:
                with self.lock:
                    if self.stopping:
                        res["launch"] = "stopped"
                        return res
                    p = subprocess.Popen(cmd, cwd=scratch, stdout=out, stderr=err, env=env,
                                         stdin=subprocess.DEVNULL, start_new_session=True)
                    self.live.add(p)
                try:
                    rc = p.wait(self.args.timeout)
                except subprocess.TimeoutExpired:
                    res["sent_term"] = True
                    try:
                        p.send_signal(signal.SIGTERM)
                    except ProcessLookupError:
                        pass
                    try:
                        rc = p.wait(self.args.grace)
                    except subprocess.TimeoutExpired:
                        res["hang"] = True
                        try:
                            os.killpg(p.pid, signal.SIGKILL)
                        except ProcessLookupError:
                            pass
                        rc = p.wait()
                # the group's leftovers (a gmsh child), if any
                try:
                    os.killpg(p.pid, signal.SIGKILL)
                except (ProcessLookupError, PermissionError):
                    pass
                with self.lock:
                    self.live.discard(p)
            res["time"] = time.time() - t0
            res["rc"] = rc
            res["stdout"] = read_text(os.path.join(scratch, "stdout.txt"))
            res["stderr"] = read_text(os.path.join(scratch, "stderr.txt"))
            # exec failed (binary replaced while we started it), or MPI could
            # not start (the machine, not the input): try again
            if not res["sent_term"] and attempt < 2 and (
                    (rc in (126, 127) and res["time"] < 5) or
                    "error occurred in MPI_Init" in res["stderr"] or
                    "orte_init failed" in res["stderr"]):
                res["retried"] = res.get("retried", 0) + 1
                time.sleep(3)
                shutil.rmtree(os.path.join(scratch, "out"), ignore_errors=True)
                continue
            break
        return res


def read_text(path, limit=2_000_000):
    try:
        with open(path, "rb") as f:
            return f.read(limit).decode("utf-8", "replace")
    except OSError:
        return ""


def strict_json(path):
    def reject(c):
        raise ValueError("non-standard JSON constant %s" % c)
    with open(path) as f:
        return json.loads(f.read(), parse_constant=reject)


def judge(res, scratch, entry_name, nan_input=False):
    """[(kind, detail)] of the failures of one run, and notes."""
    fails, notes = [], []
    if res.get("launch"):
        return [("launch", res["launch"])], notes
    rc, text = res["rc"], res["stdout"] + "\n" + res["stderr"]
    if res["hang"]:
        fails.append(("hang", "still running %g s after SIGTERM (SIGKILLed)" % res_grace(res)))
    elif rc < 0:
        fails.append(("signal death", "killed by signal %d (%s)" % (-rc, signal_name(-rc))))
    elif rc in (0, 1, 2):
        pass
    elif rc in (130, 143) and res["sent_term"]:
        if rc != 143:
            fails.append(("exit status", "exit %d after SIGTERM (expected 143)" % rc))
    elif rc > 128:
        fails.append(("signal death", "exit %d (signal %s)" % (rc, signal_name(rc - 128))))
    else:
        fails.append(("exit status", "exit %d" % rc))
    names = [entry_name] if isinstance(entry_name, str) else (entry_name or [])
    if rc == 1 and names and not any(n in text for n in names):
        # A consequence refused at another entry (Radius = 1e11 makes the
        # growth 1 + 0.3*x negative at the section's edge; the plate's
        # Thickness/Radius too small) is a clear message too, if it names
        # the file, section and entry it refuses: a note, not a failure.
        other = re.search(r"bad input in '[^']+' in section '[^']+', entry '[^']+'", text)
        if other:
            notes.append("exit 1 names another entry: " + other.group(0))
        else:
            fails.append(("exit 1 without the entry's name", "'%s' not in: %s"
                          % (names[0], " | ".join(l.strip() for l in text.splitlines()
                                                  if l.strip() and not re.match(r"\w+ \d+\.\d+\.\d+: ", l))[:300])))
    if "error occurred in MPI_Init" in res["stderr"] or "orte_init failed" in res["stderr"]:
        fails.append(("MPI_Init failed (3 attempts)", first_lines(res, 2)))
    for kind, pat in FORBIDDEN:
        lines = [l for l in text.splitlines() if pat.search(l)]
        if lines:
            fails.append(("library text: " + kind, "\n".join(lines[:4])))
    # complete files
    out = os.path.join(scratch, "out")
    tmp = []
    summaries = []
    for root, _, files in os.walk(out):
        for f in files:
            if ".tmp" in f:
                tmp.append(os.path.relpath(os.path.join(root, f), scratch))
            if f == "summary.json":
                summaries.append(os.path.join(root, f))
    if tmp:
        fails.append(("temporary files left", ", ".join(sorted(tmp)[:5])))
    top = os.path.join(out, "summary.json")
    want = {0: "converged", 2: "failed", 143: "interrupted", 130: "interrupted"}.get(rc)
    for s in summaries:
        rel = os.path.relpath(s, scratch)
        try:
            j = strict_json(s)
            status = j.get("status") if isinstance(j, dict) else None
        except (ValueError, OSError) as e:
            fails.append(("summary.json invalid", "%s: %s" % (rel, str(e)[:200])))
            continue
        if s == top:
            if want is not None and status != want:
                fails.append(("summary.json status", "%s: status %r with exit %s (expected %r)"
                              % (rel, status, rc, want)))
            elif rc == 1 and status in ("running", "converged"):
                fails.append(("summary.json status", "%s: status %r with exit 1" % (rel, status)))
        elif status == "running" and not res["hang"]:
            fails.append(("summary.json status", "%s: status 'running' after the run ended" % rel))
    # a study (sweep.csv) has a summary.json per value, none of its own
    study = os.path.exists(os.path.join(out, "sweep.csv"))
    if want is not None and not os.path.exists(top) and not study and rc != 130:
        fails.append(("summary.json missing", "exit %s and no out/summary.json" % rc))
    # KINSOL's messages, quoted by the application in a failed step's line
    # (solvers/newton.cc): by design, counted apart
    if "KINSOL said: [KINSOL ERROR]" in text:
        notes.append("KINSOL's message quoted in a step's line")
    if "MUMPS failed in phase" in text:
        notes.append("MUMPS failure (INFOG) in the message")
    if nan_input and rc == 0:
        notes.append("nan accepted (exit 0)")
    if res.get("retried"):
        notes.append("retried (MPI could not start)")
    if res["sent_term"] and not res["hang"]:
        notes.append("timed out, stopped by SIGTERM")
    return fails, notes


def res_grace(res):
    return round(res["time"], 1)


def signal_name(n):
    try:
        return signal.Signals(n).name
    except ValueError:
        return "?"


# ------------------------------------------------------------------- main


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    source_default = os.path.dirname(here)
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--source-dir", default=source_default, help="the repository (parameter_files/)")
    build = os.path.join(source_default, "build")
    for a in APPS:
        ap.add_argument("--" + a.replace("_", "-"), dest=a, default=os.path.join(build, a),
                        help="the %s executable (default build/%s)" % (a, a))
    ap.add_argument("--work", default=None, help="scratch directory (default: a new one in /tmp)")
    ap.add_argument("--seed", type=int, default=37)
    ap.add_argument("--count", type=int, default=100, help="mutants of the sample (default 100)")
    ap.add_argument("--all", action="store_true", help="every mutant (also COSMO_FUZZ_FULL=1)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=40, help="seconds before SIGTERM (default 40)")
    ap.add_argument("--grace", type=float, default=15, help="seconds after SIGTERM before a hang")
    ap.add_argument("--app", choices=APPS, action="append", help="only this application (repeatable)")
    ap.add_argument("--file", help="only example files whose path contains this")
    ap.add_argument("--entry", help="only entries 'Section/Name[k]' containing this")
    ap.add_argument("--value", help="only this mutation value (e.g. nan, 'BAD' for the bad expression)")
    ap.add_argument("--no-base", action="store_true", help="do not run the shrunk examples themselves")
    ap.add_argument("--list", action="store_true", help="list the selected mutants and exit")
    ap.add_argument("--keep", action="store_true", help="keep the scratch directories of passed runs")
    ap.add_argument("--memory-limit-gb", type=float, default=None,
                    help="address-space limit per run (default: physical memory / (jobs + 1); 0: none)")
    ap.add_argument("--exe-wait", type=float, default=300,
                    help="seconds to wait for a missing executable (being rebuilt)")
    ap.add_argument("--json", metavar="FILE", help="write every run's result to FILE")
    ap.add_argument("--only-if-env", metavar="VAR",
                    help="exit 77 (ctest: skipped) unless the environment variable VAR is 1")
    args = ap.parse_args()

    if args.only_if_env and os.environ.get(args.only_if_env, "") not in ("1", "yes", "true", "ON"):
        print("skipped: set %s=1 to run the full fuzz test" % args.only_if_env)
        return 77
    if os.environ.get("COSMO_FUZZ_FULL", "") in ("1", "yes", "true", "ON"):
        args.all = True
    if args.memory_limit_gb is None:
        try:
            phys = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE") / 2**30
            args.memory_limit_gb = max(2.0, phys / (args.jobs + 1))
        except (ValueError, OSError):
            args.memory_limit_gb = 0
    apps = args.app or list(APPS)
    runner = Runner(args)

    # the entries documented as expressions, from --print-parameters
    expr = set()
    for app in apps:
        exe = runner.exe(app) if not args.list else (runner.exes[app] if os.path.exists(runner.exes[app]) else None)
        if exe is None and args.list:
            continue
        if exe is None:
            print("FAIL: no executable %s" % runner.exes[app])
            return 1
        try:
            pp = subprocess.run([exe, "--print-parameters"], capture_output=True, text=True,
                                timeout=60, env=dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                                                     OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")).stdout
        except (subprocess.TimeoutExpired, OSError):
            pp = ""
        expr |= expression_entries(pp)

    work = args.work or os.path.join("/tmp", "cosmo_fuzz_inputs_%d" % os.getpid())
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(work)

    # the shrunk examples and their mutants
    bases, mutants = {}, []
    for app in apps:
        d = os.path.join(args.source_dir, "parameter_files", app)
        files = sorted([os.path.join(app, f) for f in os.listdir(d) if f.endswith(".prm")])
        if os.path.isdir(os.path.join(d, "studies")):
            files += sorted(os.path.join(app, "studies", f)
                            for f in os.listdir(os.path.join(d, "studies")) if f.endswith(".prm"))
        for rel in files:
            if args.file and args.file not in rel:
                continue
            with open(os.path.join(args.source_dir, "parameter_files", rel)) as f:
                base = Prm(f.read())
            added = shrink(app, base, args.source_dir, "@OUT@")
            bases[(app, rel)] = base
            mutants += mutants_of(app, rel, base, expr, set(added))
    total_all = len(mutants)
    if args.entry:
        mutants = [m for m in mutants if args.entry in m.entry]
    if args.value:
        v = BAD_EXPRESSION if args.value == "BAD" else args.value
        mutants = [m for m in mutants if m.value == v]
    filtered = bool(args.entry or args.value or args.file)
    if not args.all and not filtered and args.count < len(mutants):
        # deterministic sample spread over the files: round robin over the
        # files (in an order of the seed), each file's mutants shuffled
        rng = random.Random(args.seed)
        by_file = {}
        for m in mutants:
            by_file.setdefault((m.app, m.rel), []).append(m)
        keys = sorted(by_file)
        rng.shuffle(keys)
        for k in keys:
            rng.shuffle(by_file[k])
        chosen = []
        while len(chosen) < args.count:
            for k in keys:
                if by_file[k] and len(chosen) < args.count:
                    chosen.append(by_file[k].pop())
        mutants = chosen
    mutants.sort(key=lambda m: (APPS.index(m.app), m.rel))

    if args.list:
        for m in mutants:
            print("%-12s %-58s %-44s = %s" % (m.app, m.rel, m.entry, m.value))
        print("%d mutants selected of %d" % (len(mutants), total_all))
        return 0

    jobs = []
    if not args.no_base and not (args.entry or args.value):
        jobs += [("base", app, rel, None) for (app, rel) in sorted(bases, key=lambda k: (APPS.index(k[0]), k[1]))]
    jobs += [("mutant", m.app, m.rel, m) for m in mutants]
    mode = "all" if args.all else ("filtered" if filtered else "sample of seed %d" % args.seed)
    print("fuzz_inputs: %d runs (%d shrunk examples, %d mutants: %s; %d mutants in the full set), "
          "%d jobs, timeout %g s + %g s, memory limit %s"
          % (len(jobs), len(jobs) - len(mutants), len(mutants), mode, total_all, args.jobs,
             args.timeout, args.grace,
             "%.1f GB" % args.memory_limit_gb if args.memory_limit_gb > 0 else "none"), flush=True)

    results = []
    printed = [0]
    start = time.time()

    def task(n, job):
        kind, app, rel, m = job
        scratch = os.path.join(work, "%04d" % n)
        prm = bases[(app, rel)].copy()
        name = None
        if m is not None:
            prm.set(list(m.path), m.name, m.new_value, add=False)
            name = [m.name]
            # a study's values and template go to the swept entry: its
            # name, or the study's 'Entry', names the mutation too
            swept = prm.get(["Parameter sweep"], "Entry")
            if m.path == ("Parameter sweep",) and m.name in ("Values", "Range", "Template") and swept:
                name += ["Entry", swept.strip().split("/")[-1]]
        text = prm.text().replace("@OUT@", os.path.join(scratch, "out"))
        res = runner.run(app, text, scratch, name)
        fails, notes = judge(res, scratch, name,
                             nan_input=(m is not None and m.value == "nan"))
        if m is None and res.get("rc") == 1:
            fails.append(("shrunk example refused", first_lines(res, 3)))
        return n, job, res, fails, notes, scratch

    # SIGTERM/SIGINT (ctest's timeout, ^C): end the runs in progress too
    def stop(signum, frame):
        runner.kill_all()
        print("\nfuzz_inputs: stopped by signal %d" % signum, flush=True)
        os._exit(128 + signum)
    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as ex:
        futures = [ex.submit(task, n, job) for n, job in enumerate(jobs)]
        for fut in concurrent.futures.as_completed(futures):
            n, (kind, app, rel, m), res, fails, notes, scratch = fut.result()
            results.append((n, kind, app, rel, m, res, fails, notes, scratch))
            printed[0] += 1
            verdict = "FAIL(" + "; ".join(sorted(set(k for k, _ in fails))) + ")" if fails else "ok"
            if notes:
                verdict += " [" + "; ".join(notes) + "]"
            what = "(shrunk example)" if m is None else "%s = %s" % (m.entry, m.value)
            rc = res.get("rc")
            print("%4d/%d #%04d %-52s %-50s exit %-4s %6.1f s  %s"
                  % (printed[0], len(jobs), n, rel, what, rc if rc is not None else "-", res["time"], verdict),
                  flush=True)
            for k, d in fails:
                for line in d.splitlines()[:4]:
                    print("          | %s: %s" % (k, line[:200]))
            if fails:
                if m is not None:
                    print("          | reproduce: python3 tests/fuzz_inputs.py --app %s --file %s --entry %s --value %s --keep"
                          % (app, shq(rel), shq(m.entry), shq("BAD" if m.value == BAD_EXPRESSION else m.value)))
                print("          | scratch: %s" % scratch)
            elif not args.keep:
                shutil.rmtree(scratch, ignore_errors=True)

    elapsed = time.time() - start
    results.sort()
    failed = [r for r in results if r[6]]
    by_rc = {}
    for r in results:
        by_rc[r[5].get("rc")] = by_rc.get(r[5].get("rc"), 0) + 1
    print()
    print("summary: %d runs (%d shrunk examples, %d mutants) in %.0f s; %d passed, %d failed"
          % (len(results), len(results) - len(mutants), len(mutants), elapsed,
             len(results) - len(failed), len(failed)))
    print("  exit statuses: " + ", ".join("%s: %d" % (k, v) for k, v in
                                          sorted(by_rc.items(), key=lambda kv: str(kv[0]))))
    slow = sorted(results, key=lambda r: -r[5]["time"])[:3]
    print("  slowest: " + ", ".join("%s %s %.1f s" % (r[3], "base" if r[4] is None else r[4].entry + "=" + r[4].value,
                                                     r[5]["time"]) for r in slow))
    notes = {}
    for r in results:
        for note in r[7]:
            notes.setdefault(note, []).append(r)
    for note, rs in sorted(notes.items()):
        print("  note, %s: %d (%s)" % (note, len(rs), "; ".join(
            "%s %s" % (r[3], "base" if r[4] is None else r[4].entry + "=" + r[4].value) for r in rs[:8])
            + (" ..." if len(rs) > 8 else "")))
    groups = {}
    for r in failed:
        for k, d in r[6]:
            groups.setdefault(k, []).append((r, d))
    for k in sorted(groups):
        print("FAILED, %s: %d" % (k, len(groups[k])))
        for r, d in groups[k]:
            n, kind, app, rel, m, res = r[:6]
            print("  %s %s: %s, exit %s: %s" % (app, rel, "shrunk example" if m is None else
                                                "%s = %s" % (m.entry, m.value), res.get("rc"),
                                                d.splitlines()[0][:160] if d else ""))
    if args.json:
        with open(args.json, "w") as f:
            json.dump([{"job": r[0], "app": r[2], "file": r[3],
                        "entry": None if r[4] is None else r[4].entry,
                        "value": None if r[4] is None else r[4].value,
                        "exit": r[5].get("rc"), "time": round(r[5]["time"], 2),
                        "failures": [{"kind": k, "detail": d} for k, d in r[6]],
                        "notes": r[7], "scratch": r[8],
                        "stderr_tail": res_tail(r[5])} for r in results], f, indent=1)
    return 1 if failed else 0


def res_tail(res, n=6):
    lines = [l for l in res.get("stderr", "").splitlines() if l.strip()]
    return lines[-n:]


def shq(s):
    return "'" + s.replace("'", "'\\''") + "'" if re.search(r"[^A-Za-z0-9_./=-]", s) else s


def first_lines(res, n):
    lines = [l for l in (res["stderr"] + "\n" + res["stdout"]).splitlines() if l.strip()]
    return "\n".join(lines[:n])


if __name__ == "__main__":
    sys.exit(main())
