#!/usr/bin/env python3
"""densify.py - derive the dense (70-anchor) benchmark sets from the 25 semantic anchors.

Procedure (deterministic, identical on both meshes of a pair):
  1. Read the mesh (OFF/COFF) and its 25-anchor MeshLab PickPoints file <mesh>_25.pp from this
     folder; every anchor must coincide with a mesh vertex (distance < 1e-6 of the bbox diagonal).
  2. For every triple (A, B, f) of the pair's list below, in order (A or B may also name an anchor
     derived by an earlier triple), compute the shortest path from the vertex
     of anchor A to the vertex of anchor B on the mesh's edge graph (Dijkstra, Euclidean edge
     lengths; neighbours visited in increasing vertex index, heap ties broken by vertex index, so
     the path is unique and reproducible). This edge path is our discrete geodesic.
  3. The new anchor is the path vertex whose arc length from A is nearest to f * (path length)
     (ties: the vertex nearer to A). If that vertex already carries an anchor, the nearest free
     vertex along the same path is taken (searching +1, -1, +2, -2, ... steps from it) and this is
     reported on stdout.
  4. The new anchor is named  <A>~<B>@<percent>  (e.g. left_hip~left_knee@33) - the same name on
     both meshes - and the 25 semantic anchors followed by the 45 derived ones, in list order,
     are written to <mesh>_70.pp with the vertex coordinates copied verbatim from the OFF file.
The triples only chain anchors whose connecting path is unambiguous on a body (along a limb, the
spine, the neck, a flank), so the same fraction lands on the same body part on both meshes.

Usage:  python3 bench/anchors/densify.py [humanoid|quadruped ...]   (default: all pairs)
Needs only the Python 3 standard library. Meshes are read from third_party/cgal-data/meshes/.
"""
import heapq
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, '..', '..'))
MESHES = os.path.join(ROOT, 'third_party', 'cgal-data', 'meshes')

T3 = 1.0 / 3.0
T23 = 2.0 / 3.0

# ---------------------------------------------------------------------------------------------
# The triples (A, B, fraction from A). 45 per pair -> 25 + 45 = 70 anchors.
HUMANOID = [
    # head and neck
    ('head_top', 'nose_tip', 0.5),          # forehead
    ('left_ear', 'nose_tip', 0.5),          # left cheek
    ('right_ear', 'nose_tip', 0.5),         # right cheek
    ('chin', 'chest', 0.5),                 # throat
    ('head_top', 'upper_back', 0.5),        # back of the head / nape
    ('left_ear', 'left_shoulder', 0.5),     # left side of the neck
    ('right_ear', 'right_shoulder', 0.5),   # right side of the neck
    # arms
    ('left_shoulder', 'left_elbow', T3), ('left_shoulder', 'left_elbow', T23),
    ('right_shoulder', 'right_elbow', T3), ('right_shoulder', 'right_elbow', T23),
    ('left_elbow', 'left_wrist', 0.5), ('right_elbow', 'right_wrist', 0.5),
    ('left_wrist', 'left_hand_tip', 0.5), ('right_wrist', 'right_hand_tip', 0.5),
    ('chest', 'left_shoulder', 0.5), ('chest', 'right_shoulder', 0.5),             # collar bones
    ('upper_back', 'left_shoulder', 0.5), ('upper_back', 'right_shoulder', 0.5),   # shoulder blades
    # trunk
    ('chest', 'navel', 0.5),                # upper abdomen
    ('navel', 'crotch', 0.5),               # lower abdomen
    ('upper_back', 'crotch', T3),           # mid back (spine)
    ('upper_back', 'crotch', T23),          # lower back / sacrum
    ('chest', 'left_hip', 0.5), ('chest', 'right_hip', 0.5),            # front of the ribs
    ('upper_back', 'left_hip', 0.5), ('upper_back', 'right_hip', 0.5),  # back of the ribs
    ('left_shoulder', 'left_hip', 0.5), ('right_shoulder', 'right_hip', 0.5),  # sides
    # legs
    ('left_hip', 'left_knee', T3), ('left_hip', 'left_knee', T23),
    ('right_hip', 'right_knee', T3), ('right_hip', 'right_knee', T23),
    ('crotch', 'left_knee', 0.5), ('crotch', 'right_knee', 0.5),        # inner thighs
    ('left_knee', 'left_toe', 0.5), ('right_knee', 'right_toe', 0.5),    # shins
    ('left_heel', 'left_toe', 0.5), ('right_heel', 'right_toe', 0.5),    # feet
    ('left_hip', 'left_heel', 0.5), ('right_hip', 'right_heel', 0.5),    # back-outer side of the knees
    ('left_hip', 'left_heel', 0.8), ('right_hip', 'right_heel', 0.8),    # calves
    ('upper_back~crotch@67', 'left_hip', 0.5),                           # buttocks (chained: from
    ('upper_back~crotch@67', 'right_hip', 0.5),                          # the sacrum point above)
]

