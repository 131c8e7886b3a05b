// sepax_bullet_scenes: headless Bullet scenes, each run with Bullet's default
// collision algorithms and with sepax's (sepax::bullet), same world settings,
// 60 Hz fixed steps.  docs/bullet.md describes the scenes and the metrics.
//
//   sepax_bullet_scenes [--short] [--algorithm bullet|sepax|both] [--iterations N]
//                       [--one-friction-direction] [--digest] [SCENE...]
//   scenes: stack pyramid dice plates pile slope (default: all)
//
// --digest prints, per scene and algorithm, a 64-bit FNV-1a hash of every
// body's final world transform (the bytes of its basis and origin): a change
// that must leave the simulation as it is leaves the digests the same.
//
// --short runs 0.5 s of settling and 1 s of rest (for ctest) and checks: no
// pair refused by sepax, no stack falls with sepax that stands with Bullet's
// default, sepax handled the pairs.  The
// exit status is non-zero when a check fails.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include <sepax/bullet/collision_algorithm.hpp>
#include <sepax/convex_hull.hpp>
#include <sepax/prepared_shape.hpp>

namespace {

constexpr double kDt = 1.0 / 60.0;

/// The solver settings every scene runs with, the same for both algorithms
/// (docs/bullet.md, "World settings").
struct SolverSettings {
  int iterations = 1000;
  bool two_friction_directions = true;
};
SolverSettings g_solver;

/// btCollisionDispatcher timing its narrowphase (every pair's algorithm,
/// manifold updates included).
class TimedDispatcher : public btCollisionDispatcher {
 public:
  using btCollisionDispatcher::btCollisionDispatcher;
  void dispatchAllCollisionPairs(btOverlappingPairCache* pairs, const btDispatcherInfo& info,
                                 btDispatcher* dispatcher) override {
    const auto t0 = std::chrono::steady_clock::now();
    btCollisionDispatcher::dispatchAllCollisionPairs(pairs, info, dispatcher);
    ns += std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
    ++calls;
  }
  double ns = 0;
  long calls = 0;
};

struct Body {
  btRigidBody* rb = nullptr;
  btCollisionShape* shape = nullptr;
  double mass = 0;
};

struct World {
  btDefaultCollisionConfiguration config;
  TimedDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  std::unique_ptr<sepax::bullet::CreateFunc> sepax_cf;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btDefaultMotionState>> motions;
  std::vector<std::unique_ptr<btRigidBody>> bodies_owned;
  std::vector<Body> bodies;  // dynamic bodies
  bool stack = false;        // a stack: the top body must stay standing

  explicit World(bool use_sepax) {
    world.setGravity(btVector3(0, -9.81f, 0));
    btContactSolverInfo& si = world.getSolverInfo();
    si.m_numIterations = g_solver.iterations;
    if (g_solver.two_friction_directions) {
      // Bullet's default mode has one friction direction per point: along the
      // sliding velocity, or below 3.5e-4 m/s a fixed tangent (btPlaneSpace1),
      // which leaves the other tangent frictionless at rest.
      si.m_solverMode |=
          SOLVER_USE_2_FRICTION_DIRECTIONS | SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION;
    }
    if (use_sepax) {
      sepax_cf = std::make_unique<sepax::bullet::CreateFunc>(config);
      sepax::bullet::register_algorithm(dispatcher, *sepax_cf);
    }
  }
  ~World() {
    for (auto& b : bodies_owned) world.removeRigidBody(b.get());
  }

  btCollisionShape* own(btCollisionShape* s) {
    shapes.emplace_back(s);
    return s;
  }

  btRigidBody* add(btCollisionShape* shape, double mass, const btTransform& pose, double friction = 0.5) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(static_cast<btScalar>(mass), inertia);
    motions.push_back(std::make_unique<btDefaultMotionState>(pose));
    btRigidBody::btRigidBodyConstructionInfo ci(static_cast<btScalar>(mass), motions.back().get(), shape,
                                                inertia);
    ci.m_friction = static_cast<btScalar>(friction);
    bodies_owned.push_back(std::make_unique<btRigidBody>(ci));
    btRigidBody* rb = bodies_owned.back().get();
    if (mass > 0) {
      rb->setActivationState(
          DISABLE_DEACTIVATION);  // the solver keeps working: rest is measured, not assumed
      bodies.push_back(Body{rb, shape, mass});
    }
    world.addRigidBody(rb);
    return rb;
  }

