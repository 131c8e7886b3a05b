"""Bad input: sepax.InvalidInput (a ValueError) with the error code and a message naming the problem."""

import pickle

import numpy as np
import pytest

import sepax


def check(excinfo, code, code_name):
    e = excinfo.value
    assert isinstance(e, ValueError)
    assert e.code == code and e.code_name == code_name


def test_invalid_input_is_a_value_error_with_code():
    assert issubclass(sepax.InvalidInput, ValueError)
    with pytest.raises(ValueError) as ei:  # catchable as ValueError
        sepax.convex_hull([[0, 0, 0], [1, 0, 0], [0, np.nan, 0], [0, 0, 1]])
    check(ei, sepax.ErrorCode.NonFinite, "non-finite")
    assert "point 2" in str(ei.value)
    e = pickle.loads(pickle.dumps(ei.value))  # survives multiprocessing
    assert type(e) is sepax.InvalidInput and e.code == sepax.ErrorCode.NonFinite and str(e) == str(ei.value)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_non_finite_points(bad):
    p = np.random.default_rng(0).normal(size=(10, 3))
    p[7, 1] = bad
    with pytest.raises(sepax.InvalidInput, match="point 7") as ei:
        sepax.convex_hull(p)
    check(ei, sepax.ErrorCode.NonFinite, "non-finite")
    v = sepax.cube().vertices
    v[3, 2] = bad
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.Shape(v, sepax.cube().faces)
    check(ei, sepax.ErrorCode.NonFinite, "non-finite")


def test_degenerate_point_sets():
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.convex_hull([[0, 0, 0], [1, 1, 1]])
    check(ei, sepax.ErrorCode.TooFewPoints, "too-few-points")
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.convex_hull([[0, 0, 0]] * 5)
    check(ei, sepax.ErrorCode.TooFewPoints, "too-few-points")
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.convex_hull([[t, 2 * t, -t] for t in np.linspace(0, 1, 9)])
    check(ei, sepax.ErrorCode.Collinear, "collinear")
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.convex_hull(np.zeros((0, 3)))
    check(ei, sepax.ErrorCode.TooFewPoints, "too-few-points")
    # coplanar points are not an error: a double-sided polygon
    flat = sepax.convex_hull([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 0]])
    assert flat.is_flat and flat.vertex_count == 4 and flat.face_count == 2


def test_bad_face_lists():
    v, f = sepax.cube().vertices, sepax.cube().faces
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.Shape(v, f[:-1] + [[0, 1, 99]])
    check(ei, sepax.ErrorCode.BadIndex, "bad-index")
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.Shape(v, [list(reversed(x)) for x in f])
    check(ei, sepax.ErrorCode.InwardFaces, "inward-faces")
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.Shape(v, f[:-1])
    assert ei.value.code in (sepax.ErrorCode.NotManifold, sepax.ErrorCode.UnusedVertex, sepax.ErrorCode.BadEuler)


def test_triangulated_convex_mesh_is_its_polyhedron():
    # a cube with every face split into two triangles (as trimesh and STL files hold it): the cube
    c = sepax.cube(1.0)
    tris = [t for f in c.faces for t in ([f[0], f[1], f[2]], [f[0], f[2], f[3]])]
    s = sepax.Shape(c.vertices, tris)
    assert len(s.faces) == 6 and s.vertices.shape == (8, 3)
    assert sorted(map(tuple, s.vertices.tolist())) == sorted(map(tuple, c.vertices.tolist()))
    r = sepax.query(s, c, None, [1.5, 0, 0])
    assert r.overlap and abs(r.depth - 0.5) < 1e-12
    # a closed triangulated mesh with a dent is not convex: validation's error on the face list as given
    v = np.vstack([c.vertices, [[0, 0, 0.5]]])
    top = [f for f in c.faces if all(c.vertices[i][2] > 0 for i in f)][0]
    dented = [f for f in c.faces if f != top] + [[top[k], top[(k + 1) % 4], 8] for k in range(4)]
    with pytest.raises(sepax.InvalidInput) as ei:
        sepax.Shape(v, dented)
    check(ei, sepax.ErrorCode.NotConvex, "not-convex")


def test_malformed_arrays_are_value_errors():
    with pytest.raises(ValueError, match=r"shape \(N, 3\)"):
        sepax.convex_hull(np.zeros((5, 2)))
    with pytest.raises(ValueError, match="number"):
        sepax.query(sepax.cube(), sepax.cube(), number="half")
    with pytest.raises(ValueError, match="algorithm"):
        sepax.query(sepax.cube(), sepax.cube(), algorithm="magic")
    with pytest.raises(ValueError, match="pose_b"):
        sepax.query(sepax.cube(), sepax.cube(), None, np.eye(3))
    # flags are booleans: None is not taken for False
    for flag in ("robust", "early_out", "manifold"):
        with pytest.raises(TypeError):
            sepax.query(sepax.cube(), sepax.cube(), **{flag: None})
        with pytest.raises(TypeError):
            sepax.query_batch(sepax.cube(), sepax.cube(), None, None, **{flag: None})


