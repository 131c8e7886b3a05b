"""Queries of the sepax module against known answers, the C++ program, each other, and themselves batched."""

import ast
import json
import math
import os
import subprocess
import threading
import time
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

import sepax

NUMBERS = ["float", "double", "exact"]
ALGORITHMS = ["traversal", "gauss_map", "brute_force"]
# (number, robust): every configuration the module runs
CONFIGS = [("float", True), ("float", False), ("double", True), ("double", False), ("exact", True)]


def exact_value(sep):
    """num / sqrt(norm2) of an exact separation whose norm2 is the square of a rational."""
    num, norm2 = sep
    p, q = math.isqrt(norm2.numerator), math.isqrt(norm2.denominator)
    assert Fraction(p * p, q * q) == norm2, "norm2 is not a square"
    return num / Fraction(p, q)


def random_hull(rng, n, radius=1.0):
    p = rng.normal(size=(n, 3))
    p *= radius / np.linalg.norm(p, axis=1)[:, None]
    return sepax.convex_hull(p)


def random_poses(rng, k, spread):
    q = rng.normal(size=(k, 4))
    t = rng.uniform(-spread, spread, size=(k, 3))
    return np.stack([sepax.pose(t[i], q[i]) for i in range(k)])


# ---- known answers on boxes -------------------------------------------------


@pytest.mark.parametrize("number,robust", CONFIGS)
@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_separated_cubes(number, robust, algorithm):
    r = sepax.query(sepax.cube(), sepax.cube(), None, [2.5, 0, 0], number=number, robust=robust, algorithm=algorithm)
    assert not r.overlap
    assert r.separation == 0.5
    assert r.depth == 0.0
    assert r.feature.type == "faceA"
    np.testing.assert_array_equal(r.axis, [1.0, 0.0, 0.0])
    assert r.manifold is not None and len(r.manifold) == 0  # beyond the margin 0: no points
    if number == "exact":
        assert exact_value(r.separation_exact) == Fraction(1, 2)
    else:
        assert r.separation_exact is None


@pytest.mark.parametrize("number,robust", CONFIGS)
@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_touching_boxes_face_contact(number, robust, algorithm):
    # B's bottom face lies exactly on A's top face: touching counts as overlap, separation exactly 0
    a, b = sepax.box(2, 2, 0.5), sepax.box(0.5, 0.5, 0.5)
    r = sepax.query(a, b, None, [0.25, -0.5, 1.0], number=number, robust=robust, algorithm=algorithm)
    assert r.overlap
    assert r.separation == 0.0
    np.testing.assert_array_equal(r.axis, [0.0, 0.0, 1.0])
    m = r.manifold
    assert m.kind == "face" and len(m) == 4
    np.testing.assert_array_equal(m.normal, [0.0, 0.0, 1.0])
    np.testing.assert_array_equal(m.separations, np.zeros(4))
    np.testing.assert_array_equal(np.sort(m.points[:, 0]), [-0.25, -0.25, 0.75, 0.75])
    np.testing.assert_array_equal(m.points[:, 2], np.full(4, 0.5))


@pytest.mark.parametrize("number,robust", CONFIGS)
@pytest.mark.parametrize("algorithm", ALGORITHMS)
def test_overlapping_boxes_known_depth(number, robust, algorithm):
    a, b = sepax.box(1, 1, 1), sepax.box(0.5, 0.5, 0.5)
    t = [1.2, 0.1, -0.05]
    r = sepax.query(a, b, None, t, number=number, robust=robust, algorithm=algorithm)
    assert r.overlap
    expected = 1.5 - 1.2  # A's +x face against B's -x face
    tol = 1e-6 if number == "float" else 1e-15
    assert r.separation == pytest.approx(-expected, abs=tol)
    assert r.depth == pytest.approx(expected, abs=tol)
    np.testing.assert_array_equal(r.axis, [1.0, 0.0, 0.0])
    m = r.manifold
    assert m.kind == "face" and len(m) == 4
    np.testing.assert_allclose(m.depths, np.full(4, expected), atol=tol)
    # the contact region is B's -x face clipped to A's +x face: y in [-0.4, 0.6], z in [-0.55, 0.45]
    np.testing.assert_allclose(np.sort(np.unique(np.round(m.points[:, 1], 6))), [-0.4, 0.6], atol=tol)
    np.testing.assert_allclose(np.sort(np.unique(np.round(m.points[:, 2], 6))), [-0.55, 0.45], atol=tol)
    if number == "exact":
        # B moved by the exact value of the double 1.2
        assert exact_value(r.separation_exact) == -(Fraction(3, 2) - Fraction(1.2))