  void floor(double half, double thick) {
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(0, static_cast<btScalar>(-thick), 0));
    add(own(new btBoxShape(btVector3(static_cast<btScalar>(half), static_cast<btScalar>(thick),
                                     static_cast<btScalar>(half)))),
        0, t);
  }
};

btTransform at(double x, double y, double z, const btQuaternion& q = btQuaternion::getIdentity()) {
  btTransform t(q, btVector3(static_cast<btScalar>(x), static_cast<btScalar>(y), static_cast<btScalar>(z)));
  return t;
}

// ---- scenes ------------------------------------------------------------------------

void scene_stack(World& w) {
  w.floor(10, 0.5);
  auto* box = w.own(new btBoxShape(btVector3(0.5f, 0.5f, 0.5f)));
  for (int i = 0; i < 10; ++i) w.add(box, 1000, at(0, 0.5 + i, 0));
  w.stack = true;
}

void scene_pyramid(World& w) {
  w.floor(10, 0.5);
  auto* box = w.own(new btBoxShape(btVector3(0.5f, 0.5f, 0.5f)));
  for (int row = 0; row < 5; ++row) {
    const int n = 5 - row;
    for (int j = 0; j < n; ++j) w.add(box, 1000, at(j - (n - 1) / 2.0, 0.5 + row, 0));
  }
  w.stack = true;
}

void scene_dice(World& w) {
  w.floor(1, 0.05);
  auto* die = w.own(new btBoxShape(btVector3(0.005f, 0.005f, 0.005f)));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 16; ++i) {
    btQuaternion q(static_cast<btScalar>(u(rng)), static_cast<btScalar>(u(rng)),
                   static_cast<btScalar>(u(rng)), static_cast<btScalar>(u(rng) + 1.5));
    q.normalize();
    w.add(die, 1e-3, at((i % 4) * 0.03 - 0.045, 0.02 + 0.01 * (i % 3), (i / 4) * 0.03 - 0.045, q));
  }
}

void scene_plates(World& w) {
  w.floor(2, 0.05);
  auto* plate = w.own(new btBoxShape(btVector3(0.1f, 0.0005f, 0.1f)));
  for (int i = 0; i < 10; ++i) w.add(plate, 1000 * 0.2 * 0.001 * 0.2, at(0, 0.0005 + 0.001 * i, 0));
  w.stack = true;
}

btConvexHullShape* random_hull(std::mt19937& rng, double radius) {
  std::uniform_int_distribution<int> count(8, 64);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> s(0.6, 1.0);
  const double sx = radius * s(rng), sy = radius * s(rng), sz = radius * s(rng);
  auto* hull = new btConvexHullShape();
  const int n = count(rng);
  for (int i = 0; i < n; ++i) {
    double p[3] = {g(rng), g(rng), g(rng)};
    const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    hull->addPoint(btVector3(static_cast<btScalar>(sx * p[0] / l), static_cast<btScalar>(sy * p[1] / l),
                             static_cast<btScalar>(sz * p[2] / l)),
                   i + 1 == n);
  }
  hull->setMargin(0.005f);
  return hull;
}

void scene_pile(World& w) {
  w.floor(10, 0.5);
  std::mt19937 rng(11);
  for (int i = 0; i < 50; ++i) {
    auto* hull = static_cast<btConvexHullShape*>(w.own(random_hull(rng, 0.25)));
    const double x = (i % 5) * 0.6 - 1.2, z = ((i / 5) % 5) * 0.6 - 1.2, y = 0.4 + 0.6 * (i / 25);
    w.add(hull, 1000 * 0.5 * 0.25 * 0.25 * 0.25, at(x, y, z));
  }
}

void scene_slope(World& w) {
  w.floor(10, 0.5);
  // A static hull (a 24-sided prism, 4 m across, 0.5 m thick) tilted by 10
  // degrees about z; a 0.5 m box on it, friction 0.5 x 0.5 = 0.25 > tan 10°.
  auto* ramp = static_cast<btConvexHullShape*>(w.own(new btConvexHullShape()));
  for (int i = 0; i < 24; ++i) {
    const double a = 2 * M_PI * i / 24;
    for (double y : {-0.25, 0.25}) {
      ramp->addPoint(btVector3(static_cast<btScalar>(2 * std::cos(a)), static_cast<btScalar>(y),
                               static_cast<btScalar>(2 * std::sin(a))),
                     false);
    }
  }
  ramp->recalcLocalAabb();
  ramp->setMargin(0.005f);
  const btQuaternion tilt(btVector3(0, 0, 1), static_cast<btScalar>(10 * M_PI / 180));
  w.add(ramp, 0, at(0, 1.0, 0, tilt));
  auto* box = w.own(new btBoxShape(btVector3(0.25f, 0.25f, 0.25f)));
  // on the ramp's top face: 0.25 above its plane along the tilted normal
  const btVector3 n = btMatrix3x3(tilt) * btVector3(0, 1, 0);
  const btVector3 c = btVector3(0, 1.0f, 0) + n * 0.5f;
  w.add(box, 1000 * 0.125, btTransform(tilt, c));
}

