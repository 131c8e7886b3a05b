// src/render/svg_render.cpp -- see svg_render.hpp.
#include "svg_render.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>

#include <Eigen/Geometry>

#include <sepax/plain_kernel.hpp>

namespace sepax::render {
namespace {

using V3 = Vec3<double>;

constexpr double kPanel = 480;   // panel size in px
constexpr double kMargin = 20;   // outer margin
constexpr double kTop = 56;      // title band
constexpr int kArcSamples = 48;  // polyline samples per Gauss-map arc

const char* const kColorA = "#1f5fbf";
const char* const kColorB = "#c0392b";
const char* const kColorCross = "#6a3d9a";
const char* const kColorAxis = "#111111";
const char* const kColorContact = "#e67e22";

V3 unit(const V3& v) {
  const double n = v.norm();
  return n > 0 ? V3(v / n) : V3(0, 0, 1);
}

// An orthonormal screen basis (right, up) for looking along -view.
struct Camera {
  V3 view, right, up;
  explicit Camera(const V3& toward_viewer) : view(unit(toward_viewer)) {
    const V3 helper = std::abs(view.z()) < 0.9 ? V3(0, 0, 1) : V3(1, 0, 0);
    right = unit(helper.cross(view));
    up = view.cross(right);
  }
  double x(const V3& p) const { return p.dot(right); }
  double y(const V3& p) const { return p.dot(up); }
  double depth(const V3& p) const { return p.dot(view); }
};

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629, table 3-7 of the Unicode
// standard), or 0 when the byte there does not start one.
std::size_t utf8_sequence(const std::string& s, std::size_t i) {
  const auto at = [&](std::size_t k) { return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u; };
  const unsigned b = at(0);
  const auto cont = [&](std::size_t k, unsigned lo = 0x80, unsigned hi = 0xBF) {
    return at(k) >= lo && at(k) <= hi;
  };
  if (b < 0x80) return 1;
  if (b >= 0xC2 && b <= 0xDF) return cont(1) ? 2 : 0;
  if (b >= 0xE0 && b <= 0xEF) {
    const bool second = b == 0xE0 ? cont(1, 0xA0) : b == 0xED ? cont(1, 0x80, 0x9F) : cont(1);
    return second && cont(2) ? 3 : 0;
  }
  if (b >= 0xF0 && b <= 0xF4) {
    const bool second = b == 0xF0 ? cont(1, 0x90) : b == 0xF4 ? cont(1, 0x80, 0x8F) : cont(1);
    return second && cont(2) && cont(3) ? 4 : 0;
  }
  return 0;
}

std::string escape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (const std::size_t n = utf8_sequence(s, i); n != 1) {
      // a byte that is not UTF-8 would make the file ill-formed XML: U+FFFD, the replacement character
      out += n == 0 ? std::string("\xEF\xBF\xBD") : s.substr(i, n);
      if (n > 1) i += n - 1;
      continue;
    }
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        // control characters other than tab, newline and carriage return are not allowed in XML 1.0,
        // not even as references: each becomes U+FFFD, the replacement character
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') {
          out += "\xEF\xBF\xBD";
        } else {
          out += c;
        }
    }
  }
  return out;
}

// Maps model-space screen coordinates into a panel.
struct Viewport {
  double ox, oy, scale, cx, cy;
  double px(double x) const { return ox + kPanel / 2 + (x - cx) * scale; }
  double py(double y) const { return oy + kPanel / 2 - (y - cy) * scale; }
};

// Points of the Gauss-map arc of edge e of p (normals negated when `negate`).
std::vector<V3> arc_points(const ConvexPolyhedron<double>& p, int e, bool negate) {
  const V3 n0 = unit(p.plane(p.edge_face(e, 0)).normal);
  const V3 n1 = unit(p.plane(p.edge_face(e, 1)).normal);
  V3 w;
  double theta;
  const double c = std::clamp(n0.dot(n1), -1.0, 1.0);
  if (c < -1.0 + 1e-12) {
    // double-sided polygon: half great circle through the outward edge direction
    w = unit(p.edge_direction(e).cross(n0));
    theta = std::numbers::pi;
  } else {
    w = unit(V3(n1 - c * n0));
    theta = std::acos(c);
  }
  std::vector<V3> out;
  for (int i = 0; i <= kArcSamples; ++i) {
    const double t = theta * i / kArcSamples;
    V3 q = std::cos(t) * n0 + std::sin(t) * w;
    out.push_back(negate ? V3(-q) : q);
  }
  return out;
}