@pytest.mark.parametrize("number,robust", CONFIGS)
def test_rotated_box_edge_on(number, robust):
    # B turned 45 degrees about z reaches sqrt(2) along x: a vertical edge of B faces A's +x face
    s = math.sin(math.pi / 8)
    p = sepax.pose([1 + math.sqrt(2) + 0.25, 0, 0], [math.cos(math.pi / 8), 0, 0, s])
    r = sepax.query(sepax.cube(), sepax.cube(), None, p, number=number, robust=robust)
    assert not r.overlap
    assert r.separation == pytest.approx(0.25, abs=1e-6 if number == "float" else 1e-12)
    assert r.feature.type == "faceA"
    r2 = sepax.query(sepax.cube(), sepax.cube(), None, p, number=number, robust=robust, margin=0.3)
    assert len(r2.manifold) == 2  # the edge's two ends within the margin
    np.testing.assert_allclose(r2.manifold.separations, [0.25, 0.25], atol=1e-6)


def test_poses_of_both_shapes_and_pose_forms():
    a, b = sepax.cube(), random_hull(np.random.default_rng(3), 20, 0.8)
    pa, pb = sepax.pose([0.3, -0.2, 0.1], [0.9, 0.1, 0.2, 0.3]), sepax.pose([1.2, 0.5, 0.4], [0.2, 0.7, -0.1, 0.4])
    r = sepax.query(a, b, pa, pb)
    # (R, t) pairs give the same answer as the 4x4 matrices
    r2 = sepax.query(a, b, (pa[:3, :3], pa[:3, 3]), (pb[:3, :3], pb[:3, 3]))
    assert r2.separation == r.separation and r2.feature == r.feature
    np.testing.assert_array_equal(r2.manifold.points, r.manifold.points)
    # moving both by one rigid motion leaves the separation (nearly) unchanged
    g = sepax.pose([5, -3, 2], [0.5, 0.5, 0.5, 0.5])
    r3 = sepax.query(a, b, g @ pa, g @ pb)
    assert r3.overlap == r.overlap
    assert r3.separation == pytest.approx(r.separation, abs=1e-12)


def test_shapes_pickle():
    import pickle

    a = random_hull(np.random.default_rng(4), 25)
    b = pickle.loads(pickle.dumps(a))
    np.testing.assert_array_equal(b.vertices, a.vertices)
    assert b.faces == a.faces
    p = sepax.pose([0.9, 0.3, -0.2], [0.4, 0.1, -0.6, 0.2])
    ra, rb = sepax.query(a, sepax.cube(), None, p), sepax.query(b, sepax.cube(), None, p)
    assert (ra.separation, ra.feature) == (rb.separation, rb.feature)


# ---- against the C++ program ---------------------------------------------------


def cli_query(cli, a, b, pose, number, robust):
    args = [cli, "query", a, b, "--pose", *map(repr, pose), "--number", number, "--algorithm", "traversal", "--json"]
    if robust:
        args.append("--robust")
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return json.loads(out)


