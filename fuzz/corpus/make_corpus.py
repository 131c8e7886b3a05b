#!/usr/bin/env python3
# Writes the hand-made seed corpus (the degenerate cases that matter, double-
# sided triangles first).  Run from fuzz/corpus/.  Coordinates are float values.
import math, struct

def box(hx, hy, hz, t=(0, 0, 0)):
    v = []
    for i in range(8):
        x = hx if ((i & 1) ^ ((i >> 1) & 1)) else -hx
        y = hy if (i & 2) else -hy
        z = hz if (i & 4) else -hz
        v.append((x + t[0], y + t[1], z + t[2]))
    return v, [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [0, 4, 7, 3], [1, 2, 6, 5]]

def flat(loop):
    fr = list(range(len(loop)))
    return loop, [fr, fr[::-1]]

def sub(a, b): return [a[i] - b[i] for i in range(3)]
def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
def dot(a, b): return sum(a[i]*b[i] for i in range(3))

def tetra(p):
    det = dot(cross(sub(p[1], p[0]), sub(p[2], p[0])), sub(p[3], p[0]))
    f = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
    if det > 0: f = [x[::-1] for x in f]
    return p, f

def prism(n, r, h, t=(0, 0, 0), rot90=False):
    v = []
    for k in range(2):
        for i in range(n):
            a = 2 * math.pi * i / n
            x, y, z = r * math.cos(a), r * math.sin(a), (h if k else -h)
            if rot90: x, y, z = x, -z, y
            v.append((x + t[0], y + t[1], z + t[2]))
    f = [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    f.append([n - 1 - i for i in range(n)])
    f.append([n + i for i in range(n)])
    return v, f

def f32(x): return struct.unpack('f', struct.pack('f', x))[0]

def write(name, desc, A, B, faces_reversed_a=False):
    with open(name, 'w') as o:
        for l in desc.split('\n'): o.write('# ' + l + '\n')
        o.write('sepax-fuzz-case 1\nfamily corpus\nseed 0\n')
        for nm, (v, f) in (('A', A), ('B', B)):
            if nm == 'A' and faces_reversed_a: f = [x[::-1] for x in f]
            o.write('shape %s\n' % nm)
            for p in v: o.write('v %s\n' % ' '.join('%.9g' % f32(c) for c in p))
            for fc in f: o.write('f %s\n' % ' '.join(map(str, fc)))
            o.write('end\n')

write('00-triangle-on-box-face.case', 'A double-sided triangle lying exactly on the top face of a cube (coplanar contact).\nExact: touching (max separation 0); the box face ties with the triangle\'s back face.',
      box(1, 1, 1), flat([(-1, -1, 1), (1, -1, 1), (0, 1, 1)]))
write('01-triangle-inside-box-face-small.case', 'A small double-sided triangle lying on the cube face z = 1, strictly inside the face.',
      box(1, 1, 1), flat([(-0.25, -0.25, 1), (0.5, -0.25, 1), (0, 0.5, 1)]))
write('02-triangle-edge-on-box-edge.case', 'A vertical double-sided triangle whose bottom edge lies exactly on the cube\'s top edge y = 1, z = 1.',
      box(1, 1, 1), flat([(-0.5, 1, 1), (0.5, 1, 1), (0, 1, 2)]))
write('03-triangle-vertex-on-box-face.case', 'A double-sided triangle standing on one vertex at the centre of the cube\'s top face.',
      box(1, 1, 1), flat([(0, 0, 1), (1, 0, 2), (0, 1, 2)]))
write('04-triangle-crossing-triangle.case', 'Two double-sided triangles in perpendicular planes whose edges cross exactly.',
      flat([(-1, -1, 0), (1, -1, 0), (0, 1, 0)]), flat([(0, -0.5, -1), (0, -0.5, 1), (0, 0.5, 0)]))
write('05-coplanar-triangles-overlapping.case', 'Two double-sided triangles in the same plane z = 0, overlapping (parallel edges, opposite normals).',
      flat([(-1, -1, 0), (1, -1, 0), (0, 1, 0)]), flat([(0, -0.5, 0), (2, -0.5, 0), (1, 1.5, 0)]))
write('06-coplanar-triangles-touching.case', 'Two double-sided triangles in one plane sharing an edge segment (touching).',
      flat([(-1, -1, 0), (1, -1, 0), (0, 1, 0)]), flat([(-1, -1, 0), (1, -3, 0), (1, -1, 0)]))
write('07-quad-on-box-face.case', 'A double-sided square lying exactly on the cube face, half off its edge.',
      box(1, 1, 1), flat([(0.5, -0.5, 1), (1.5, -0.5, 1), (1.5, 0.5, 1), (0.5, 0.5, 1)]))
write('08-box-on-box-touching.case', 'Two cubes stacked face on face, exactly touching, offset in x.',
      box(1, 1, 1), box(1, 1, 1, (0.5, 0, 2)))
write('09-box-edge-on-box-edge.case', 'Two boxes touching along parallel edges (many exact zeros and exactly parallel pairs).',
      box(1, 0.5, 0.25), box(0.25, 1, 0.5, (1.25, 0, 0.75)))
write('10-prisms-parallel-edges.case', 'Two 12-sided prisms with parallel axes side by side: many exactly parallel edge pairs.',
      prism(12, 1, 1), prism(12, 1, 1, (1.9, 0.3, 0.5)))
write('11-prism-crossed.case', 'Two 8-sided prisms with perpendicular axes, overlapping.',
      prism(8, 1, 1), prism(8, 0.5, 1.5, (0.3, 0.2, 1.2), rot90=True))
write('12-sliver-tetra.case', 'A sliver tetrahedron (4th point 1e-5 off the plane) against a box.',
      tetra([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0.3, 0.3, 1e-5)]), box(0.5, 0.5, 0.5, (0.25, 0.25, 0.5)))
write('13-far-from-origin.case', 'A box and a tetrahedron 1e4 from the origin, nearly touching.',
      box(1, 1, 1, (10000, 10000, 10000)), tetra([(10001.5, 10000, 10000), (10003, 10001, 10000), (10003, 10000, 10001), (10003, 9999, 9999)]))
write('14-tiny-scale.case', 'Two boxes at scale 1e-4, overlapping slightly.',
      box(1e-4, 1e-4, 1e-4), box(5e-5, 5e-5, 5e-5, (1.4e-4, 0.3e-4, 0)))
write('15-huge-scale.case', 'A box and a triangle at scale 1e4.',
      box(1e4, 1e4, 1e4), flat([(-5e3, -5e3, 1.00001e4), (5e3, -5e3, 1e4), (0, 5e3, 1.2e4)]))
write('invalid-collinear-triangle.case', 'A "triangle" whose vertices are collinear: must be rejected (InvalidInput), never crash.',
      flat([(0, 0, 0), (1, 0, 0), (2, 0, 0)]), box(1, 1, 1))
write('invalid-inward-box.case', 'A box with every face listed clockwise (inward): must be rejected.',
      box(1, 1, 1), box(1, 1, 1, (3, 0, 0)), faces_reversed_a=True)
