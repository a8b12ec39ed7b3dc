#!/usr/bin/env python3
"""Turn the benchmark's CSV files into gnuplot scripts and bench/README.md.

report.py ROOT OUT            write OUT/plots/*.gp (and the data files they read)
report.py ROOT OUT --readme   print bench/README.md (every number from OUT's CSV files)
"""
import csv, math, os, platform, subprocess, sys

root, out = sys.argv[1], sys.argv[2]
readme = '--readme' in sys.argv
plots = os.path.join(out, 'plots')
os.makedirs(plots, exist_ok=True)

def rows(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))

table = rows(os.path.join(out, 'table.csv'))
scal_a = [r for r in rows(os.path.join(out, 'scaling_anchors', 'scaling.csv')) if r['experiment'] == 'anchors']
scal_s = [r for r in rows(os.path.join(out, 'scaling_size', 'scaling.csv')) if r['experiment'] == 'size']
methods = ['greedy', 'voronoi-E1', 'voronoi-C']
full = rows(os.path.join(out, 'scaling_size', 'full.csv'))
orders = rows(os.path.join(out, 'table_orders.csv'))
sens = rows(os.path.join(out, 'sensitivity.csv'))
regs = rows(os.path.join(out, 'regions.csv'))
flips = rows(os.path.join(out, 'flipping.csv'))
# cbd's defaults and the bench's constants as the binary that ran has them (`cbd_bench defaults`).
defaults = {r['setting']: r['value'] for r in rows(os.path.join(out, 'defaults.csv'))}
if readme and not defaults:
    sys.exit(f"report.py: {os.path.join(out, 'defaults.csv')} is missing: run `cbd_bench defaults {out}` "
             "(bench/run.sh does) so the report names the settings the runs used")
ROUNDS = int(defaults.get('straighten_rounds', '-1'))
B_NODES = defaults.get('min_edge_nodes', '?')
W = float(defaults.get('polish_stretch_weight', 'nan'))
FLIP_C = defaults.get('flip_paths') == '1'           # Voronoi method: path flipping by default
FLIP_G = defaults.get('greedy_flip_paths', '1') == '1'  # greedy: its path flipping by default
# The polish's objective, E_ang x E_L2^W, as the table heads and the text write it.
PRODUCT = 'E_ang × E_L2' + ('²' if W == 2 else f'^{W:g}')

def fit(points):
    """Least-squares exponent k of t = c * x^k over (x, t) with t > 0."""
    pts = [(math.log(x), math.log(t)) for x, t in points if x > 0 and t > 0]
    if len(pts) < 2:
        return float('nan')
    mx = sum(p[0] for p in pts) / len(pts); my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx if sxx > 0 else float('nan')

def write_plots():
    pairs = []
    for r in table:
        if r['pair'] not in pairs:
            pairs.append(r['pair'])
    for metric, label in [('e_ang', 'E_ang'), ('e_l2', 'E_L2'), ('t_layout', 'layout time (s)')]:
        dat = os.path.join(plots, metric + '.dat')
        with open(dat, 'w') as f:
            for p in pairs:
                vals = []
                for m in methods:
                    r = [x for x in table if x['pair'] == p and x['method'] == m]
                    vals.append(r[0][metric] if r and r[0]['status'] == 'ok' else '?')
                f.write(p + ' ' + ' '.join(vals) + '\n')
        with open(os.path.join(plots, metric + '.gp'), 'w') as f:
            f.write(f"""set terminal pngcairo size 900,420 font 'Sans,10'
set output '{os.path.join(plots, metric + '.png')}'
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set datafile missing '?'
set key outside right top noenhanced
set ylabel '{label}'
set xtics rotate by -20
{"set logscale y" if metric == 't_layout' else ""}
plot '{dat}' using 2:xtic(1) title 'greedy (Kraevoy and Sheffer)', '' using 3 title 'Voronoi E1', '' using 4 title 'Voronoi C'
""")
    for name, data, xcol, xlabel in [('scaling_anchors', scal_a, 'anchors', 'anchors'),
                                     ('scaling_size', scal_s, 'vertices', 'vertices')]:
        if not data:
            continue
        for m in ['greedy', 'voronoi-C']:
            with open(os.path.join(plots, f'{name}_{m}.dat'), 'w') as f:
                for r in data:
                    if r['method'] == m and r['status'] == 'ok':
                        f.write(f"{r[xcol]} {r['t_layout']} {r['t_dijkstra']}\n")
        with open(os.path.join(plots, name + '.gp'), 'w') as f:
            f.write(f"""set terminal pngcairo size 700,460 font 'Sans,10'
set output '{os.path.join(plots, name + '.png')}'
set logscale xy
set key top left
set xlabel '{xlabel}'
set ylabel 'seconds'
plot '{os.path.join(plots, name + '_greedy.dat')}' using 1:2 with linespoints title 'greedy layout', \\
     '{os.path.join(plots, name + '_voronoi-C.dat')}' using 1:2 with linespoints title 'Voronoi layout (C)', \\
     '{os.path.join(plots, name + '_voronoi-C.dat')}' using 1:3 with linespoints dt 2 title 'one Dijkstra sweep'
""")

