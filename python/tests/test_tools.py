"""render_svg, audit(report=...) and sepax.fuzz.replay: the program's renderer and the fuzzer from Python."""

import json
import os
import subprocess
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import sepax

pytestmark = pytest.mark.skipif(not hasattr(sepax, "render_svg"),
                                reason="module built without the program's and the fuzzer's libraries")

ROOT = Path(__file__).resolve().parents[2]
CORPUS = ROOT / "fuzz" / "corpus"
SVG = "{http://www.w3.org/2000/svg}"
COLOR_A, COLOR_B, COLOR_CONTACT = "#1f5fbf", "#c0392b", "#e67e22"  # src/render/svg_render.cpp


def parse_svg(text):
    root = ET.fromstring(text)  # raises on malformed XML
    assert root.tag == SVG + "svg"
    return root


def elements(root, tag, **attrs):
    return [e for e in root.iter(SVG + tag) if all(e.get(k) == v for k, v in attrs.items())]


def header(root):
    return [t.text for t in root.iter(SVG + "text")][1]  # the line under the title


# ---- render_svg -------------------------------------------------------------------


@pytest.mark.parametrize("number", ["double", "float", "exact"])
def test_svg_draws_the_shapes_and_the_manifold(number):
    a, b = sepax.box(1, 1, 1), sepax.box(0.5, 0.5, 0.5)
    pose_b = sepax.pose([1.2, 0.1, -0.05], [0.98, 0.05, 0.1, 0.15])
    for margin in (0.0, 0.3):
        svg = sepax.render_svg(a, b, None, pose_b, number=number, margin=margin)
        root = parse_svg(svg)
        r = sepax.query(a, b, None, pose_b, number=number, margin=margin)
        m = len(r.manifold)
        assert m > 0
        # one contact dot per manifold point, and the normal drawn from their centre
        assert len(elements(root, "circle", fill=COLOR_CONTACT)) == m
        assert len(elements(root, "line", stroke=COLOR_CONTACT)) == 1
        assert f"contacts {m}" in header(root)
        assert header(root).startswith("overlap" if r.overlap else "separated")
        for shape, color in ((a, COLOR_A), (b, COLOR_B)):
            lines = elements(root, "line", stroke=color)
            assert len(lines) == shape.edge_count  # every edge, hidden ones dashed
            ends = {(l.get("x1"), l.get("y1")) for l in lines} | {(l.get("x2"), l.get("y2")) for l in lines}
            assert len(ends) == shape.vertex_count  # the edges meet at the shape's vertices
            faces = elements(root, "polygon", fill=color)
            assert 1 <= len(faces) <= 3  # the faces towards the viewer of a box
            assert all(len(f.get("points").split()) == 4 for f in faces)


def test_svg_of_a_double_sided_triangle_and_separated_shapes():
    box, tri = sepax.box(1, 1, 0.5), sepax.polygon([[0, 0, 0], [0.7, 0.1, 0], [0.2, 0.6, 0]])
    root = parse_svg(sepax.render_svg(box, tri, None, [0.1, -0.2, 0.5], title="triangle <on> box & face"))
    assert [t.text for t in root.iter(SVG + "text")][0] == "triangle <on> box & face"  # escaped, parsed back
    # control characters are not allowed in XML: each becomes U+FFFD, and the SVG still parses
    root = parse_svg(sepax.render_svg(box, tri, None, [0.1, -0.2, 0.5], title="a\x01b\x1fc"))
    assert [t.text for t in root.iter(SVG + "text")][0] == "a\ufffdb\ufffdc"
    faces = elements(root, "polygon", fill=COLOR_B)
    assert len(faces) == 2 and all(len(f.get("points").split()) == 3 for f in faces)  # both sides drawn
    assert len(elements(root, "circle", fill=COLOR_CONTACT)) == len(sepax.query(box, tri, None, [0.1, -0.2, 0.5]).manifold)
    # far apart: no contact points, no normal
    root = parse_svg(sepax.render_svg(box, tri, None, [5, 0, 0]))
    assert elements(root, "circle", fill=COLOR_CONTACT) == [] and elements(root, "line", stroke=COLOR_CONTACT) == []
    assert header(root).startswith("separated") and "contacts 0" in header(root)