QUADRUPED = [
    # head and neck
    ('nose_tip', 'head_top', 0.5),          # bridge of the nose
    ('nose_tip', 'chin', 0.5),              # mouth
    ('nose_tip', 'left_cheek', 0.5), ('nose_tip', 'right_cheek', 0.5),  # muzzle sides
    ('head_top', 'nape', 0.5),              # back of the head
    ('chin', 'neck_bottom', T3), ('chin', 'neck_bottom', T23),          # throat line
    ('nape', 'neck_mid', 0.5), ('neck_mid', 'withers', 0.5),            # crest of the neck
    ('left_cheek', 'left_flank', 0.25), ('left_cheek', 'left_flank', 0.5),    # left side of the neck
    ('right_cheek', 'right_flank', 0.25), ('right_cheek', 'right_flank', 0.5),
    # trunk
    ('withers', 'mid_back', 0.5), ('mid_back', 'rump', 0.5), ('rump', 'tail_base', 0.5),
    ('tail_base', 'tail_tip', T3), ('tail_base', 'tail_tip', T23),
    ('neck_bottom', 'chest', 0.5), ('chest', 'belly', 0.5),
    ('belly', 'tail_base', 0.5),            # groin, between the hind legs
    ('left_flank', 'mid_back', 0.5), ('right_flank', 'mid_back', 0.5),
    ('left_flank', 'belly', 0.5), ('right_flank', 'belly', 0.5),
    ('left_flank', 'tail_base', 0.5), ('right_flank', 'tail_base', 0.5),      # haunches
    ('neck_bottom', 'left_front_knee', 0.5), ('neck_bottom', 'right_front_knee', 0.5),  # breast
    # legs
    ('withers', 'left_front_knee', T3), ('withers', 'left_front_knee', T23),
    ('withers', 'right_front_knee', T3), ('withers', 'right_front_knee', T23),
    ('rump', 'left_hind_knee', T3), ('rump', 'left_hind_knee', T23),
    ('rump', 'right_hind_knee', T3), ('rump', 'right_hind_knee', T23),
    ('left_front_knee', 'left_front_foot', 0.5), ('right_front_knee', 'right_front_foot', 0.5),
    ('left_hind_knee', 'left_hind_foot', 0.5), ('right_hind_knee', 'right_hind_foot', 0.5),
    ('chest', 'left_front_knee', 0.5), ('chest', 'right_front_knee', 0.5),    # inner forearms
    ('belly', 'left_hind_knee', 0.5), ('belly', 'right_hind_knee', 0.5),      # inner thighs
]

PAIRS = {
    'humanoid': (('man', 'homer'), HUMANOID),
    'quadruped': (('camel', 'diplodocus'), QUADRUPED),
}
# ---------------------------------------------------------------------------------------------


def read_off(path):
    """Vertices (floats), their coordinate strings as written in the file, and faces."""
    toks = []
    with open(path) as f:
        for line in f:
            line = line.split('#', 1)[0].split()
            toks.extend(line)
    if not toks[0].endswith('OFF'):
        raise SystemExit('%s: not an OFF file' % path)
    per_vertex = 3 + (4 if toks[0] == 'COFF' else 0)  # COFF: r g b a after x y z
    nv, nf = int(toks[1]), int(toks[2])
    i = 4
    raw, faces = [], []
    for _ in range(nv):
        raw.append(tuple(toks[i:i + 3]))
        i += per_vertex
    for _ in range(nf):
        n = int(toks[i])
        faces.append(tuple(int(t) for t in toks[i + 1:i + 1 + n]))
        i += 1 + n
    return [tuple(float(c) for c in r) for r in raw], raw, faces


def read_pp(path):
    pts = []
    for m in re.finditer(r'<point\s+([^>]*)/>', open(path).read()):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
        pts.append((attrs['name'], (float(attrs['x']), float(attrs['y']), float(attrs['z']))))
    return pts


