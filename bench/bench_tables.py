#!/usr/bin/env python3
"""Markdown tables from sepax_bench --json output (used for docs/bench.md).

    python3 bench/bench_tables.py build-bench/bench/bench.json
"""
import json
import sys

W = ['sphere4', 'sphere8', 'sphere16', 'sphere32', 'sphere64', 'sphere128', 'sphere256', 'box', 'cylinder32']


def main(path):
    d = json.load(open(path))
    runs = {(m['workload'], m['poses'], m['row']): m for m in d}
    full = {}
    for m in d:
        full[(m['workload'], m['poses'])] = max(full.get((m['workload'], m['poses']), 0), m['queries'])

    def fmt_ns(x):
        if x >= 1e6:
            return '%.1f ms' % (x / 1e6)
        if x >= 1e3:
            return '%.1f µs' % (x / 1e3)
        return '%.0f ns' % x

    for poses in ['overlapping', 'separated']:
        rows = []
        for m in d:
            if m['poses'] == poses and m['row'] not in rows:
                rows.append(m['row'])
        print('\n#### ns/query, %s poses (in parentheses: ratio to `traversal float`; '
              '[k]: timed on the first k pairs only)\n' % poses)
        print('| row | ' + ' | '.join(W) + ' |')
        print('|---|' + '---|' * len(W))
        for r in rows:
            cells = []
            for w in W:
                m = runs.get((w, poses, r))
                if not m:
                    cells.append('–')
                    continue
                s = fmt_ns(m['ns']) + (' (%.3gx)' % m['ratio_to_traversal'] if m['ratio_to_traversal'] is not None else '')
                if m['queries'] < full[(w, poses)]:
                    s += ' [%d]' % m['queries']
                cells.append(s)
            print('| %s | ' % r + ' | '.join(cells) + ' |')

    print('\n#### Depth error against the exact depth, overlapping poses: median / max\n')
    skip = {'traversal float +pose', 'traversal+manifold float', 'brute double', 'gauss double', 'brute float',
            'gauss float', 'brute float robust', 'gauss float robust'}
    rows = []
    for m in d:
        if m['poses'] == 'overlapping' and m['row'] not in rows and 'mpq' not in m['row'] and m['row'] not in skip:
            rows.append(m['row'])
    print('| row | ' + ' | '.join(W) + ' |')
    print('|---|' + '---|' * len(W))
    for r in rows:
        cells = []
        for w in W:
            m = runs.get((w, 'overlapping', r))
            cells.append('%.1e / %.1e' % (m['depth_err_median'] or 0, m['depth_err_max'] or 0) if m else '–')
        print('| %s | ' % r + ' | '.join(cells) + ' |')

    bad = [(m['workload'], m['poses'], m['row'], m['verdict_disagreements'], m['failed'])
           for m in d if m['verdict_disagreements'] or m['failed']]
    print('\nVerdict disagreements with the exact verdict or failed queries (all rows, workloads, pose sets): ' +
          (str(bad) if bad else 'none') + '.')

    print('\n#### Moving poses\n')
    print('| row | moving16 | moving64 |')
    print('|---|---|---|')
    for r in ['traversal float', 'traversal float early-out', 'traversal float cached', 'traversal float robust',
              'bullet gjk+epa (float)']:
        cells = []
        for w in ['moving16', 'moving64']:
            m = runs.get((w, 'moving', r))
            cells.append(fmt_ns(m['ns']) + (' (%.3gx)' % m['ratio_to_traversal'] if m['ratio_to_traversal'] is not None else '')
                         if m else '–')
        print('| %s | ' % r + ' | '.join(cells) + ' |')


if __name__ == '__main__':
    main(sys.argv[1] if len(sys.argv) > 1 else 'build-bench/bench/bench.json')