def unit(v):
    return v / np.linalg.norm(v)


def left_panel_projection(axis, world_vertices):
    """The left panel's camera and viewport of src/render/svg_render.cpp, for checking positions."""
    def basis(toward):
        view = unit(toward)
        helper = np.array([0.0, 0, 1]) if abs(view[2]) < 0.9 else np.array([1.0, 0, 0])
        right = unit(np.cross(helper, view))
        return right, np.cross(view, right)

    axis = unit(axis)
    helper = np.array([0.0, 0, 1]) if abs(axis[2]) < 0.9 else np.array([1.0, 0, 0])
    side = unit(np.cross(helper, axis))
    right, up = basis(0.35 * axis + side + 0.45 * np.cross(axis, side))
    xy = np.stack([world_vertices @ right, world_vertices @ up], axis=1)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    scale, centre = 0.82 * 480 / max((hi - lo).max(), 1e-300), (lo + hi) / 2

    def project(p):
        q = np.stack([p @ right, p @ up], axis=1)
        return np.stack([20 + 240 + (q[:, 0] - centre[0]) * scale, 56 + 20 + 240 - (q[:, 1] - centre[1]) * scale], 1)

    return project


def moved(shape, pose):
    return shape.vertices @ pose[:3, :3].T + pose[:3, 3]


def test_svg_is_drawn_in_world_coordinates():
    # both shapes posed: the edges end at the projected world vertices, the dots are the manifold's points
    a, b = sepax.cube(), sepax.tetrahedron(0.5)
    pa = sepax.pose([0.5, -2, 3], [0.2, 0.7, -0.1, 0.4])
    pb = pa @ sepax.pose([1.2, 0.2, 0.1], [0.9, 0.1, 0.2, 0.3])
    r = sepax.query(a, b, pa, pb, margin=0.1)
    root = parse_svg(sepax.render_svg(a, b, pa, pb, margin=0.1))
    project = left_panel_projection(r.axis, np.vstack([moved(a, pa), moved(b, pb)]))
    dots = np.array([[float(c.get("cx")), float(c.get("cy"))] for c in elements(root, "circle", fill=COLOR_CONTACT)])
    assert len(dots) == len(r.manifold) > 0
    np.testing.assert_allclose(dots, project(r.manifold.points), atol=0.006)
    for shape, pose, color in ((a, pa, COLOR_A), (b, pb, COLOR_B)):
        lines = elements(root, "line", stroke=color)
        got = np.array([[float(l.get(k)) for k in ("x1", "y1", "x2", "y2")] for l in lines])
        want = project(moved(shape, pose))[shape.edges].reshape(-1, 4)
        np.testing.assert_allclose(got, want, atol=0.006)


@pytest.mark.skipif(not os.environ.get("SEPAX_CLI"), reason="SEPAX_CLI (the sepax program) not given")
def test_svg_equals_the_program_picture(tmp_path):
    # `sepax render` draws the robust double traversal of A and B moved by --pose; a translation by dyadic
    # numbers poses B exactly, so the module's picture of the same query is the same document
    cli = os.environ["SEPAX_CLI"]
    for na, nb, a, b, t in [("cube", "cube", sepax.cube(), sepax.cube(), [1.5, 0.25, 0.5]),
                            ("box:1,1,1", "box:0.5,0.5,0.5", sepax.box(1, 1, 1), sepax.box(0.5, 0.5, 0.5),
                             [1.25, -0.5, 0.75])]:
        out = tmp_path / "p.svg"
        subprocess.run([cli, "render", na, nb, "--robust", "--pose", *map(str, t), "--svg", str(out)], check=True,
                       capture_output=True)
        assert sepax.render_svg(a, b, None, t, title=f"{na}  vs  {nb}") == out.read_text()