@pytest.mark.skipif(not os.environ.get("SEPAX_CLI"), reason="SEPAX_CLI (the sepax program) not given")
@pytest.mark.parametrize("number,robust", [("double", True), ("double", False), ("float", True), ("exact", False)])
def test_agrees_with_cli(number, robust):
    cli = os.environ["SEPAX_CLI"]
    # same_input: the program poses B in double and then converts to float / exact; the module poses the
    # float / exact shape by the converted pose.  The inputs agree when the posed coordinates are exact in
    # double (below: translations by dyadic numbers).  In double the two posing formulas round these poses'
    # coordinates alike; a general rotation may round one differently in its last bit (docs/python.md, Poses).
    cases = [
        ([2.5, 0, 0, 1, 0, 0, 0], "cube", "cube", True),
        ([2.0, 0.25, 0, 1, 0, 0, 0], "cube", "cube", True),
        ([1.25, -0.5, 0.75, 1, 0, 0, 0], "box:1,1,1", "box:0.5,0.5,0.5", True),
        ([1.2, 0.1, -0.05, 1, 0, 0, 0], "box:1,1,1", "box:0.5,0.5,0.5", False),
        ([1.5, 0.2, 0.1, 0.9, 0.1, 0.2, 0.3], "cube", "tetra", False),
        ([2.1, 0.4, -0.3, 0.3, -0.5, 0.7, 0.2], "box:1,0.5,0.25", "prism:7", False),
    ]
    shapes = {"cube": sepax.cube(), "tetra": sepax.tetrahedron(), "box:1,1,1": sepax.box(1, 1, 1),
              "box:0.5,0.5,0.5": sepax.box(0.5, 0.5, 0.5), "box:1,0.5,0.25": sepax.box(1, 0.5, 0.25),
              "prism:7": sepax.prism(7)}
    compared = 0
    for pose, na, nb, same_input in cases:
        if number != "double" and not same_input:
            continue
        want = cli_query(cli, na, nb, pose, number, robust)
        got = sepax.query(shapes[na], shapes[nb], None, sepax.pose(pose[:3], pose[3:]), number=number,
                          robust=robust, manifold=False)
        assert got.overlap == want["overlap"], (pose, na, nb)
        assert got.separation == want["separation"], (pose, na, nb)
        assert [got.feature.type, got.feature.a, got.feature.b] == [want["feature"][k] for k in ("type", "a", "b")]
        np.testing.assert_array_equal(got.axis, want["normal"])
        compared += 1
    assert compared >= 3


# ---- algorithms, number types and policies agree --------------------------------


def test_algorithms_agree_on_random_hulls():
    rng = np.random.default_rng(7)
    for _ in range(6):
        a, b = random_hull(rng, int(rng.integers(6, 40))), random_hull(rng, int(rng.integers(6, 16)))
        poses = random_poses(rng, 8, 1.6)
        for number, robust in [("double", True), ("exact", True)]:
            ps = poses[:3] if number == "exact" else poses  # exact brute force is slow
            results = [sepax.query_batch(a, b, None, ps, number=number, robust=robust, algorithm=al)
                       for al in ALGORITHMS]
            trav, gauss, brute = results
            for r in (gauss, brute):
                np.testing.assert_array_equal(r.overlap, trav.overlap)
                np.testing.assert_array_equal(r.feature_type, trav.feature_type)
                np.testing.assert_array_equal(r.feature, trav.feature)
            # the same feature gives the same value in the traversal and the Gauss map; the brute force
            # evaluates an edge pair's separation in another order (up to a few ulps in double)
            np.testing.assert_array_equal(gauss.separation, trav.separation)
            if number == "exact":
                np.testing.assert_array_equal(brute.separation, trav.separation)
            else:
                np.testing.assert_allclose(brute.separation, trav.separation, rtol=0, atol=4 * np.finfo(float).eps)
        # the robust double verdict is the exact verdict; the value is the double one (within rounding)
        rd = sepax.query_batch(a, b, None, poses, number="double")
        rx = sepax.query_batch(a, b, None, poses, number="exact")
        np.testing.assert_array_equal(rd.overlap, rx.overlap)
        np.testing.assert_array_equal(np.sign(rd.separation), np.sign(rx.separation))
        np.testing.assert_allclose(rd.separation, rx.separation, atol=1e-12)


