#!/usr/bin/env python3
"""Markdown tables from `sepax_bench --json FILE` (used for docs/bench.md).

    python3 bench/bench_tables.py build-bench/bench/bench.json
"""
import json
import sys


def fmt_ns(x):
    if x is None:
        return '–'
    if x >= 1e6:
        return '%.1f ms' % (x / 1e6)
    if x >= 1e3:
        return '%.2f µs' % (x / 1e3)
    return '%.0f ns' % x


def main(path):
    d = json.load(open(path))
    rows = d['rows']
    runs = {(m['workload'], m['poses'], m['row']): m for m in rows}

    print('#### Targets\n')
    print('| target | slower row | faster row | ratio | bound | |')
    print('|---|---|---|---|---|---|')
    for t in d['targets']:
        ratio = t['ratio']
        bound = ('>= ' if t['bound'] == 'at_least' else '<= ') + '%g' % t['value']
        state = 'not measured' if ratio is None else ('met' if t['met'] else '**missed**')
        if t.get('result_differences') is not None:
            state += ' (%d answers differ)' % t['result_differences']
        print('| %s | `%s` | `%s` | %s | %s | %s |' % (t['name'], t['slower'], t['faster'],
                                                     '–' if ratio is None else '%.2f' % ratio, bound, state))

    poses_order = []
    for m in rows:
        if m['poses'] not in poses_order:
            poses_order.append(m['poses'])
    for poses in poses_order:
        workloads, names = [], []
        for m in rows:
            if m['poses'] != poses:
                continue
            if m['workload'] not in workloads:
                workloads.append(m['workload'])
            if m['row'] not in names:
                names.append(m['row'])
        print('\n#### ns/query, %s poses (in parentheses: ratio to `%s`; [k]: timed on the first k pairs)\n'
              % (poses, d.get('baseline', 'traversal float')))
        print('| row | ' + ' | '.join(workloads) + ' |')
        print('|---|' + '---|' * len(workloads))
        full = {w: max(m['queries'] for m in rows if m['poses'] == poses and m['workload'] == w) for w in workloads}
        for r in names:
            cells = []
            for w in workloads:
                m = runs.get((w, poses, r))
                if not m:
                    cells.append('–')
                    continue
                s = fmt_ns(m['ns'])
                if m['ratio_to_traversal'] is not None:
                    s += ' (%.2f)' % m['ratio_to_traversal']
                if m['queries'] < full[w]:
                    s += ' [%d]' % m['queries']
                cells.append(s)
            print('| `%s` | ' % r + ' | '.join(cells) + ' |')

    print('\n#### Decisions left to exact arithmetic per query (robust rows with any)\n')
    keys = []
    for m in rows:
        if m.get('exact_fallbacks_per_query') and (m['poses'], m['row']) not in keys:
            keys.append((m['poses'], m['row']))
    workloads = []
    for m in rows:
        if m['workload'] not in workloads:
            workloads.append(m['workload'])
    print('| poses | row | ' + ' | '.join(workloads) + ' |')
    print('|---|---|' + '---|' * len(workloads))
    for poses, r in keys:
        cells = []
        for w in workloads:
            m = runs.get((w, poses, r))
            cells.append('–' if not m or m.get('exact_fallbacks_per_query') is None
                         else '%.2g' % m['exact_fallbacks_per_query'])
        print('| %s | `%s` | ' % (poses, r) + ' | '.join(cells) + ' |')

    bad = [(m['workload'], m['poses'], m['row'], m['verdict_disagreements'], m['failed'])
           for m in rows if m['verdict_disagreements'] or m['failed']]
    print('\nVerdicts differing from the exact verdict, or failed queries (workload, poses, row, differing, failed): ' +
          (', '.join(str(b) for b in bad) if bad else 'none') + '.')
    worst = {}
    for m in rows:
        if m['group'] == 'sepax' and m['depth_err_max'] is not None and 'mpq' not in m['row']:
            worst[m['row']] = max(worst.get(m['row'], 0), m['depth_err_max'])
    print('\nLargest depth error against the exact depth (sepax rows, all workloads): ' +
          ', '.join('`%s` %.1e' % (r, e) for r, e in worst.items()) + '.')


if __name__ == '__main__':
    main(sys.argv[1] if len(sys.argv) > 1 else 'build-bench/bench/bench.json')
