#!/usr/bin/env python3
"""Compare a regression run's key numbers with the stored reference.

Each line is a list of words. A word 'x~r' is a located critical load x with
its round-off resolution r (summary.json: events.*.location.resolution;
sweep.csv: t_resolution): it must agree within 2 r_ref, the scatter two
machines may show (threads, CPU, inputs perturbed at 1e-14;
doc/theory-continuation.md 4), and r_new must not exceed 4 r_ref (the
tolerance is the reference's: a run that resolves its load worse -- another
location method, a worse-conditioned point -- is a change, not a licence). Other numbers: relative 1e-6 or absolute 1e-9
(states converge to a weighted residual of 1e-10: far below); words that are
not numbers must be equal.
usage: compare_key_numbers.py <reference> <new>
"""
import sys


def parse(word):
    if "~" in word:
        x, r = word.split("~")
        return float(x), float(r)
    try:
        return float(word), None
    except ValueError:
        return word, None


def main(ref_file, new_file):
    ref = [l.split() for l in open(ref_file) if l.strip()]
    new = [l.split() for l in open(new_file) if l.strip()]
    bad = []
    if len(ref) != len(new):
        bad.append("%d lines in the reference, %d now" % (len(ref), len(new)))
    for k, (a, b) in enumerate(zip(ref, new)):
        if len(a) != len(b):
            bad.append("line %d: %r against %r" % (k + 1, " ".join(a), " ".join(b)))
            continue
        for j, (wa, wb) in enumerate(zip(a, b)):
            (xa, ra), (xb, rb) = parse(wa), parse(wb)
            if isinstance(xa, str) or isinstance(xb, str):
                if wa != wb:
                    bad.append("line %d word %d: %r against %r" % (k + 1, j + 1, wa, wb))
                continue
            if ra is not None or rb is not None:
                if ra is None or rb is None or rb > 4 * ra:
                    bad.append("line %d word %d: resolution %s against %s of the reference"
                               % (k + 1, j + 1, rb, ra))
                    continue
                tol = 2 * ra + 1e-14 * abs(xa)
                why = "2 x resolution"
            else:
                tol = max(1e-6 * abs(xa), 1e-9)
                why = "rel 1e-6 / abs 1e-9"
            if not abs(xa - xb) <= tol:
                bad.append("line %d word %d: %.17g against %.17g (|diff| %.3g > %.3g, %s)"
                           % (k + 1, j + 1, xa, xb, abs(xa - xb), tol, why))
    for b in bad:
        print(b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