@pytest.mark.parametrize("number", ["float", "double", "exact"])
def test_bad_poses(number):
    a, b = sepax.cube(), sepax.tetrahedron()
    p = np.eye(4)
    p[1, 3] = np.nan
    with pytest.raises(sepax.InvalidInput, match="pose_b: translation entry 1") as ei:
        sepax.query(a, b, None, p, number=number)
    check(ei, sepax.ErrorCode.NonFinite, "non-finite")
    p = np.eye(4)
    p[3, 0] = 0.5
    with pytest.raises(sepax.InvalidInput, match="last row") as ei:
        sepax.query(a, b, p, None, number=number)
    check(ei, sepax.ErrorCode.BadScale, "bad-scale")
    mirror = np.diag([1.0, 1.0, -1.0, 1.0])  # det R < 0: refused by every number type, naming the argument
    with pytest.raises(sepax.InvalidInput, match="^pose_b: the rotation") as ei:
        sepax.query(a, b, None, mirror, number=number)
    check(ei, sepax.ErrorCode.BadScale, "bad-scale")
    with pytest.raises(sepax.InvalidInput, match="^pose_a: the rotation"):
        sepax.render_svg(a, b, mirror, None, number=number)
    if number != "exact":  # float/double refuse |R^T R - I| > 1e-3 (exact T: only det R <= 0)
        with pytest.raises(sepax.InvalidInput, match="^pose_a: the rotation is not a rotation") as ei:
            sepax.query(a, b, np.diag([2.0, 2.0, 2.0, 1.0]), None, number=number)
        check(ei, sepax.ErrorCode.BadScale, "bad-scale")
        with pytest.raises(sepax.InvalidInput, match="^pose_b: the rotation is not a rotation"):
            sepax.audit(a, b, None, np.diag([2.0, 2.0, 2.0, 1.0]), number=number)
    stack = np.stack([np.eye(4)] * 3)
    stack[2, 0, 0] = np.inf
    with pytest.raises(sepax.InvalidInput, match=r"poses_b\[2\]") as ei:
        sepax.query_batch(a, b, None, stack, number=number)
    check(ei, sepax.ErrorCode.NonFinite, "non-finite")
    stack[2] = mirror
    with pytest.raises(sepax.InvalidInput, match=r"^poses_b\[2\]: the rotation") as ei:
        sepax.query_batch(a, b, None, stack, number=number)
    check(ei, sepax.ErrorCode.BadScale, "bad-scale")
    with pytest.raises(sepax.InvalidInput, match=r"^poses_a: the rotation"):
        sepax.query_batch(a, b, mirror, stack[:2], number=number)


@pytest.mark.parametrize("margin,code", [(-0.1, sepax.ErrorCode.BadScale), (np.inf, sepax.ErrorCode.BadScale),
                                         (np.nan, sepax.ErrorCode.BadScale)])
def test_bad_margin(margin, code):
    with pytest.raises(sepax.InvalidInput, match="margin") as ei:
        sepax.query(sepax.cube(), sepax.cube(), None, [3, 0, 0], margin=margin)
    assert ei.value.code == code


def test_float_range():
    # finite in double, beyond float: refused when first queried in float, with the coordinate named
    big = sepax.cube(1e39)
    assert sepax.query(big, sepax.cube(1e38), None, [0, 0, 3e39]).separation == pytest.approx(1.9e39)
    with pytest.raises(sepax.InvalidInput, match="beyond the range of float") as ei:
        sepax.query(big, sepax.cube(1e38), None, [0, 0, 3e39], number="float")
    check(ei, sepax.ErrorCode.BadScale, "bad-scale")
    # a translation beyond float's range: refused as the program refuses it, naming the entry
    with pytest.raises(sepax.InvalidInput, match=r"^pose_b: translation entry 2 \(1e\+39\) is beyond the range of float") as ei:
        sepax.query(sepax.cube(), sepax.cube(), None, [0, 0, 1e39], number="float")
    check(ei, sepax.ErrorCode.BadScale, "bad-scale")


def test_shape_too_small_for_its_position():
    # a unit cube 3e39 away: double's spacing there (about 5e23) puts its vertices on one line per face,
    # so its faces have no plane: refused, in the number type that cannot hold it
    big = sepax.cube(1e39)
    with pytest.raises(sepax.InvalidInput, match="face 2 has no plane at these coordinates") as ei:
        sepax.query(big, sepax.cube(), None, [0, 0, 3e39])
    check(ei, sepax.ErrorCode.BadScale, "bad-scale")
    # exact: the pose is applied exactly, the cube keeps its faces
    assert sepax.query(big, sepax.cube(), None, [0, 0, 3e39], number="exact").separation == pytest.approx(2e39)