struct Scene {
  const char* name;
  void (*build)(World&);
};
const Scene kScenes[] = {{"stack", scene_stack},   {"pyramid", scene_pyramid}, {"dice", scene_dice},
                         {"plates", scene_plates}, {"pile", scene_pile},       {"slope", scene_slope}};

// ---- metrics -----------------------------------------------------------------------

/// The geometry each algorithm collides (docs/bullet.md): the polyhedron
/// btPolyhedralConvexShape::getVertex gives, in double, for the penetration
/// measurement; plus the margin Bullet's GJK adds around a hull.
struct Geometry {
  std::map<const btCollisionShape*, std::unique_ptr<sepax::PreparedShape<double>>> shapes;
  const sepax::PreparedShape<double>& of(const btCollisionShape* s) {
    auto& p = shapes[s];
    if (!p) {
      const auto* poly = static_cast<const btPolyhedralConvexShape*>(s);
      std::vector<sepax::Vec3<double>> pts;
      for (int i = 0; i < poly->getNumVertices(); ++i) {
        btVector3 v;
        poly->getVertex(i, v);
        pts.emplace_back(v.x(), v.y(), v.z());
      }
      p = std::make_unique<sepax::PreparedShape<double>>(sepax::convex_hull<double>(pts));
    }
    return *p;
  }
};

sepax::RigidTransform<double> pose_of(const btTransform& t) {
  sepax::RigidTransform<double> x;
  btQuaternion q = t.getRotation();
  // re-orthonormalised in double from the quaternion (the metric's own input)
  x = sepax::RigidTransform<double>::from_quaternion(q.w(), q.x(), q.y(), q.z());
  for (int i = 0; i < 3; ++i) x.translation[i] = t.getOrigin()[i];
  return x;
}

/// The margin the algorithm in use adds to a shape's polyhedron: Bullet's
/// GJK path (btConvexConvexAlgorithm) collides a hull inflated by its
/// margin; its box-box detector and sepax collide the polyhedron itself.
double inflation(const btCollisionShape* s, bool sepax_algo) {
  if (sepax_algo || s->getShapeType() == BOX_SHAPE_PROXYTYPE) return 0;
  return s->getMargin();
}

struct Metrics {
  double max_penetration = 0;  // m, over the rest window
  double drift5 = 0, drift10 = 0;
  double ke = 0;               // mean kinetic energy per body over the last 5 s (J)
  double ke_per_mass = 0;      // the same divided by the body's mass (J/kg)
  double points_per_pair = 0;  // over the rest window
  double np_us = 0;            // narrowphase time per step
  std::uint64_t digest = 0;    // FNV-1a of the final transforms (--digest)
  bool standing = true;
  double top_fall = 0;  // the top body's displacement from its start
  sepax::bullet::Counters counters;
};

double kinetic(const btRigidBody* rb, double mass) {
  const btVector3 v = rb->getLinearVelocity();
  const btVector3 w = rb->getAngularVelocity();
  const btVector3 iw = rb->getInvInertiaTensorWorld().inverse() * w;
  return 0.5 * mass * v.length2() + 0.5 * w.dot(iw);
}