# ---- batch == loop ---------------------------------------------------------------------


@pytest.mark.parametrize("number,robust", CONFIGS)
def test_batch_equals_loop(number, robust):
    rng = np.random.default_rng(11)
    a, b = random_hull(rng, 24), random_hull(rng, 12, 0.7)
    k = 4 if number == "exact" else 40
    pa, pb = random_poses(rng, k, 0.5), random_poses(rng, k, 1.8)
    for algorithm in ALGORITHMS:
        kw = dict(number=number, robust=robust, algorithm=algorithm, margin=0.05)
        br = sepax.query_batch(a, b, pa, pb, manifold=True, **kw)
        assert len(br) == k
        for i in range(k):
            r = sepax.query(a, b, pa[i], pb[i], **kw)
            assert br.overlap[i] == r.overlap and br.early_out[i] == r.early_out
            assert br.separation[i] == r.separation
            np.testing.assert_array_equal(br.axis[i], r.axis)
            assert sepax.FEATURE_TYPES[br.feature_type[i]] == r.feature.type
            assert tuple(br.feature[i]) == (r.feature.a, r.feature.b)
            assert br.exact_fallbacks[i] == r.stats["exact_fallbacks"]
            n = len(r.manifold)
            assert br.contact_count[i] == n
            np.testing.assert_array_equal(br.contact_points[i, :n], r.manifold.points)
            np.testing.assert_array_equal(br.contact_separations[i, :n], r.manifold.separations)
            np.testing.assert_array_equal(br.contact_ids[i, :n], r.manifold.ids)
            assert np.isnan(br.contact_points[i, n:]).all() and (br.contact_ids[i, n:] == -1).all()
    # the (R, t) form and a broadcast single pose give the same rows
    rt = sepax.query_batch(a, b, (pa[:, :3, :3], pa[:, :3, 3]), (pb[:, :3, :3], pb[:, :3, 3]), number=number,
                           robust=robust)
    mat = sepax.query_batch(a, b, pa, pb, number=number, robust=robust)
    np.testing.assert_array_equal(rt.separation, mat.separation)
    one = sepax.query_batch(a, b, pa[3], pb, number=number, robust=robust)
    for i in (0, k // 2, k - 1):
        assert one.separation[i] == sepax.query(a, b, pa[3], pb[i], number=number, robust=robust).separation


def test_result_arrays_are_read_only():
    a, b = sepax.cube(), sepax.cube()
    r = sepax.query(a, b, None, [1.5, 0, 0])
    m = r.manifold
    for arr in (r.axis, m.normal, m.points, m.points_a, m.points_b, m.separations, m.ids, m.id_keys):
        assert not arr.flags.writeable
    with pytest.raises(ValueError):
        r.axis[0] = 2.0
    assert r.axis[0] == 1.0 and r.axis is r.axis
    copy = np.array(r.axis)
    copy[0] = 2.0  # a copy is the caller's
    br = sepax.query_batch(a, b, None, np.stack([np.eye(4)] * 2), manifold=True)
    for arr in (br.overlap, br.separation, br.axis, br.feature, br.contact_points, br.contact_count):
        assert not arr.flags.writeable


def test_batch_pose_count_mismatch():
    rng = np.random.default_rng(1)
    with pytest.raises(ValueError, match="each must hold K or 1"):
        sepax.query_batch(sepax.cube(), sepax.cube(), random_poses(rng, 3, 1), random_poses(rng, 4, 1))
    with pytest.raises(ValueError, match="shape"):
        sepax.query_batch(sepax.cube(), sepax.cube(), None, np.zeros((3, 4, 3)))


def test_batch_of_no_poses_gives_empty_columns():
    for number in ("float", "double", "exact"):
        r = sepax.query_batch(sepax.cube(), sepax.cube(), np.zeros((0, 4, 4)), None, number=number, manifold=True)
        assert r.overlap.shape == (0,) and r.separation.shape == (0,) and r.axis.shape == (0, 3)
        assert r.contact_points.shape == (0, 4, 3)
    with pytest.raises(ValueError, match="each must hold K or 1"):
        sepax.query_batch(sepax.cube(), sepax.cube(), np.zeros((0, 4, 4)), random_poses(np.random.default_rng(2), 2, 1))


# ---- the cache ---------------------------------------------------------------------------


def trajectory(k):
    # B slides and turns over A's top face, lifts off and comes back
    t = np.linspace(0, 1, k)
    z = 1.0 + 0.4 * np.sin(2 * np.pi * t) - 0.02
    return np.stack([sepax.pose([0.8 * s, 0.3 * math.cos(3 * s), zz], [1, 0, 0, 0.3 * s]) for s, zz in zip(t, z)])


@pytest.mark.parametrize("number,robust", [("float", True), ("double", True), ("exact", True), ("double", False)])
def test_cache_gives_identical_answers(number, robust):
    rng = np.random.default_rng(5)
    a, b = sepax.box(1.5, 1.5, 0.5), random_hull(rng, 20, 0.5)
    poses = trajectory(8 if number == "exact" else 120)
    algorithms = ["gauss_map", "brute_force"] if not robust else ALGORITHMS
    for algorithm in algorithms:
        cache = sepax.Cache()
        kw = dict(number=number, robust=robust, algorithm=algorithm, margin=0.02)
        for p in poses:
            fresh = sepax.query(a, b, None, p, **kw)
            cached = sepax.query(a, b, None, p, cache=cache, **kw)
            assert (cached.overlap, cached.separation, cached.feature) == (fresh.overlap, fresh.separation,
                                                                          fresh.feature)
            np.testing.assert_array_equal(cached.manifold.points, fresh.manifold.points)
            np.testing.assert_array_equal(cached.manifold.ids, fresh.manifold.ids)
        assert cache.misses == len(poses) and cache.hits == 0
        # early_out: the verdict is the fresh one; separated poses beyond the margin are answered by the cache
        cache = sepax.Cache()
        for p in poses:
            fresh = sepax.query(a, b, None, p, early_out=True, **kw)
            cached = sepax.query(a, b, None, p, early_out=True, cache=cache, **kw)
            assert cached.overlap == fresh.overlap and cached.early_out == fresh.early_out
            if cached.early_out:
                assert cached.separation > 0.02
            else:
                assert (cached.separation, cached.feature) == (fresh.separation, fresh.feature)
        assert cache.hits > 0
        # a batch carries the cache from row to row exactly like the loop
        c1, c2 = sepax.Cache(), sepax.Cache()
        br = sepax.query_batch(a, b, None, poses, early_out=True, cache=c1, **kw)
        loop = [sepax.query(a, b, None, p, early_out=True, cache=c2, **kw) for p in poses]
        np.testing.assert_array_equal(br.separation, [r.separation for r in loop])
        assert (c1.hits, c1.misses) == (c2.hits, c2.misses)


def test_cache_refuses_plain_float_traversal():
    with pytest.raises(ValueError, match="warm-start"):
        sepax.query(sepax.cube(), sepax.cube(), None, [1, 0, 0], robust=False, cache=sepax.Cache())


def test_margin_keeps_speculative_points():
    a, b = sepax.box(2, 2, 0.5), sepax.cube(0.5)
    r = sepax.query(a, b, None, [0, 0, 1.03], margin=0.05)
    assert not r.overlap and len(r.manifold) == 4
    np.testing.assert_allclose(r.manifold.separations, np.full(4, 0.03), atol=1e-15)
    assert len(sepax.query(a, b, None, [0, 0, 1.03], margin=0.02).manifold) == 0
    r = sepax.query(a, b, None, [0, 0, 1.03], margin=0.02, early_out=True)
    assert r.early_out and r.manifold is None and r.separation > 0.02


# ---- the GIL ---------------------------------------------------------------------------------


def test_queries_release_the_gil():
    rng = np.random.default_rng(2)
    a, b = random_hull(rng, 60), random_hull(rng, 60)
    poses = random_poses(rng, 60, 1.5)  # brute force on 60-point hulls: milliseconds per query
    span = {}

    def work():
        span["start"] = time.perf_counter()
        span["result"] = sepax.query_batch(a, b, None, poses, algorithm="brute_force")
        span["end"] = time.perf_counter()

    th = threading.Thread(target=work)
    ticks = []
    th.start()
    while th.is_alive():
        ticks.append(time.perf_counter())
    th.join()
    start, end = span["start"], span["end"]
    assert end - start > 0.02, "the batch is too short to tell"
    inside = [t for t in ticks if start + 0.1 * (end - start) < t < end - 0.1 * (end - start)]
    assert len(inside) > 100  # Python ran in this thread while the batch ran in the other one


def test_threads_give_the_serial_answers():
    # the posed queries keep per-thread scratch: threads querying the same shapes (and a shared cache)
    # must give the answers of a serial run
    rng = np.random.default_rng(9)
    shapes = [random_hull(rng, 30), random_hull(rng, 16, 0.6), sepax.box(1, 0.5, 0.25)]
    poses = random_poses(rng, 300, 1.5)
    jobs = [(shapes[i % 3], shapes[(i + 1) % 3], number) for i in range(6) for number in ("float", "double")]
    serial = [sepax.query_batch(a, b, None, poses, number=n, manifold=True) for a, b, n in jobs]
    out = [None] * len(jobs)
    shared = sepax.Cache()
    mismatches = []

    def run(j):
        a, b, n = jobs[j]
        out[j] = sepax.query_batch(a, b, None, poses, number=n, manifold=True)
        for i in range(0, 300, 7):  # single queries through one cache shared by every thread
            r = sepax.query(a, b, None, poses[i], number=n, cache=shared)
            if r.separation != serial[j].separation[i]:
                mismatches.append((j, i))

    threads = [threading.Thread(target=run, args=(j,)) for j in range(len(jobs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not mismatches
    for got, want in zip(out, serial):
        np.testing.assert_array_equal(got.separation, want.separation)
        np.testing.assert_array_equal(got.feature, want.feature)
        np.testing.assert_array_equal(got.contact_points, want.contact_points)
        np.testing.assert_array_equal(got.contact_ids, want.contact_ids)


# ---- stubs -----------------------------------------------------------------------------------


def test_stubs_cover_the_module():
    stub = Path(sepax.__file__).with_name("sepax.pyi")
    tree = ast.parse(stub.read_text())
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    public = {n for n in dir(sepax) if not n.startswith("_")}
    assert public <= names, public - names
    for cls in ("Shape", "Result", "Manifold", "BatchResult", "Cache", "Feature"):
        node = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == cls)
        declared = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
        members = {n for n in dir(getattr(sepax, cls)) if not n.startswith("_")}
        assert members <= declared, (cls, members - declared)
    # ErrorCode: a pybind11 enum, typed as one (its members, name and value; no enum.Enum iteration)
    node = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "ErrorCode")
    declared = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
    declared |= {n.target.id for n in node.body if isinstance(n, ast.AnnAssign)}
    assert {n for n in dir(sepax.ErrorCode) if not n.startswith("_")} <= declared
    assert set(sepax.ErrorCode.__members__) <= declared and not node.bases
    if hasattr(sepax, "fuzz"):  # the submodule, typed as a namespace class
        node = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "fuzz")
        declared = {n.name for n in node.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
        assert {n for n in dir(sepax.fuzz) if not n.startswith("_")} <= declared
        report = next(n for n in node.body if isinstance(n, ast.ClassDef) and n.name == "CaseReport")
        declared = {n.name for n in report.body if isinstance(n, ast.FunctionDef)}
        members = {n for n in dir(sepax.fuzz.CaseReport) if not n.startswith("_")}
        assert members <= declared, members - declared


# ---- audit: the sign table ---------------------------------------------------------------------


def check_audit(a, b, pa, pb, number):
    t = sepax.audit(a, b, pa, pb, number=number)
    n = a.edge_count * b.edge_count
    assert t["edges"].shape == (n, 2) and t["exact"].shape == (n, 4)
    assert tuple(t["edges"][b.edge_count + 2]) == (1, 2)
    # the robust policy's decisions are the exact ones (robust_kernel.hpp's contract)
    np.testing.assert_array_equal(t["robust"], t["exact"])
    np.testing.assert_array_equal(t["minkowski_robust"], t["minkowski_exact"])
    np.testing.assert_array_equal(t["parallel_robust"], t["parallel_exact"])
    return t


@pytest.mark.parametrize("number", ["float", "double"])
def test_audit_double_sided_triangle_on_a_box_face(number):
    # a double-sided triangle lying in the plane of the box's top face: exactly coplanar faces, exact zeros
    box = sepax.box(1, 1, 0.5)
    tri = sepax.polygon([[0, 0, 0], [0.7, 0.1, 0], [0.2, 0.6, 0]])
    t = check_audit(box, tri, None, [0.1, -0.2, 0.5], number)
    assert (t["exact"] == 0).any()
    assert t["minkowski_exact"].sum() > 0
    # and turned by a tiny angle about an axis in the face: signs near zero, still decided exactly
    eps = 1e-9
    t = check_audit(box, tri, None, sepax.pose([0.1, -0.2, 0.5], [1, eps, 2 * eps, 0]), number)
    r = sepax.query(box, tri, None, sepax.pose([0.1, -0.2, 0.5], [1, eps, 2 * eps, 0]), number=number,
                    algorithm="brute_force")
    assert r.overlap


def test_audit_random_pairs_and_refusals():
    rng = np.random.default_rng(13)
    for _ in range(4):
        a, b = random_hull(rng, 14), random_hull(rng, 10, 0.7)
        p = random_poses(rng, 2, 1.2)
        t = check_audit(a, b, p[0], p[1], "double")
        # the exact Minkowski faces (non-parallel) are the edge pairs the exact brute force counts
        r = sepax.query(a, b, p[0], p[1], number="double", algorithm="brute_force")
        assert r.stats["minkowski_faces"] == int((t["minkowski_exact"] & ~t["parallel_exact"]).sum())
    with pytest.raises(ValueError, match="float or double"):
        sepax.audit(sepax.cube(), sepax.cube(), number="exact")


def test_convex_hull_local_keeps_a_far_piece_at_its_own_scale():
    # a 0.1-unit piece a million units out: double cannot validate it in world coordinates,
    # and its hull in its own frame answers as the same piece at a pose
    rng = np.random.default_rng(11)
    local_points = rng.uniform(-0.05, 0.05, size=(60, 3))
    world = local_points + 1.0e6
    with pytest.raises(sepax.InvalidInput) as err:
        sepax.convex_hull(world)
    assert err.value.code == sepax.ErrorCode.BadScale
    shape, origin = sepax.convex_hull_local(world)
    assert origin.shape == (3,)
    v = shape.vertices
    # every vertex + origin is exactly an input point
    inputs = {tuple(p) for p in world}
    assert all(tuple(p) in inputs for p in v + origin)
    # the piece at its world place (pose: the origin) against its copy 0.2 along x gives what the
    # same piece near the world origin gives; float poses cannot hold a million units to 0.2 (float's
    # spacing there is 0.0625), so float is asked in a frame near the pair, as an engine would
    near = sepax.convex_hull(local_points)
    for number in NUMBERS:
        at = origin if number != "float" else np.zeros(3)
        far_r = sepax.query(shape, shape, at, at + [0.2, 0, 0], number=number)
        near_r = sepax.query(near, near, None, [0.2, 0, 0], number=number)
        assert far_r.overlap is False and near_r.overlap is False
        assert far_r.separation == pytest.approx(near_r.separation, rel=1e-6)
        assert far_r.feature.type == near_r.feature.type
