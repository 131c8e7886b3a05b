#!/usr/bin/env python3
"""Checks a `sepax_bench --json FILE` output: every target names rows that
exist in the same workload and pose set, and its ratio is the slower row's
ns over the faster row's; every row's verdicts agree with the exact reference.

    python3 bench/check_targets.py FILE.json
"""
import json
import math
import sys


def main(path):
    d = json.load(open(path))
    rows = {(m['workload'], m['poses'], m['row']): m for m in d['rows']}
    errors = []
    measured = 0
    for t in d['targets']:
        for key in ('name', 'workload', 'poses', 'slower', 'faster', 'bound', 'value', 'ratio', 'met'):
            if key not in t:
                errors.append('target %r lacks %r' % (t.get('name'), key))
        if t['bound'] not in ('at_least', 'at_most'):
            errors.append('target %r: bound %r' % (t['name'], t['bound']))
        s = rows.get((t['workload'], t['poses'], t['slower']))
        f = rows.get((t['workload'], t['poses'], t['faster']))
        if t['ratio'] is None:
            if s and f:
                errors.append('target %r: both rows measured, ratio null' % t['name'])
            continue
        measured += 1
        if not (s and f):
            errors.append('target %r: ratio without both rows' % t['name'])
            continue
        r = s['ns'] / f['ns']
        if not math.isclose(r, t['ratio'], rel_tol=1e-9):
            errors.append('target %r: ratio %g, rows give %g' % (t['name'], t['ratio'], r))
        ok = r >= t['value'] if t['bound'] == 'at_least' else r <= t['value']
        if t.get('result_differences') not in (None, 0):
            ok = False
        if ok != t['met']:
            errors.append('target %r: met %r, rows give %r' % (t['name'], t['met'], ok))
    for m in d['rows']:
        if m['verdict_disagreements'] or m['failed']:
            errors.append('row %s / %s / %s: %d verdicts differ from the exact ones, %d failed' %
                          (m['workload'], m['poses'], m['row'], m['verdict_disagreements'], m['failed']))
    print('%d rows, %d targets (%d measured)' % (len(d['rows']), len(d['targets']), measured))
    for e in errors:
        print('error: ' + e)
    return 1 if errors or measured == 0 else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1]))