Metrics run(const Scene& sc, bool use_sepax, double settle_s, double rest_s) {
  World w(use_sepax);
  sc.build(w);
  Geometry geo;
  const int settle = static_cast<int>(std::lround(settle_s / kDt));
  const int rest = static_cast<int>(std::lround(rest_s / kDt));
  const int last5 = std::min(rest, static_cast<int>(std::lround(5 / kDt)));
  // top body: highest at the start
  std::size_t top = 0;
  for (std::size_t i = 0; i < w.bodies.size(); ++i) {
    if (w.bodies[i].rb->getWorldTransform().getOrigin().y() >
        w.bodies[top].rb->getWorldTransform().getOrigin().y())
      top = i;
  }
  const btVector3 top_start = w.bodies[top].rb->getWorldTransform().getOrigin();
  double top_width;  // the top body's horizontal size
  {
    btVector3 lo, hi;
    w.bodies[top].shape->getAabb(btTransform::getIdentity(), lo, hi);
    top_width = std::max(hi.x() - lo.x(), hi.z() - lo.z());
  }
  Metrics m;
  btVector3 p10(0, 0, 0), p5(0, 0, 0);
  double ke_sum = 0, kem_sum = 0;
  long ke_n = 0, pts = 0, pairs = 0;
  for (int step = 0; step < settle + rest; ++step) {
    w.world.stepSimulation(static_cast<btScalar>(kDt), 1, static_cast<btScalar>(kDt));
    const int r = step - settle;  // steps into the rest window
    if (r < 0) continue;
    if (r == 0) {
      // a stack's top body is the one on top at the start; elsewhere the
      // highest body when the rest window starts
      for (std::size_t i = 0; i < w.bodies.size() && !w.stack; ++i) {
        if (w.bodies[i].rb->getWorldTransform().getOrigin().y() >
            w.bodies[top].rb->getWorldTransform().getOrigin().y())
          top = i;
      }
      p10 = w.bodies[top].rb->getWorldTransform().getOrigin();
    }
    if (r == rest - last5) p5 = w.bodies[top].rb->getWorldTransform().getOrigin();
    if (r >= rest - last5) {
      for (const auto& b : w.bodies) {
        const double k = kinetic(b.rb, b.mass);
        ke_sum += k;
        kem_sum += k / b.mass;
        ++ke_n;
      }
    }
    const int nm = w.dispatcher.getNumManifolds();
    for (int i = 0; i < nm; ++i) {
      const btPersistentManifold* man = w.dispatcher.getManifoldByIndexInternal(i);
      if (man->getNumContacts() == 0) continue;
      pts += man->getNumContacts();
      ++pairs;
      if (r % 6 != 0) continue;  // penetration sampled at 10 Hz
      const auto* o0 = man->getBody0();
      const auto* o1 = man->getBody1();
      const auto& a = geo.of(o0->getCollisionShape());
      const auto& b = geo.of(o1->getCollisionShape());
      const auto res =
          sepax::sat::traversal(a, pose_of(o0->getWorldTransform()), b, pose_of(o1->getWorldTransform()));
      const double depth = -sepax::to_double(res.separation) - inflation(o0->getCollisionShape(), use_sepax) -
                           inflation(o1->getCollisionShape(), use_sepax);
      m.max_penetration = std::max(m.max_penetration, depth);
    }
  }
  const btVector3 pend = w.bodies[top].rb->getWorldTransform().getOrigin();
  m.drift10 = (pend - p10).length();
  m.drift5 = (pend - p5).length();
  m.ke = ke_n ? ke_sum / static_cast<double>(ke_n) : 0;
  m.ke_per_mass = ke_n ? kem_sum / static_cast<double>(ke_n) : 0;
  m.points_per_pair = pairs ? static_cast<double>(pts) / static_cast<double>(pairs) : 0;
  m.np_us = w.dispatcher.calls ? w.dispatcher.ns / static_cast<double>(w.dispatcher.calls) / 1000 : 0;
  m.top_fall = (pend - top_start).length();
  // standing: the top body moved sideways by less than 10% of its width and
  // sank by less than 10% of the stack's height
  const btVector3 d = pend - top_start;
  const double side = std::sqrt(d.x() * d.x() + d.z() * d.z());
  m.standing = !w.stack || (side < 0.1 * top_width && -d.y() < 0.1 * top_start.y());
  if (w.sepax_cf) m.counters = w.sepax_cf->counters();
  m.digest = 14695981039346656037ull;
  for (const auto& b : w.bodies) {
    const btTransform& t = b.rb->getWorldTransform();
    const btScalar* parts[4] = {&t.getBasis()[0][0], &t.getBasis()[1][0], &t.getBasis()[2][0],
                                &t.getOrigin()[0]};
    for (const btScalar* p : parts) {
      unsigned char bytes[3 * sizeof(btScalar)];
      std::memcpy(bytes, p, sizeof bytes);
      for (const unsigned char c : bytes) m.digest = (m.digest ^ c) * 1099511628211ull;
    }
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  bool short_mode = false;
  bool digest = false;
  std::string algo = "both";
  std::vector<std::string> names;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--short") {
      short_mode = true;
    } else if (a == "--algorithm" && i + 1 < argc) {
      algo = argv[++i];
    } else if (a == "--iterations" && i + 1 < argc) {
      g_solver.iterations = std::atoi(argv[++i]);
      if (g_solver.iterations < 1) {
        std::fprintf(stderr, "--iterations needs a positive count\n");
        return 2;
      }
    } else if (a == "--one-friction-direction") {
      g_solver.two_friction_directions = false;
    } else if (a == "--digest") {
      digest = true;
    } else if (a == "--help" || a == "-h") {
      std::printf(
          "usage: %s [--short] [--algorithm bullet|sepax|both] [--iterations N] [--one-friction-direction]\n"
          "          [--digest] [stack pyramid dice plates pile slope]\n",
          argv[0]);
      return 0;
    } else {
      names.push_back(a);
    }
  }
  if (algo != "bullet" && algo != "sepax" && algo != "both") {
    std::fprintf(stderr, "unknown --algorithm '%s' (bullet, sepax or both)\n", algo.c_str());
    return 2;
  }
  if (names.empty()) {
    for (const auto& s : kScenes) names.emplace_back(s.name);
  }
  const double settle = short_mode ? 0.5 : 3.0, rest = short_mode ? 1.0 : 10.0;
  std::printf("%-8s %-6s %12s %11s %11s %11s %12s %8s %10s %8s\n", "scene", "algo", "max_pen_mm", "drift5_mm",
              "drift10_mm", "KE_J", "KE/m_J/kg", "pts/pair", "np_us", "standing");
  int failures = 0;
  for (const auto& name : names) {
    const Scene* sc = nullptr;
    for (const auto& s : kScenes) {
      if (name == s.name) sc = &s;
    }
    if (!sc) {
      std::fprintf(stderr, "unknown scene '%s'\n", name.c_str());
      return 2;
    }
    bool bullet_standing = true;  // with --algorithm sepax: every stack must stand
    for (const bool use_sepax : {false, true}) {
      if ((use_sepax && algo == "bullet") || (!use_sepax && algo == "sepax")) continue;
      const Metrics m = run(*sc, use_sepax, settle, rest);
      if (!use_sepax) bullet_standing = m.standing;
      std::printf("%-8s %-6s %12.4f %11.4f %11.4f %11.3g %12.3g %8.2f %10.2f %8s\n", sc->name,
                  use_sepax ? "sepax" : "bullet", 1e3 * m.max_penetration, 1e3 * m.drift5, 1e3 * m.drift10,
                  m.ke, m.ke_per_mass, m.points_per_pair, m.np_us, m.standing ? "yes" : "NO");
      if (digest) std::printf("         digest: %016llx\n", static_cast<unsigned long long>(m.digest));
      if (use_sepax) {
        const auto& c = m.counters;
        std::printf(
            "         sepax: %lld queries, %lld beyond the margin, %lld culled by spheres, %lld kept apart, "
            "%lld kept faces (%lld refreshed, %lld of them reduced), "
            "%lld manifolds, %lld points, %lld id matches, %lld refused, %lld fallback pairs%s%s\n",
            static_cast<long long>(c.queries), static_cast<long long>(c.early_outs),
            static_cast<long long>(c.culled), static_cast<long long>(c.kept_apart),
            static_cast<long long>(c.kept), static_cast<long long>(c.refreshed),
            static_cast<long long>(c.reduced), static_cast<long long>(c.manifolds),
            static_cast<long long>(c.points), static_cast<long long>(c.id_matches),
            static_cast<long long>(c.errors), static_cast<long long>(c.fallback_pairs),
            c.last_error.empty() ? "" : "; last: ", c.last_error.c_str());
        if (short_mode) {
          if (c.errors != 0 || c.fallback_pairs != 0) {
            std::fprintf(stderr, "FAIL %s: sepax refused %lld queries / %lld pairs\n", sc->name,
                         static_cast<long long>(c.errors), static_cast<long long>(c.fallback_pairs));
            ++failures;
          }
          if (c.manifolds == 0) {
            std::fprintf(stderr, "FAIL %s: sepax built no manifold\n", sc->name);
            ++failures;
          }
          if (!m.standing && bullet_standing) {
            std::fprintf(stderr,
                         "FAIL %s: the stack fell with sepax, not with Bullet (top body moved %.4g m)\n",
                         sc->name, m.top_fall);
            ++failures;
          }
        }
      }
      std::fflush(stdout);
    }
  }
  return failures == 0 ? 0 : 1;
}