def test_svg_errors():
    a = sepax.cube()
    with pytest.raises(sepax.InvalidInput) as e:
        sepax.render_svg(a, a, None, np.diag([2.0, 1, 1, 1]))
    assert e.value.code == sepax.ErrorCode.BadScale
    with pytest.raises(ValueError, match="algorithm"):
        sepax.render_svg(a, a, algorithm="nope")


# ---- audit(report=...) --------------------------------------------------------------


def test_audit_report_json_matches_the_sign_table():
    box, tri = sepax.box(1, 1, 0.5), sepax.polygon([[0, 0, 0], [0.75, 0.125, 0], [0.25, 0.5, 0]])
    pose = [0.125, -0.25, 0.5]  # every coordinate a float: nothing rounded
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        rep = sepax.audit(box, tri, None, pose, number="float", report="json")
    table = sepax.audit(box, tri, None, pose, number="float")
    assert rep["number"] == "float"
    assert rep["shapes"]["A"]["edges"] == box.edge_count and rep["shapes"]["B"]["edges"] == tri.edge_count
    pairs = rep["edge_pairs"]
    assert len(pairs) == len(table["edges"])
    exact = [[p["exact_sign"] for p in e["triple_products"]] for e in pairs]
    np.testing.assert_array_equal(np.array(exact), table["exact"])
    assert [e["minkowski_face"]["exact"] for e in pairs] == list(table["minkowski_exact"])
    assert rep["check"]["valid"] and rep["check"]["unexplained"] == 0


def test_audit_report_text_and_rounding_warning():
    a, b = sepax.cube(), sepax.tetrahedron(0.5)
    with pytest.warns(UserWarning, match="coordinates changed when rounded to float"):
        text = sepax.audit(a, b, None, sepax.pose([1.1, 0.2, 0.3], [0.9, 0.1, 0.2, 0.3]), report="text")
    assert isinstance(text, str) and "edge pair" in text.lower()
    with pytest.raises(ValueError, match="report"):
        sepax.audit(a, b, report="xml")
    with pytest.raises(ValueError, match="exact"):
        sepax.audit(a, b, number="exact", report="text")


# ---- sepax.fuzz.replay ------------------------------------------------------------------


def test_fuzz_is_an_importable_submodule():
    from sepax.fuzz import replay  # noqa: F401
    import sepax.fuzz

    assert sepax.fuzz.replay is replay


def test_replay_documented_classifications():
    # 26: "Plain float skips the pair: the feature difference is explained ... never 'tie'.  Plain double
    # measures the pair and agrees."
    r = sepax.fuzz.replay(CORPUS / "26-flat-near-parallel-skip-explained.case")
    assert r.outcome == "ok" and r.valid and r.unexplained_count == 0 and r.findings == []
    assert r.family == "flat" and r.seed == 11000974
    assert r.by_config["feature/float_plain"]["explained"] >= 1
    assert r.by_config["feature/float_plain"]["tie"] == 0
    assert r.by_config["feature/double_plain"]["explained"] == 0
    # robust configurations decide every sign exactly
    for key, counts in r.by_config.items():
        if key.startswith(("arc_sign/", "minkowski_face/", "overlap/")) and "robust" in key:
            assert counts["explained"] == counts["unexplained"] == 0, key
    # the case's shapes come back as (vertices, faces)
    va, fa = r.a
    assert va.shape == (3, 3) and sorted(map(sorted, fa)) == [[0, 1, 2], [0, 1, 2]]
    assert sepax.Shape(*r.a).is_flat


def test_replay_rejected_cases():
    r = sepax.fuzz.replay(str(CORPUS / "invalid-inward-box.case"))
    assert r.outcome == "rejected" and not r.valid and "inward" in r.reject_reason.lower()
    assert r.comparisons == {}
    r = sepax.fuzz.replay(CORPUS / "invalid-collinear-triangle.case")
    assert r.outcome == "rejected" and r.reject_reason


