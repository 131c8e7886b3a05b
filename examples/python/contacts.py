"""sepax from Python: a box dropped onto a slab, queried step by step and then as one batch.

Run with the built module on the path:
    PYTHONPATH=build/python/module python3 examples/python/contacts.py
"""

import time

import numpy as np

import sepax

slab = sepax.box(2.0, 2.0, 0.25)  # prepared once per shape
crate = sepax.convex_hull(np.array([[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]))
print(slab, crate)

# One pose per step: the crate falls, turning slowly about z, and sinks 1 cm into the slab.
steps = 8
heights = np.linspace(1.2, 0.74, steps)
poses = np.stack([sepax.pose([0.1, -0.2, z], [1.0, 0.0, 0.0, 0.05 * i]) for i, z in enumerate(heights)])

cache = sepax.Cache()  # one per pair, kept from step to step
print("\nstep  height  overlap  separation  feature          contacts (depth, id)")
for i, p in enumerate(poses):
    r = sepax.query(slab, crate, None, p, margin=0.02, early_out=True, cache=cache)
    contacts = "" if r.manifold is None else ", ".join(
        f"{d:.4f} {name}" for d, name in zip(r.manifold.depths, r.manifold.id_names))
    print(f"{i:4d}  {heights[i]:6.3f}  {str(r.overlap):7s}  {r.separation:10.6f}  {r.feature!r:15s}  {contacts}")
print(f"cache: {cache.hits} hits, {cache.misses} misses")

# The last pose exactly: GMP rationals decide, the separation comes back as fractions.
r = sepax.query(slab, crate, None, poses[-1], number="exact")
num, norm2 = r.separation_exact
print(f"\nexact at the last step: separation = {num} / sqrt({norm2}) ~ {r.separation:.17g}")

# Many pose pairs in one call: arrays in, arrays out, the GIL released for the whole batch.
rng = np.random.default_rng(1)
k = 20000
q = rng.normal(size=(k, 4))
t = rng.uniform(-2.5, 2.5, size=(k, 3))
many = np.stack([sepax.pose(t[i], q[i]) for i in range(k)])
t0 = time.perf_counter()
b = sepax.query_batch(slab, crate, None, many)
t1 = time.perf_counter()
loop = [sepax.query(slab, crate, None, many[i], manifold=False).separation for i in range(2000)]
t2 = time.perf_counter()
assert np.array_equal(b.separation[:2000], loop)
print(f"\nbatch: {k} queries, {b.overlap.sum()} overlapping, {1e6 * (t1 - t0) / k:.2f} us per query; "
      f"loop of query(): {1e6 * (t2 - t1) / 2000:.2f} us per call")