void draw_shape(std::ostringstream& s, const ConvexPolyhedron<double>& p, const Camera& cam,
                const Viewport& vp, const char* color, const char* label) {
  // faces, back to front
  std::vector<std::pair<double, int>> order;
  for (int f = 0; f < p.face_count(); ++f) {
    double d = 0;
    const auto vs = p.face_vertices(f);
    for (int v : vs) d += cam.depth(p.vertex(v));
    order.emplace_back(d / static_cast<double>(vs.size()), f);
  }
  std::sort(order.begin(), order.end());
  for (const auto& [d, f] : order) {
    const bool front = p.plane(f).normal.dot(cam.view) > 0;
    if (!front && !p.is_flat()) continue;
    s << "<polygon points=\"";
    for (int v : p.face_vertices(f))
      s << fmt(vp.px(cam.x(p.vertex(v)))) << ',' << fmt(vp.py(cam.y(p.vertex(v)))) << ' ';
    s << "\" fill=\"" << color << "\" fill-opacity=\"" << (p.is_flat() ? "0.18" : "0.10")
      << "\" stroke=\"none\"/>\n";
  }
  for (int e = 0; e < p.edge_count(); ++e) {
    const bool f0 = p.plane(p.edge_face(e, 0)).normal.dot(cam.view) > 0;
    const bool f1 = p.plane(p.edge_face(e, 1)).normal.dot(cam.view) > 0;
    const bool hidden = !p.is_flat() && !f0 && !f1;
    const V3& t = p.vertex(p.edge_tail(e));
    const V3& h = p.vertex(p.edge_head(e));
    s << "<line x1=\"" << fmt(vp.px(cam.x(t))) << "\" y1=\"" << fmt(vp.py(cam.y(t))) << "\" x2=\""
      << fmt(vp.px(cam.x(h))) << "\" y2=\"" << fmt(vp.py(cam.y(h))) << "\" stroke=\"" << color
      << "\" stroke-width=\"" << (hidden ? "0.8" : "1.6") << "\""
      << (hidden ? " stroke-dasharray=\"4 3\" stroke-opacity=\"0.5\"" : "") << "/>\n";
  }
  const V3& c = p.centroid();
  s << "<text x=\"" << fmt(vp.px(cam.x(c))) << "\" y=\"" << fmt(vp.py(cam.y(c))) << "\" fill=\"" << color
    << "\" font-size=\"16\" font-weight=\"bold\" text-anchor=\"middle\">" << label << "</text>\n";
}

void draw_polyline_on_sphere(std::ostringstream& s, const std::vector<V3>& pts, const Camera& cam,
                             const Viewport& vp, const char* color, double width) {
  // split into visible (front hemisphere) and hidden runs
  std::size_t i = 0;
  while (i + 1 < pts.size()) {
    const bool front = cam.depth(pts[i]) >= 0;
    std::size_t j = i + 1;
    while (j < pts.size() && (cam.depth(pts[j]) >= 0) == front) ++j;
    const std::size_t end = std::min(j, pts.size() - 1);
    s << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\""
      << fmt(front ? width : width * 0.6) << "\""
      << (front ? "" : " stroke-opacity=\"0.25\" stroke-dasharray=\"3 3\"") << " points=\"";
    for (std::size_t k = i; k <= end; ++k)
      s << fmt(vp.px(cam.x(pts[k]))) << ',' << fmt(vp.py(cam.y(pts[k]))) << ' ';
    s << "\"/>\n";
    i = end;
    if (j >= pts.size()) break;
  }
}