def md_table(traced):
    lines = ['| pair | V src / tgt | anchors | method | E_ang | E_ang (deg) | E_L2 | E_L2 inverse | flipped | composed: E_ang / E_L2 / flipped | layout s | straighten s | total s | peak MB | note |',
             '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|']
    for r in table:
        if r['method'].endswith('-traced') != traced:
            continue
        ok = r['status'] == 'ok'
        f = lambda k, d=3: ('%.*f' % (d, float(r[k]))) if ok else '-'
        lines.append(f"| {r['pair']} | {r['source_vertices']} / {r['target_vertices']} | {r['anchors']} | {r['method']} | "
                     f"{f('e_ang')} | {f('e_ang_deg', 1)} | {f('e_l2')} | {f('e_l2_inverse', 2)} | {r['flipped'] if ok else '-'} | "
                     f"{(f('e_ang_composed') + ' / ' + f('e_l2_composed') + ' / ' + r['flipped_before_untangle']) if ok else '-'} | "
                     f"{float(r['t_layout']):.3f} | {float(r['t_straighten']):.3f} | {float(r['t_total']):.3f} | {float(r['peak_mb']):.0f} | "
                     f"{'' if ok else 'failed: ' + r['error'][:120]} |")
    return '\n'.join(lines)

def md_speedup(suffix=''):
    """Voronoi C against greedy: layout speed-up, and which has the lower E_ang, E_L2 and flip
    count, after untangling and as composed (the base domains and patch maps alone)."""
    lines = ['| pair | anchors | greedy layout s | Voronoi C layout s | speed-up | lower E_ang | lower E_L2 | lower ' + PRODUCT + ' | fewer or as few flipped | lower E_ang, composed | lower E_L2, composed |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    pairs = []
    for r in table:
        if r['pair'] not in pairs:
            pairs.append(r['pair'])
    wins = [0] * 6
    n = 0
    product = lambda r: float(r['e_ang']) * float(r['e_l2']) ** W
    for p in pairs:
        g = [x for x in table if x['pair'] == p and x['method'] == 'greedy' + suffix]
        c = [x for x in table if x['pair'] == p and x['method'] == 'voronoi-C' + suffix]
        if not g or not c:
            continue
        g, c = g[0], c[0]
        if g['status'] != 'ok' or c['status'] != 'ok':
            lines.append(f"| {p} | {c['anchors']} | {g['status']} | {c['status']} | - | - | - | - | - | - | - |")
            continue
        n += 1
        w = [float(c['e_ang']) < float(g['e_ang']), float(c['e_l2']) < float(g['e_l2']),
             product(c) < product(g), int(c['flipped']) <= int(g['flipped']),
             float(c['e_ang_composed']) < float(g['e_ang_composed']), float(c['e_l2_composed']) < float(g['e_l2_composed'])]
        wins = [a + b for a, b in zip(wins, w)]
        yn = lambda b: 'yes' if b else 'no'
        lines.append(f"| {p} | {c['anchors']} | {float(g['t_layout']):.3f} | {float(c['t_layout']):.3f} | "
                     f"{float(g['t_layout']) / max(float(c['t_layout']), 1e-9):.1f}x | " + ' | '.join(yn(b) for b in w) + ' |')
    lines.append("| **pairs where Voronoi C is lower** | | | | | " + ' | '.join(f"{x} of {n}" for x in wins) + " |")
    return '\n'.join(lines)

def span(xs):
    """'lo – hi' of a method's values over runs that differ only in a shared setting."""
    return f'{min(xs):.3f} – {max(xs):.3f}'

def md_orders():
    """Greedy against Voronoi C over the polish's vertex orders: the range of each method's final
    E_ang and E_L2, and whether Voronoi C is lower in every order (its worst below greedy's best),
    in none (its best above greedy's worst), or in some (the ranges overlap)."""
    pairs = []
    for r in orders:
        if r['pair'] not in pairs:
            pairs.append(r['pair'])
    n_orders = max([int(r['order_seed']) for r in orders] + [-1]) + 1
    if n_orders < 2:
        return '(one polish order only: run `bench/run.sh` without `--quick`)'
    lines = ['| pair | greedy E_ang | Voronoi C E_ang | Voronoi C lower E_ang | greedy E_L2 | Voronoi C E_L2 | Voronoi C lower E_L2 |',
             '|---|---|---|---|---|---|---|']
    tally = {'e_ang': [0, 0, 0], 'e_l2': [0, 0, 0]}
    for p in pairs:
        runs = {m: [r for r in orders if r['pair'] == p and r['method'] == m] for m in ('greedy', 'voronoi-C')}
        if any(r['status'] != 'ok' for rs in runs.values() for r in rs) or not all(runs.values()):
            lines.append(f"| {p} | failed run(s) | | | | | |")
            continue
        cells = []
        for k in ('e_ang', 'e_l2'):
            g = [float(r[k]) for r in runs['greedy']]
            c = [float(r[k]) for r in runs['voronoi-C']]
            verdict = 0 if max(c) < min(g) else 2 if min(c) > max(g) else 1
            tally[k][verdict] += 1
            cells += [span(g), span(c),
                      ['in every order', 'in some orders', 'in no order'][verdict]]
        lines.append(f"| {p} | " + ' | '.join(cells) + ' |')
    t = lambda k: f"every order {tally[k][0]}, some {tally[k][1]}, none {tally[k][2]}"
    lines.append(f"| **pairs** | | | {t('e_ang')} | | | {t('e_l2')} |")
    return f'{n_orders} polish orders per method and pair (the index order of the table above, then ' \
           f'{n_orders - 1} seeded permutations).\n\n' + '\n'.join(lines)

def md_renumber():
    """Each pair and method run on the source as given and renumbered (bench/renumber.sh): how far
    the images of the source's vertices moved, and both runs' metrics, per map stage."""
    stages = [('composed', 'composed (the map before its last stage)'), ('untangle', 'untangle (the default)'),
              ('optimize', 'optimize')]
    got = {}
    for name, _ in stages[1:]:
        for r in rows(os.path.join(out, f'renumber_{name}.csv')):
            got[(r['pair'], r['method'], r['map'])] = r
    if not got:
        return '(not run: `bench/renumber.sh`, which `bench/run.sh` runs without `--quick`)'
    pairs = []
    for (p, _, _) in got:
        if p not in pairs:
            pairs.append(p)
    lines = ['| pair | method | map | largest / median move | E_ang: as given / renumbered | E_L2 | flipped |',
             '|---|---|---|---|---|---|---|']
    for p in pairs:
        for m in ('voronoi', 'greedy'):
            for k, label in stages:
                r = got.get((p, m, k))
                if r:
                    lines.append(f"| {p} | {m} | {label} | {float(r['max_moved']):.1e} / {float(r['median_moved']):.1e} | "
                                 f"{float(r['e_ang']):.4f} / {float(r['e_ang_renumbered']):.4f} | "
                                 f"{float(r['e_l2']):.4f} / {float(r['e_l2_renumbered']):.4f} | "
                                 f"{r['flipped']} / {r['flipped_renumbered']} |")
    ran = {k: {p for (p, _, m) in got if m == k} for k, _ in stages[1:]}
    note = ''
    if ran['optimize'] and ran['optimize'] != ran['untangle']:
        note = (f"\n\nThe optimize stage ran on {len(ran['optimize'])} of the {len(ran['untangle'])} pairs "
                f"(`PAIRS=\"{' '.join(p for p in pairs if p in ran['optimize'])}\" bench/renumber.sh -- --map-stage optimize`).")
    return '\n'.join(lines) + note

def md_sensitivity():
    """Greedy against Voronoi C over the rounds of path straightening: the default (ROUNDS) and the
    paths as traced (0) from table.csv, the other rounds from sensitivity.csv; per pair, each
    method's range of the final E_ang and E_L2, and at how many settings Voronoi C is the lower,
    in the final map and as composed (before untangling)."""
    if not sens:
        return '(not in this run: `bench/run.sh` without `--quick` runs it)'
    runs = {}
    for r in table:
        k = {'greedy': ROUNDS, 'voronoi-C': ROUNDS, 'greedy-traced': 0, 'voronoi-C-traced': 0}.get(r['method'])
        if k is not None:
            runs.setdefault(r['pair'], {}).setdefault(k, {})[r['method'].replace('-traced', '')] = r
    for r in sens:
        runs.setdefault(r['pair'], {}).setdefault(int(r['straighten_rounds']), {})[r['method']] = r
    settings = sorted({k for p in runs.values() for k in p})
    lines = ['| pair | greedy E_ang | Voronoi C E_ang | Voronoi C lower E_ang | greedy E_L2 | Voronoi C E_L2 | Voronoi C lower E_L2 | Voronoi C lower in both | Voronoi C lower, composed: E_ang / E_L2 | flipped (greedy / C, worst) |',
             '|---|---|---|---|---|---|---|---|---|---|']
    keys = ('e_ang', 'e_l2', 'both', 'e_ang_composed', 'e_l2_composed')
    every = dict.fromkeys(keys, 0)  # pairs where Voronoi C is lower at every setting
    n_pairs = 0
    for p, by in runs.items():
        ks = [k for k in settings if k in by and len(by[k]) == 2]
        if not ks:
            continue
        if any(by[k][m]['status'] != 'ok' for k in ks for m in by[k]):
            lines.append(f"| {p} | failed run(s) | | | | | | | | |")
            continue
        n_pairs += 1
        def lower_at(k, key):
            if key == 'both':
                return lower_at(k, 'e_ang') and lower_at(k, 'e_l2')
            return float(by[k]['voronoi-C'][key]) < float(by[k]['greedy'][key])
        counts = {key: sum(lower_at(k, key) for k in ks) for key in keys}
        for key in keys:
            every[key] += counts[key] == len(ks)
        cells = []
        for key in ('e_ang', 'e_l2'):
            g = [float(by[k]['greedy'][key]) for k in ks]
            c = [float(by[k]['voronoi-C'][key]) for k in ks]
            cells += [span(g), span(c), f'{counts[key]} of {len(ks)}']
        cells += [f"{counts['both']} of {len(ks)}", f"{counts['e_ang_composed']} / {counts['e_l2_composed']} of {len(ks)}"]
        worst = lambda m: max(int(by[k][m]['flipped']) for k in ks)
        lines.append(f"| {p} | " + ' | '.join(cells) + f" | {worst('greedy')} / {worst('voronoi-C')} |")
    lines.append(f"| **pairs where Voronoi C is lower at every setting** | | | {every['e_ang']} of {n_pairs} | | | "
                 f"{every['e_l2']} of {n_pairs} | {every['both']} of {n_pairs} | "
                 f"{every['e_ang_composed']} / {every['e_l2_composed']} of {n_pairs} | |")
    return f"Rounds of straightening: {', '.join(str(k) for k in settings)} ({ROUNDS} is cbd's default, 0 the paths as traced).\n\n" + '\n'.join(lines)

def md_regions():
    """Per pair and metric, greedy's and Voronoi C's final value as the sum of the source regions'
    shares (regions.csv: faces by nearest anchor), the difference, and the three regions where
    Voronoi C's share exceeds greedy's most and the three where it falls short most, each with
    the same difference as composed (before untangling). The sums are checked against
    table.csv's default runs: a regions.csv from other code is not shown."""
    if not regs:
        return '(not in this run: `bench/run.sh` without `--quick` runs it)'
    by = {}
    for r in regs:
        by.setdefault(r['pair'], []).append(r)
    final = {(r['pair'], r['method']): r for r in table}
    lines = ['| pair | metric | greedy | Voronoi C | C − greedy (composed) | where C is higher most (composed) | where C is lower most (composed) |',
             '|---|---|---|---|---|---|---|']
    for p, rs in by.items():
        for metric, key, col in (('E_ang', 'e_ang', 'e_ang'), ('E_L2²', 'e_l2sq', 'e_l2')):
            def total(m, stage=''):
                return sum(float(r[f'{key}_{m}{stage}']) for r in rs)
            for m, tm in (('greedy', 'greedy'), ('voronoi_c', 'voronoi-C')):
                t = final.get((p, tm))
                for stage, tcol in (('', col), ('_composed', col + '_composed')):
                    ref = float(t[tcol]) ** (2 if col == 'e_l2' else 1) if t and t['status'] == 'ok' else None
                    if ref is None or abs(total(m, stage) - ref) > 1e-4 * max(1.0, ref):
                        return f'(regions.csv does not add up to table.csv for {p} {tm}: not from the same code; re-run both)'
            diff = lambda r, stage='': float(r[f'{key}_voronoi_c{stage}']) - float(r[f'{key}_greedy{stage}'])
            d = sorted(rs, key=diff)
            fmt = lambda xs: ', '.join(f"{r['name']} {diff(r):+.4f} ({diff(r, '_composed'):+.4f})" for r in xs)
            g, c = total('greedy'), total('voronoi_c')
            dc = total('voronoi_c', '_composed') - total('greedy', '_composed')
            lines.append(f'| {p} | {metric} | {g:.4f} | {c:.4f} | {c - g:+.4f} ({dc:+.4f}) | {fmt(d[::-1][:3])} | {fmt(d[:3])} |')
    return '\n'.join(lines)

def md_flipping():
    """Greedy without and with its path flipping, Voronoi C without (cbd's default) and with it
    (flipping.csv); per pair the final E_ang / E_L2 of each, and whether Voronoi C is lower than
    greedy (both at cbd's defaults, then both flipped). The default runs must equal table.csv's
    (the same code, deterministic): a flipping.csv from other code is not shown."""
    if not flips:
        return '(not in this run: `bench/run.sh` without `--quick` runs it)'
    final = {(r['pair'], r['method']): r for r in table}
    by = {}
    for r in flips:
        by.setdefault(r['pair'], {})[(r['method'], r['flip_paths'] == '1')] = r
    dflt = lambda on: ' (default)' if on else ''
    lines = [f'| pair | greedy, no flipping{dflt(not FLIP_G)} | greedy, flipping{dflt(FLIP_G)} | Voronoi C, no flipping{dflt(not FLIP_C)} | '
             f'Voronoi C, flipping{dflt(FLIP_C)} | Voronoi C lower in both, defaults | Voronoi C lower in both, both flipping |',
             '|---|---|---|---|---|---|---|']
    both = {'defaults': 0, 'flipped': 0}
    n = 0
    for p, rs in by.items():
        keys = [('greedy', False), ('greedy', True), ('voronoi-C', False), ('voronoi-C', True)]
        if any(k not in rs for k in keys):
            continue
        for m, default in (('greedy', FLIP_G), ('voronoi-C', FLIP_C)):
            t, f = final.get((p, m)), rs[(m, default)]
            if not t or t['status'] != f['status'] or (t['status'] == 'ok' and any(
                    abs(float(t[c]) - float(f[c])) > 1e-9 * max(1.0, abs(float(t[c]))) for c in ('e_ang', 'e_l2'))):
                return f'(flipping.csv differs from table.csv for {p} {m} at cbd\'s defaults: not from the same code; re-run both)'
        cell = lambda r: f"{float(r['e_ang']):.3f} / {float(r['e_l2']):.3f}" if r['status'] == 'ok' else 'failed'
        def lower(c, g):
            ok = c['status'] == 'ok' and g['status'] == 'ok'
            return ok and float(c['e_ang']) < float(g['e_ang']) and float(c['e_l2']) < float(g['e_l2'])
        d = lower(rs[('voronoi-C', FLIP_C)], rs[('greedy', FLIP_G)])
        f = lower(rs[('voronoi-C', True)], rs[('greedy', True)])
        both['defaults'] += d; both['flipped'] += f; n += 1
        lines.append(f"| {p} | " + ' | '.join(cell(rs[k]) for k in keys) + f" | {'yes' if d else 'no'} | {'yes' if f else 'no'} |")
    lines.append(f"| **pairs** | | | | | {both['defaults']} of {n} | {both['flipped']} of {n} |")
    return 'E_ang / E_L2 of the final map, all else as cbd\'s defaults.\n\n' + '\n'.join(lines)

def md_scaling(data, xcol):
    if not data:
        return '(not run)'
    lines = [f'| {xcol} | method | layout s | Voronoi stage s | one Dijkstra sweep s | layout / sweep | peak MB |', '|---|---|---|---|---|---|---|']
    for r in data:
        if r['status'] != 'ok':
            lines.append(f"| {r[xcol]} | {r['method']} | failed | | | | |")
            continue
        t, d = float(r['t_layout']), float(r['t_dijkstra'])
        lines.append(f"| {r[xcol]} | {r['method']} | {t:.3f} | {float(r['t_voronoi']):.3f} | {d:.3f} | {t / d if d > 0 else float('nan'):.1f} | {float(r['peak_mb']):.0f} |")
    ex = []
    for m in ['greedy', 'voronoi-C']:
        k = fit([(float(r[xcol]), float(r['t_layout'])) for r in data if r['method'] == m and r['status'] == 'ok'])
        ex.append(f'{m}: t ~ {xcol}^{k:.2f}')
    return '\n'.join(lines) + '\n\nFitted exponents (least squares on log-log): ' + '; '.join(ex) + '.'

def md_full():
    if not full:
        return '(not run)'
    lines = ['| vertices | anchors | method | E_ang | E_L2 | flipped (before untangling) | layout s | total s | peak MB |', '|---|---|---|---|---|---|---|---|---|']
    for r in full:
        if r['status'] != 'ok':
            lines.append(f"| {r['vertices']} | {r['anchors']} | {r['method']} | failed: {r['error']} | | | | | |")
            continue
        lines.append(f"| {r['vertices']} | {r['anchors']} | {r['method']} | {float(r['e_ang']):.4f} | {float(r['e_l2']):.4f} | "
                     f"{r['flipped']} ({r['flipped_before_untangle']}) | {float(r['t_layout']):.1f} | {float(r['t_total']):.1f} | {float(r['peak_mb']):.0f} |")
    return '\n'.join(lines)

def machine():
    cpu = 'unknown CPU'
    try:
        for line in open('/proc/cpuinfo'):
            if line.startswith('model name'):
                cpu = line.split(':', 1)[1].strip(); break
    except OSError:
        pass
    mem = ''
    try:
        for line in open('/proc/meminfo'):
            if line.startswith('MemTotal'):
                mem = '%.0f GiB' % (int(line.split()[1]) / 1048576); break
    except OSError:
        pass
    return f'{cpu}, {os.cpu_count()} cores, {mem}, {platform.platform()}'

if not readme:
    write_plots()
    sys.exit(0)

# Facts of this run the text names, from its data rather than by hand.
shrec = [r for r in table if r['pair'].startswith('shrec')]
shrec_note = (f"SHREC'07 381 -> 382 with its {shrec[0]['anchors']} landmarks (from "
              "`../shared/data/shrec07-fourleg`, which this run had)" if shrec else
              "SHREC'07 381 -> 382 with its landmarks when `../shared/data/shrec07-fourleg` is present "
              "(absent in this run)")
one = lambda xs: xs.pop() if len(xs) == 1 else ' / '.join(sorted(xs, key=int))
anchors_mesh_vertices = one({r['vertices'] for r in scal_a}) if scal_a else '?'
size_anchors = one({r['anchors'] for r in scal_s}) if scal_s else defaults.get('size_sweep_anchors', '?')
stress_rows = rows(os.path.join(out, 'stress.csv'))
crashed = sum('crashed' in r['message'] for r in stress_rows)
stress_end = ('every other run ended with a typed error (none crashed; each runs in its own process)'
              if crashed == 0 else f'{crashed} runs crashed (stress.csv: "the run crashed"), the others ended with a typed error')
stress_md = open(os.path.join(out, 'stress.md')).read() if os.path.exists(os.path.join(out, 'stress.md')) else '(not run)'
print(f"""# Benchmark

Every number below comes from the CSV files of `bench/run.sh` on this machine ({machine()}),
turned into this page by `bench/report.py`; each section is one `cbd_bench` command of the
script and can be re-run alone. Reproduce everything from scratch with

```sh
bash bench/run.sh
```

(`--quick` for fewer scaling points and stress sets, one polish order, and none of the
straightening sensitivity, the regions, the path flipping and the renumbering). Inputs: `bench/manifest.txt` (real pairs
only: the bundled cow/bull in both directions, {shrec_note}, and pairs of Debian libcgal-demo meshes with the anchors in
`bench/anchors/`). Every method runs on the same input in the same invocation; each run is a
forked child process, so its peak resident memory (`getrusage`) is its own. Methods: **greedy**
= Kraevoy & Sheffer 2004 as described by the paper (all-pairs shortest paths, trial and error,
completion, path flipping), **Voronoi E1** = the paper's method with one edge node per edge,
**Voronoi C** = with adaptive edge nodes (b = {B_NODES}). All use the same edge-node graph, tracer and
build flags; the greedy method's cost is its all-pairs searches over the whole surfaces and its
trial and error. All three have their layouts' paths straightened inside their patches
(cbd's default, `--straighten {ROUNDS}`, the same for every method: `core/include/cbd/path_straightening.h`)
before the patch maps are computed; **greedy-traced** and **Voronoi-C-traced** are the same runs
with the paths as traced (`--straighten 0`), the paper's protocol, where only the map is
post-processed.

## Table 2: distortion and time (cbd's defaults)

{md_table(False)}

Layout = Voronoi clusters + source layout + target layout (greedy: all-pairs paths + trial and
error + completion + flipping, both surfaces); straightening is timed apart. Total adds the
straightening, the patch parameterizations, the composition, the untangling of M_st and M_ts,
and the metrics. Flipped counts M_st's triangles facing against the target surface after
untangling (the same untangling for every method, `core/include/cbd/map_untangle.h`), whose
last stage polishes the whole map: it moves vertices across patch boundaries towards a local
minimum of {PRODUCT}, so the final numbers keep the base domain only as a starting point.
"Composed" is the map before untangling: what the base domains and their patch maps give by
themselves. E_L2 is Sander et al.'s L2 stretch normalised so that 1 is
optimal (Sander et al. 2001); E_ang is the area-weighted (σ1/σ2 + σ2/σ1)/2 − 1 (0 optimal).

![E_ang](results/plots/e_ang.png) ![E_L2](results/plots/e_l2.png)
![layout time](results/plots/t_layout.png)

## Speed-up and distortion, measured side by side

{md_speedup()}

{PRODUCT} is the objective the untangling's polish lowers on every map (the same for both
methods, `map_untangle.h`); where one method is lower in that product but not in both metrics,
the two maps sit at different trade-offs between angle and stretch rather than one being worse
in both.

## How far the polish's vertex order moves the final numbers

The polish at the end of the untangling (`map_untangle.h`) is a local descent that visits the
vertices one at a time; where it ends depends on the order it visits them in. The same runs of
greedy and Voronoi C, with the vertices visited in seeded random orders
(`MapUntangleOptions::polishOrderSeed`), show how much of a difference between the methods is
that order alone:

{md_orders()}

"In every order": Voronoi C's worst result is below greedy's best, so the difference is the
methods' and not the order's; "in no order": the reverse. Both methods get the same
straightening, patch maps, untangling and polish; the polish moves vertices across patch
boundaries, so a base domain decides the final map only through where the descent starts. The
"composed" columns above (before untangling) are what the base domains and patch maps give by
themselves.

## How far the source's vertex numbering moves the map

The same pairs with the source's vertices and faces renumbered (a seeded shuffle; the mesh and
its anchors are otherwise the same), run by `bench/renumber.sh` through `cbd map`. A move is the
distance between a source vertex's images in the two runs, as a fraction of the target's
bounding-box diagonal. The composed map moves only where rounding that differs with the
numbering tips one of the layouts' or the straightening's discrete choices (where a path runs,
whether it snaps onto a vertex); the map stages after it end at other local minima, and the
polish visits the vertices in index order, so their numbers move more than the composed map's.
Moves and metrics only: no timings.

{md_renumber()}

## How far the straightening moves the final numbers

Both methods' paths are straightened inside their patches before the patch maps are computed
(`--straighten`, the same rounds for both); each round moves every path, and with it where the
untangling and polish start. The same pairs with other numbers of rounds
(`cbd_bench sensitivity`), each run in its own process:

{md_sensitivity()}

Where the two methods' ranges overlap, a difference between them at cbd's default (the table at
the top) is no larger than what a setting both methods share moves. The composed columns compare
the base domains and patch maps alone, before any untangling.

## Where on the source the two methods' maps differ

E_ang and E_L2² are sums over the source's faces (E_ang: source area × angle distortion over
the total area; E_L2²: image area × (σ1² + σ2²)/2, normalised). `cbd_bench regions` runs greedy
and Voronoi C once more with cbd's defaults, in one process so that every face's share is at
hand, and sums the shares per region of the source: the faces geodesically nearest to each
anchor (the same regions for both methods); in brackets, the same for the composed map of those
runs (before untangling: the base domains and patch maps alone). The regions' sums are the
table's metrics (checked here), so a difference between the methods splits into where it comes
from, and whether it was there before the untangling:

{md_regions()}

## What path flipping does for each method

The greedy method ends with Kraevoy & Sheffer's path flipping (an edge replaced by the other
diagonal of its two patches when that is shorter on both surfaces together), which the paper
grants it for fairness; the Voronoi method's edges come from the dual of the anchors' Voronoi
diagram{' and are flipped too by default' if FLIP_C else ' and are not flipped by default'}. `cbd_bench flipping` runs greedy without its flipping
and Voronoi C with the same flipping (`--flip-paths`, `flipLayoutPaths` in
`core/include/cbd/greedy_layout.h`, the same code), each run in its own process:

{md_flipping()}

## The same with the paths as traced (the paper's protocol)

{md_table(True)}

{md_speedup('-traced')}

## Scaling with the number of anchors (diplodocus, {anchors_mesh_vertices} vertices, onto a turned copy of itself)

{md_scaling(scal_a, 'anchors')}

![scaling with anchors](results/plots/scaling_anchors.png)

## Scaling with mesh size (the cow, 1-to-4 subdivided, {size_anchors} anchors, onto a turned copy of itself)

{md_scaling(scal_s, 'vertices')}

![scaling with size](results/plots/scaling_size.png)

Each mesh is paired with a copy of itself turned a quarter about z (coordinates swapped, so
every length is the same to the last bit): the same surface, but not the same input, so the
Voronoi method traces its target layout (for an input paired with itself it takes the source's).
"one Dijkstra sweep" is a single-source search over the whole edge-node graph (vertices plus
adaptive edge nodes), the paper's lower bound for a layout; "layout / sweep" is the ratio.
Memory goes to the refined half-edge meshes, the edge-node table and the Dijkstra scratch
arrays (per node: distance, parent, stamps), all linear in the mesh size.

The whole pipeline (`cbd map`'s defaults: layouts, straightening, patch parameterizations,
untangling and polish of both maps, metrics) at the largest size, each method in its own
process:

{md_full()}

Beyond the layouts, memory goes to the two patch parameterizations (a sparse LU factorisation
of the mean-value system per patch, one per worker thread at a time), the two maps with their
point location on the other surface, and the untangling's per-vertex stars.

## Random-anchor stress (synthetic pairs with known deformations)

{stress_md}

Each row: anchor sets of that size drawn uniformly at random or by farthest-point sampling from
a random seed, transferred to the deformed target through the known correspondence; "ok" means
the run finished with both layouts valid and isomorphic and every image on the target surface;
{stress_end}.

## Renders

Base domains on the cow (target of bull -> cow) and M_st coloured by stretch:

![Voronoi](results/plots/layout_voronoi.png)
![greedy](results/plots/layout_greedy.png)
""")
