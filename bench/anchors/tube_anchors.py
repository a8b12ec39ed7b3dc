#!/usr/bin/env python3
"""tube_anchors.py - the genus-1 benchmark pair pipe.off -> pinion.off (12 anchors each).

Both meshes are thick-walled tubes (pipe: plain tube along +y; pinion: 10-tooth gear with a bore,
axis = the normal of its two planar end caps, (0.828, 0.314, -0.465)). Anchors are placed in
cylindrical coordinates about the axis, identically on both:
  cap    = 'top' (end cap at +axis) or 'bottom';  rim = 'outer' (largest radius: for the gear a
  tooth tip) or 'inner' (the bore); angle theta counter-clockwise about +axis, theta = 0 along +x
  for the pipe and at the gear tooth tip closest to +x.
  top/outer at 0,108,216 deg; bottom/outer at 72,180,288; top/inner at 60,180,300;
  bottom/inner at 0,120,240 (outer angles are multiples of 36 deg, so they hit gear tooth tips).
Each anchor is the cap vertex on that rim (radius within 2 % of the extreme) with the nearest angle.
Writes pipe_12.pp and pinion_12.pp next to this script (names like top_outer_108).
Usage: python3 bench/anchors/tube_anchors.py
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
MESHES = os.path.join(HERE, '..', '..', 'third_party', 'cgal-data', 'meshes')
ANGLES = {('top', 'outer'): [0, 108, 216], ('bottom', 'outer'): [72, 180, 288],
          ('top', 'inner'): [60, 180, 300], ('bottom', 'inner'): [0, 120, 240]}


def read_off(path):
    toks = []
    for line in open(path):
        toks.extend(line.split('#', 1)[0].split())
    nv = int(toks[1])
    raw = [tuple(toks[4 + 3 * k:7 + 3 * k]) for k in range(nv)]
    return [tuple(map(float, r)) for r in raw], raw


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def unit(a):
    n = math.sqrt(dot(a, a))
    return [x / n for x in a]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def anchors(name, axis, gear):
    V, raw = read_off(os.path.join(MESHES, name + '.off'))
    axis = unit(axis)
    cen = [sum(v[i] for v in V) / len(V) for i in range(3)]
    t = [dot([v[i] - cen[i] for i in range(3)], axis) for v in V]
    caps = {'top': [i for i in range(len(V)) if t[i] > max(t) - 0.01],
            'bottom': [i for i in range(len(V)) if t[i] < min(t) + 0.01]}

    def radial(i):
        return [V[i][k] - cen[k] - t[i] * axis[k] for k in range(3)]
    if gear:  # theta = 0 at the tooth tip (largest radius) closest to +x
        rmax = max(math.sqrt(dot(radial(i), radial(i))) for i in caps['top'])
        tips = [i for i in caps['top'] if math.sqrt(dot(radial(i), radial(i))) > 0.99 * rmax]
        e1 = unit(radial(max(tips, key=lambda i: dot(unit(radial(i)), [1, 0, 0]))))
    else:
        e1 = [1.0, 0.0, 0.0]
    e2 = cross(axis, e1)

    def rt(i):
        d = radial(i)
        return math.hypot(dot(d, e1), dot(d, e2)), math.degrees(math.atan2(dot(d, e2), dot(d, e1))) % 360
    out = []
    for cap in ('top', 'bottom'):
        r = [rt(i)[0] for i in caps[cap]]
        for rim in ('outer', 'inner'):
            ring = [i for i in caps[cap] if (rt(i)[0] > 0.98 * max(r) if rim == 'outer' else rt(i)[0] < 1.02 * min(r))]
            for a in ANGLES[(cap, rim)]:
                v = min(ring, key=lambda i: (min(abs(rt(i)[1] - a), 360 - abs(rt(i)[1] - a)), i))
                out.append(('%s_%s_%03d' % (cap, rim, a), v))
    out.sort()
    lines = ['<!DOCTYPE PickedPoints>', '<PickedPoints>', ' <DocumentData>',
             '  <DataFileName name="%s.off"/>' % name, '  <templateName name=""/>', ' </DocumentData>']
    for n, v in out:
        lines.append(' <point x="%s" y="%s" z="%s" active="1" name="%s"/>' % (raw[v] + (n,)))
    lines.append('</PickedPoints>')
    with open(os.path.join(HERE, name + '_12.pp'), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('wrote %s_12.pp' % name)


if __name__ == '__main__':
    anchors('pipe', [0, 1, 0], gear=False)
    anchors('pinion', [0.828, 0.314, -0.465], gear=True)