void draw_dot(std::ostringstream& s, const V3& p, const Camera& cam, const Viewport& vp, const char* color,
              double r, bool on_sphere) {
  const bool front = !on_sphere || cam.depth(p) >= 0;
  s << "<circle cx=\"" << fmt(vp.px(cam.x(p))) << "\" cy=\"" << fmt(vp.py(cam.y(p))) << "\" r=\"" << fmt(r)
    << "\" fill=\"" << color << "\"" << (front ? "" : " fill-opacity=\"0.25\"") << "/>\n";
}

}  // namespace

std::string render_svg(const SvgScene& scene) {
  const auto& A = *scene.a;
  const auto& B = *scene.b;
  const auto& r = scene.sat;
  const V3 axis = unit(r.axis);
  std::ostringstream s;
  const double W = 2 * kPanel + 3 * kMargin;
  const double H = kPanel + kTop + 2 * kMargin + 40;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 "
    << W << ' ' << H << "\" font-family=\"sans-serif\">\n";
  s << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"" << kMargin << "\" y=\"28\" font-size=\"18\">" << escape(scene.title) << "</text>\n";
  {
    std::ostringstream line;
    line << (r.overlap ? "overlap" : "separated") << "  separation " << r.separation_as_double() << "  axis "
         << to_string(r.feature) << "  (" << fmt(axis.x()) << ", " << fmt(axis.y()) << ", " << fmt(axis.z())
         << ")  contacts " << scene.contacts.size();
    s << "<text x=\"" << kMargin << "\" y=\"48\" font-size=\"13\" fill=\"#444\">" << escape(line.str())
      << "</text>\n";
  }

  // ---- left panel: the shapes ----
  {
    const V3 helper = std::abs(axis.z()) < 0.9 ? V3(0, 0, 1) : V3(1, 0, 0);
    const V3 side = unit(helper.cross(axis));
    const Camera cam(V3(0.35 * axis + side + 0.45 * axis.cross(side)));
    double lo_x = std::numeric_limits<double>::max(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
    auto grow = [&](const V3& p) {
      lo_x = std::min(lo_x, cam.x(p));
      hi_x = std::max(hi_x, cam.x(p));
      lo_y = std::min(lo_y, cam.y(p));
      hi_y = std::max(hi_y, cam.y(p));
    };
    for (const auto& v : A.vertices()) grow(v);
    for (const auto& v : B.vertices()) grow(v);
    const double span = std::max({hi_x - lo_x, hi_y - lo_y, 1e-300});
    const Viewport vp{kMargin, kTop + kMargin, 0.82 * kPanel / span, (lo_x + hi_x) / 2, (lo_y + hi_y) / 2};
    s << "<rect x=\"" << kMargin << "\" y=\"" << kTop + kMargin << "\" width=\"" << kPanel << "\" height=\""
      << kPanel << "\" fill=\"#fafafa\" stroke=\"#ddd\"/>\n";
    draw_shape(s, A, cam, vp, kColorA, "A");
    draw_shape(s, B, cam, vp, kColorB, "B");
    V3 mid(0, 0, 0);
    for (const auto& c : scene.contacts) {
      draw_dot(s, c.position, cam, vp, kColorContact, 4.5, false);
      mid += c.position;
    }
    if (!scene.contacts.empty()) {
      mid /= static_cast<double>(scene.contacts.size());
      const V3 tip = mid + axis * (0.25 * span);
      s << "<line x1=\"" << fmt(vp.px(cam.x(mid))) << "\" y1=\"" << fmt(vp.py(cam.y(mid))) << "\" x2=\""
        << fmt(vp.px(cam.x(tip))) << "\" y2=\"" << fmt(vp.py(cam.y(tip))) << "\" stroke=\"" << kColorContact
        << "\" stroke-width=\"2.5\"/>\n";
    }
    s << "<text x=\"" << kMargin + 8 << "\" y=\"" << kTop + kMargin + kPanel - 10
      << "\" font-size=\"12\" fill=\"#666\">shapes (hidden edges dashed), contact points and normal</text>\n";
  }

  // ---- right panel: overlaid Gauss maps of A and -B ----
  {
    // look along the chosen axis, tilted a little so that arcs through it
    // show their curvature instead of collapsing into radial lines
    const V3 helper = std::abs(axis.z()) < 0.9 ? V3(0, 0, 1) : V3(1, 0, 0);
    const V3 side = unit(helper.cross(axis));
    const Camera cam(V3(axis + 0.45 * side + 0.25 * axis.cross(side)));
    const double ox = 2 * kMargin + kPanel, oy = kTop + kMargin;
    const Viewport vp{ox, oy, 0.44 * kPanel, 0, 0};
    s << "<rect x=\"" << ox << "\" y=\"" << oy << "\" width=\"" << kPanel << "\" height=\"" << kPanel
      << "\" fill=\"#fafafa\" stroke=\"#ddd\"/>\n";
    s << "<circle cx=\"" << fmt(vp.px(0)) << "\" cy=\"" << fmt(vp.py(0)) << "\" r=\"" << fmt(vp.scale)
      << "\" fill=\"white\" stroke=\"#999\"/>\n";
    for (int e = 0; e < A.edge_count(); ++e)
      draw_polyline_on_sphere(s, arc_points(A, e, false), cam, vp, kColorA, 1.6);
    for (int e = 0; e < B.edge_count(); ++e)
      draw_polyline_on_sphere(s, arc_points(B, e, true), cam, vp, kColorB, 1.6);
    for (int f = 0; f < A.face_count(); ++f)
      draw_dot(s, unit(A.plane(f).normal), cam, vp, kColorA, 3.5, true);
    for (int f = 0; f < B.face_count(); ++f)
      draw_dot(s, unit(V3(-B.plane(f).normal)), cam, vp, kColorB, 3.5, true);
    // Minkowski edge-edge faces: the crossings of A's arcs with -B's arcs
    PlainKernel<double> k(A, B);
    for (int ea = 0; ea < A.edge_count(); ++ea) {
      for (int eb = 0; eb < B.edge_count(); ++eb) {
        if (!k.arc_signs(ea, eb).minkowski_face() || k.edges_parallel(ea, eb)) continue;
        const V3 p = unit(k.axis(Feature::edges(ea, eb)));
        const bool front = cam.depth(p) >= 0;
        const double x = vp.px(cam.x(p)), y = vp.py(cam.y(p));
        s << "<polygon points=\"" << fmt(x) << ',' << fmt(y - 5) << ' ' << fmt(x + 5) << ',' << fmt(y) << ' '
          << fmt(x) << ',' << fmt(y + 5) << ' ' << fmt(x - 5) << ',' << fmt(y) << "\" fill=\"" << kColorCross
          << "\"" << (front ? "" : " fill-opacity=\"0.25\"") << "/>\n";
      }
    }
    // the chosen axis (on the near hemisphere by construction of the view)
    s << "<circle cx=\"" << fmt(vp.px(cam.x(axis))) << "\" cy=\"" << fmt(vp.py(cam.y(axis)))
      << "\" r=\"9\" fill=\"none\" stroke=\"" << kColorAxis << "\" stroke-width=\"2\"/>\n";
    s << "<text x=\"" << ox + 8 << "\" y=\"" << oy + kPanel - 10
      << "\" font-size=\"12\" fill=\"#666\">Gauss maps: A blue, -B red; ring: axis; "
         "diamonds: edge-edge faces of A-B</text>\n";
  }
  // legend
  const double ly = kTop + 2 * kMargin + kPanel + 16;
  s << "<text x=\"" << kMargin << "\" y=\"" << ly << "\" font-size=\"12\" fill=\"#444\">"
    << "A: " << A.vertex_count() << " vertices, " << A.face_count() << " faces"
    << (A.is_flat() ? " (double-sided)" : "") << ".  B: " << B.vertex_count() << " vertices, "
    << B.face_count() << " faces" << (B.is_flat() ? " (double-sided)" : "")
    << ".  Far hemisphere faded.</text>\n";
  s << "</svg>\n";
  return s.str();
}

}  // namespace sepax::render