def test_replay_of_a_written_case(tmp_path):
    # two unit cubes 0.5 apart (every coordinate a float): separated, every configuration agrees
    cube = [(x, y, z) for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)]
    faces = ["0 2 3 1", "4 5 7 6", "0 1 5 4", "2 6 7 3", "0 4 6 2", "1 3 7 5"]

    def shape(name, dx):
        return [f"shape {name}"] + [f"v {x + dx} {y} {z}" for x, y, z in cube] + [f"f {f}" for f in faces] + ["end"]

    path = tmp_path / "cubes.case"
    path.write_text("\n".join(["sepax-fuzz-case 1", "family written", "seed 7", *shape("A", 0), *shape("B", 2.5)]) + "\n")
    assert sepax.Shape(*sepax.fuzz.replay(path).b).vertex_count == 8
    r = sepax.fuzz.replay(path)
    assert (r.outcome, r.family, r.seed) == ("ok", "written", 7)
    assert r.comparisons["overlap"]["agree"] > 0
    assert set(r.comparisons["overlap"]) == {"agree", "exact_zero", "explained", "tie", "unexplained", "nonconvex"}
    assert sum(v for k, v in r.comparisons["overlap"].items() if k != "agree") == 0
    assert any(c.startswith("float_plain/") for c in r.configs_run)


@pytest.mark.skipif(not os.environ.get("SEPAX_CLI"), reason="SEPAX_CLI (the sepax program) not given")
@pytest.mark.parametrize("name", ["00-triangle-on-box-face.case", "26-flat-near-parallel-skip-explained.case",
                                  "33-flat-flipped-edge-axis-beats-face.case"])
def test_replay_equals_the_program(name):
    out = subprocess.run([os.environ["SEPAX_CLI"], "fuzz", "--replay", str(CORPUS / name), "--json", "--quiet"],
                         check=True, capture_output=True, text=True).stdout
    want = json.loads(out)
    r = sepax.fuzz.replay(CORPUS / name)
    assert r.comparisons == want["comparisons"]
    assert r.by_config == want["by_config"]
    assert r.unexplained_count == want["unexplained"] == 0


def test_replay_errors(tmp_path):
    missing = tmp_path / "no-such.case"
    with pytest.raises(FileNotFoundError) as e:
        sepax.fuzz.replay(missing)
    assert e.value.filename == str(missing) and str(missing) in str(e.value)
    bad = tmp_path / "bad.case"
    bad.write_text("sepax-fuzz-case 1\nshape A\nv 1 2\nend\n")
    with pytest.raises(sepax.InvalidInput) as e:
        sepax.fuzz.replay(bad)
    assert e.value.code == sepax.ErrorCode.Parse and str(bad) in str(e.value)
    with pytest.raises(IsADirectoryError) as e:
        sepax.fuzz.replay(tmp_path)  # a directory is not a case file
    assert e.value.filename == str(tmp_path)


def test_replay_path_kinds(tmp_path):
    # str, bytes and os.PathLike name the same file; the report's path is the decoded name
    case = CORPUS / "00-triangle-on-box-face.case"
    by_bytes = sepax.fuzz.replay(os.fsencode(case))
    assert by_bytes.path == str(case) and by_bytes.outcome == "ok"
    assert by_bytes.comparisons == sepax.fuzz.replay(case).comparisons
    with pytest.raises(FileNotFoundError) as e:
        sepax.fuzz.replay(os.fsencode(tmp_path / "missing.case"))
    assert e.value.filename == str(tmp_path / "missing.case")
    with pytest.raises(TypeError):
        sepax.fuzz.replay(3)
    # a libFuzzer input need not be a regular file, and an empty input is an input
    if os.path.exists("/dev/null"):
        r = sepax.fuzz.replay("/dev/null", bytes=True)
        assert r.outcome in ("ok", "rejected") and r.unexplained_count == 0
        assert repr(r).startswith("<sepax.fuzz.CaseReport: '/dev/null': ")
