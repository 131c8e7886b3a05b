"""Audit a double-sided triangle lying on a box's top face: the Minkowski-face sign table, decided in plain
double, by the robust policy and exactly.

    PYTHONPATH=build/python/module python3 examples/python/audit_triangle.py
"""

import numpy as np

import sepax

box = sepax.box(1.0, 1.0, 0.5)
triangle = sepax.polygon([[0.0, 0.0, 0.0], [0.7, 0.1, 0.0], [0.2, 0.6, 0.0]])  # double-sided
pose = sepax.pose([0.1, -0.2, 0.5])  # exactly in the plane of the top face z = 0.5

table = sepax.audit(box, triangle, None, pose)
print(f"{box} vs {triangle}: {len(table['edges'])} edge pairs\n")
print(" eA eB  plain         robust        exact         face of A-B  parallel")
for i, (ea, eb) in enumerate(table["edges"]):
    if not (table["minkowski_exact"][i] or table["parallel_exact"][i] or (table["exact"][i] == 0).any()):
        continue  # rows with nothing degenerate or interesting
    cells = [" ".join(f"{s:+d}" for s in table[k][i]) for k in ("plain", "robust", "exact")]
    print(f"{ea:3d} {eb:2d}  {cells[0]:12s}  {cells[1]:12s}  {cells[2]:12s}  "
          f"{str(bool(table['minkowski_exact'][i])):11s}  {bool(table['parallel_exact'][i])}")

same = np.array_equal(table["robust"], table["exact"])
print(f"\nrobust == exact on every sign: {same}; plain differs on "
      f"{int((table['plain'] != table['exact']).sum())} of {table['exact'].size} signs")
r = sepax.query(box, triangle, None, pose)
print(f"query: overlap={r.overlap}, separation={r.separation}, {r.feature!r}, {len(r.manifold)} contact points")
assert same

# The fuzzer's full audit of the same input (`sepax audit`), and the picture of the query (`sepax render`).
# The pose and the shapes are float-valued except 0.7, 0.1, 0.2, 0.6: the audit rounds them to float.
if hasattr(sepax, "render_svg"):
    import warnings

    with warnings.catch_warnings(record=True) as rounded:
        warnings.simplefilter("always")
        report = sepax.audit(box, triangle, None, pose, report="json")
    print(f"\naudit report ({rounded[0].message if rounded else 'no coordinate rounded'}):")
    print(f"  {len(report['axes'])} candidate axes, {len(report['chosen'])} configuration/SAT answers, "
          f"differential check: {report['check']['unexplained']} unexplained")
    for c in report["chosen"][:3]:
        print(f"  {c['config']:13s} {c['sat']:11s} {c['feature_text']:24s} separation {c['separation']}")
    svg = sepax.render_svg(box, triangle, None, pose, title="double-sided triangle on a box face")
    with open("audit_triangle.svg", "w") as f:
        f.write(svg)
    print(f"wrote audit_triangle.svg ({len(svg)} bytes: the shapes, {len(r.manifold)} contact points, the Gauss maps)")
    assert report["check"]["unexplained"] == 0