def write_pp(path, mesh_name, raw, named):
    lines = ['<!DOCTYPE PickedPoints>', '<PickedPoints>', ' <DocumentData>',
             '  <DataFileName name="%s.off"/>' % mesh_name, '  <templateName name=""/>',
             ' </DocumentData>']
    for name, v in named:
        x, y, z = raw[v]
        lines.append(' <point x="%s" y="%s" z="%s" active="1" name="%s"/>' % (x, y, z, name))
    lines.append('</PickedPoints>')
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def neighbours(V, F):
    nb = [dict() for _ in V]
    for f in F:
        for k in range(len(f)):
            a, b = f[k], f[(k + 1) % len(f)]
            d = math.dist(V[a], V[b])
            nb[a][b] = d
            nb[b][a] = d
    return [sorted(n.items()) for n in nb]


def shortest_path(nb, s, t):
    dist = {s: 0.0}
    prev = {}
    heap = [(0.0, s)]
    done = set()
    while heap:
        d, u = heapq.heappop(heap)
        if u in done:
            continue
        done.add(u)
        if u == t:
            break
        for w, l in nb[u]:
            nd = d + l
            if nd < dist.get(w, math.inf):
                dist[w] = nd
                prev[w] = u
                heapq.heappush(heap, (nd, w))
    if t not in done:
        raise SystemExit('no path between vertices %d and %d' % (s, t))
    path = [t]
    while path[-1] != s:
        path.append(prev[path[-1]])
    return path[::-1]


def point_along(V, path, frac):
    cum = [0.0]
    for a, b in zip(path, path[1:]):
        cum.append(cum[-1] + math.dist(V[a], V[b]))
    target = frac * cum[-1]
    return min(range(len(path)), key=lambda k: (abs(cum[k] - target), k))


def snap_anchors(V, pts, path):
    diag = math.dist([min(v[i] for v in V) for i in range(3)], [max(v[i] for v in V) for i in range(3)])
    out = []
    for name, p in pts:
        v = min(range(len(V)), key=lambda i: math.dist(V[i], p))
        if math.dist(V[v], p) > 1e-6 * diag:
            raise SystemExit('%s: anchor %s is not on a vertex' % (path, name))
        out.append((name, v))
    return out


def densify(mesh_name, triples):
    V, raw, F = read_off(os.path.join(MESHES, mesh_name + '.off'))
    src = os.path.join(HERE, mesh_name + '_25.pp')
    named = snap_anchors(V, read_pp(src), src)
    index = dict(named)
    used = set(index.values())
    if len(used) != len(named):
        raise SystemExit('%s: two anchors on one vertex' % src)
    nb = neighbours(V, F)
    for a, b, frac in triples:
        path = shortest_path(nb, index[a], index[b])
        k = point_along(V, path, frac)
        for step in [0] + [s for j in range(1, len(path)) for s in (j, -j)]:
            if 0 <= k + step < len(path) and path[k + step] not in used:
                break
        else:
            raise SystemExit('%s: no free vertex on the path %s -> %s' % (mesh_name, a, b))
        if step:
            print('  %s: %s~%s@%d moved %+d steps along the path (vertex taken)'
                  % (mesh_name, a, b, round(frac * 100), step))
        v = path[k + step]
        used.add(v)
        name = '%s~%s@%d' % (a, b, round(frac * 100))
        named.append((name, v))
        index[name] = v
    out = os.path.join(HERE, mesh_name + '_70.pp')
    write_pp(out, mesh_name, raw, named)
    dmin = min(math.dist(V[p], V[q]) for i, (_, p) in enumerate(named) for _, q in named[i + 1:])
    print('  wrote %s: %d anchors, closest two %.4f apart' % (os.path.relpath(out, ROOT), len(named), dmin))


def main(argv):
    names = argv or sorted(PAIRS)
    for pair in names:
        meshes, triples = PAIRS[pair]
        assert len(triples) == 45, (pair, len(triples))
        assert len({(a, b, round(f * 100)) for a, b, f in triples}) == len(triples), 'duplicate triple'
        assert all(0.0 < f < 1.0 for _, _, f in triples)
        print(pair)
        for m in meshes:
            densify(m, triples)


if __name__ == '__main__':
    main(sys.argv[1:])
