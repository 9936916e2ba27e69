#!/usr/bin/env python3
"""Rewrites the rows of README.md's "Where levrt stands" table from a targets run.

Usage: tools/update_readme_targets.py docs/results/targets/targets.csv README.md

The rows are the fastest method and setting per scene and error target (targets.csv), with
"(shaded with `rt`'s loop)" where the sweep (targets_sweep.csv, beside it) says the render used
rt's loop. Only the rows after the table's header change; the prose around it is left alone.
"""
import csv, sys, re
csv_path, readme = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(csv_path)))
sweep = list(csv.DictReader(open(csv_path.replace('targets.csv', 'targets_sweep.csv'))))
names = {'street': 'street (instanced lamps)', 'street_bare': 'street (the same lamps, bare)'}
def speed(x):
    v = float(x)
    return '%.0fx' % v if v >= 100 else ('%.1fx' % v if v >= 10 else '%.2fx' % v)
def fallback(r):
    for s in sweep:
        if s['scene'] == r['scene'] and s['lights'] == r['lights'] and s['method'] == r['method'] and s['tolerance'] == r['tolerance']:
            return s['rt_fallback'] == 'yes'
    return False
def setting(r):
    if r['method'] in ('', 'none'): return 'none'
    t = '%s %s' % (r['method'], r['tolerance']) if r['tolerance'] not in ('', '-') else r['method']
    return t + (" (shaded with `rt`'s loop)" if fallback(r) else '')
by = {}
order = []
for r in rows:
    key = (r['scene'], r['lights'])
    if key not in by: by[key] = {}; order.append(key)
    by[key][r['target'].startswith('max') and 'max' or 'avg'] = r
out = []
for key in order:
    m, a = by[key]['max'], by[key]['avg']
    out.append('| %s | %s | %.1f | %s | %s | %s | %s |' % (names.get(key[0], key[0]), format(int(key[1]), ','), float(m['rt_seconds']), setting(m), speed(m['speedup']) if setting(m) != 'none' else '-', setting(a), speed(a['speedup']) if setting(a) != 'none' else '-'))
text = open(readme).read()
start = text.index('|---|---:|---:|---|---:|---|---:|\n') + len('|---|---:|---:|---|---:|---|---:|\n')
end = text.index('\n\n', start)
text = text[:start] + '\n'.join(out) + text[end:]
open(readme, 'w').write(text)
print('\n'.join(out))
