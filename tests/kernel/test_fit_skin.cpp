// Skinning (The NURBS Book 10.3): make_compatible keeps the shapes; the skinned surface reproduces every
// section as its iso-curve, is periodic in u for periodic sections, reproduces linear extrusions
// exactly, is C^(q-1) across the v knots, and stays close to OCCT's BRepOffsetAPI_ThruSections.
#define BOOST_TEST_MODULE fit_skin
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <boost/test/unit_test.hpp>
#include <cmath>

#include "adaptors/occt_convert.hpp"
#include "src/core/error.hpp"
#include "src/fit/skin.hpp"
#include "support/random_geometry.hpp"

using namespace cg;

namespace {

// A random planar-ish section at height z: a random curve in x, y (|x|, |y| <= 10) lifted to z with a
// small z wobble, so consecutive sections are separated.
Curve3 random_section(test::Rng& r, double z, bool rational) {
  const int p = r.integer(1, 5);
  const Curve3 c = test::random_curve<3>(r, p, r.integer(p + 1, p + 8), rational);
  auto H = c.homogeneous_poles();
  for (Eigen::Index i = 0; i < H.cols(); ++i) H(2, i) = H(3, i) * (z + 0.1 * std::sin(3.0 * i));
  return Curve3::from_homogeneous(p, c.knots(), H);
}

// A closed star-shaped section (periodic interpolant) at height z.
Curve3 closed_section(test::Rng& r, double z) {
  const int n = r.integer(5, 14), p = r.integer(2, 5);
  PointList<3> Q;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n, rad = r.uniform(3, 6);
    Q.emplace_back(rad * std::cos(a), 0.5 * rad * std::sin(a), z);
  }
  return interpolate_closed<3>(Q, std::min(p, n - 1));
}

// Largest distance between section k (at its own parameters, mapped onto [0, 1]) and the surface's
// iso-curve at v_k, over the section's size.
double iso_curve_error(const SkinResult& s, const Curve3& section, double v) {
  double e = 0;
  const double a = section.first_param(), b = section.last_param();
  for (int i = 0; i <= 60; ++i) {
    const double u = i / 60.0;
    e = std::max(e, (s.surface.point(u, v) - section.point(a + u * (b - a))).norm());
  }
  return e / test::pole_scale(section);
}

}  // namespace

BOOST_AUTO_TEST_CASE(make_compatible_keeps_shapes) {
  test::Rng r(51);
  for (int i = 0; i < 200; ++i) {
    std::vector<Curve3> s;
    for (int k = r.integer(1, 5); k > 0; --k) s.push_back(random_section(r, k, r.coin()));
    const auto c = make_compatible(s);
    for (std::size_t k = 0; k < s.size(); ++k) {
      BOOST_TEST(c[k].knots() == c[0].knots());
      BOOST_TEST(c[k].degree() == c[0].degree());
      const double a = s[k].first_param(), b = s[k].last_param();
      for (int j = 0; j <= 20; ++j)  // knot insertion / elevation are exact up to rounding
        BOOST_TEST((c[k].point(j / 20.0) - s[k].point(a + j / 20.0 * (b - a))).norm() <=
                   1e-11 * test::pole_scale(s[k]));
    }
  }
}

BOOST_AUTO_TEST_CASE(sections_reproduced_open) {
  // The surface's iso-curves at the section parameters are the sections: exact in theory, rounding of
  // compatibility (A5.4, A5.9) and of the v interpolation (LU) in practice: 1e-10 relative.
  test::Rng r(52);
  int rational_weight_failures = 0;
  for (int i = 0; i < 150; ++i) {
    const int K = r.integer(2, 7);
    const bool rational = i % 3 == 0;
    std::vector<Curve3> s;
    double z = 0;
    for (int k = 0; k < K; ++k) s.push_back(random_section(r, z += r.uniform(2, 10), rational));
    SkinOptions opt;
    opt.degree_v = r.integer(1, 4);
    opt.method = i % 2 ? ParamMethod::ChordLength : ParamMethod::Centripetal;
    SkinResult res;
    try {
      res = skin(s, opt);
    } catch (const AlgorithmFailure&) {
      ++rational_weight_failures;  // interpolated weights went non-positive: reported, not a crash
      BOOST_TEST(rational);
      continue;
    }
    BOOST_TEST(res.surface.degree_v() == std::min(opt.degree_v, K - 1));
    BOOST_TEST(!res.surface.is_periodic_u());
    for (int k = 0; k < K; ++k)
      BOOST_TEST(iso_curve_error(res, s[static_cast<std::size_t>(k)], res.v_params[static_cast<std::size_t>(k)]) <=
                 1e-10);
  }
  BOOST_TEST_MESSAGE("rational skins rejected for non-positive weights: " << rational_weight_failures << " of 50");
  BOOST_TEST(rational_weight_failures < 50);  // random weights in [0.2, 5]: many, not all, go non-positive
}

BOOST_AUTO_TEST_CASE(sections_reproduced_periodic) {
  test::Rng r(53);
  for (int i = 0; i < 100; ++i) {
    const int K = r.integer(2, 6);
    std::vector<Curve3> s;
    double z = 0;
    for (int k = 0; k < K; ++k) s.push_back(closed_section(r, z += r.uniform(2, 10)));
    SkinOptions opt;
    opt.degree_v = 3;
    const SkinResult res = skin(s, opt);
    BOOST_TEST_REQUIRE(res.surface.is_periodic_u());
    for (int k = 0; k < K; ++k)
      BOOST_TEST(iso_curve_error(res, s[static_cast<std::size_t>(k)], res.v_params[static_cast<std::size_t>(k)]) <=
                 1e-10);
    // Closed chordwise with matching derivatives: S and S_u agree on both sides of the seam.
    const int pu = res.surface.degree_u();
    const auto open = BSplineSurface<3>::from_homogeneous(pu, res.surface.degree_v(), res.surface.knots_u(),
                                                          res.surface.knots_v(), res.surface.num_poles_u(),
                                                          res.surface.num_poles_v(), res.surface.homogeneous_poles());
    for (int j = 0; j <= 10; ++j) {
      const double v = j / 10.0;
      Eigen::Vector3d a[4], b[4];
      open.derivatives(open.first_u(), v, 1, a);
      open.derivatives(open.last_u(), v, 1, b);
      BOOST_TEST((a[0] - b[0]).norm() <= 1e-12 * 10);
      BOOST_TEST((a[2] - b[2]).norm() <= 1e-10 * std::max(1.0, a[2].norm()));  // S_u: index (1,0) = 1*2+0
    }
  }
}

BOOST_AUTO_TEST_CASE(extrusion_reproduced_exactly) {
  // Translated copies of one curve at heights z_k: chord-length v parameters are proportional to the
  // z spacing and spline interpolation reproduces linear data, so S(u, v) = C(u) + z(v) e_z with z
  // linear in v, everywhere (not only at the sections): 1e-10 relative.
  test::Rng r(54);
  for (int i = 0; i < 100; ++i) {
    const Curve3 base = random_section(r, 0.0, i % 2 == 1);
    const int K = r.integer(2, 7);
    std::vector<double> z{0.0};
    for (int k = 1; k < K; ++k) z.push_back(z.back() + r.uniform(1, 10));
    std::vector<Curve3> s;
    for (double h : z) {
      auto H = base.homogeneous_poles();
      H.row(2) += h * H.row(3);
      s.push_back(Curve3::from_homogeneous(base.degree(), base.knots(), H));
    }
    SkinOptions opt;
    opt.degree_v = r.integer(1, 5);
    const SkinResult res = skin(s, opt);
    const double a = base.first_param(), b = base.last_param();
    for (int j = 0; j < 50; ++j) {
      const double u = r.uniform(0, 1), v = r.uniform(0, 1);
      const Eigen::Vector3d expect = base.point(a + u * (b - a)) + Eigen::Vector3d(0, 0, v * z.back());
      BOOST_TEST((res.surface.point(u, v) - expect).norm() <= 1e-10 * (test::pole_scale(base) + z.back()));
    }
  }
}

BOOST_AUTO_TEST_CASE(explicit_v_params_and_smooth_iso_curves) {
  test::Rng r(55);
  for (int i = 0; i < 50; ++i) {
    const int K = r.integer(4, 7);
    std::vector<Curve3> s;
    std::vector<double> v;
    for (int k = 0; k < K; ++k) {
      s.push_back(random_section(r, 5.0 * k, false));
      v.push_back(k == 0 ? 0.0 : v.back() + r.uniform(0.5, 2.0));
    }
    SkinOptions opt;
    opt.degree_v = 3;
    opt.v_params = v;
    const SkinResult res = skin(s, opt);
    BOOST_TEST(res.v_params == v);
    BOOST_TEST(res.surface.first_v() == v.front());
    BOOST_TEST(res.surface.last_v() == v.back());
    for (int k = 0; k < K; ++k)
      BOOST_TEST(iso_curve_error(res, s[static_cast<std::size_t>(k)], v[static_cast<std::size_t>(k)]) <= 1e-10);
    // v-iso curves are C2 across the interior v knots: S_v and S_vv from both sides of a knot agree up
    // to their change over the gap 2h (h = 1e-7 of the v range), bounded by 2h times the next
    // derivative (factor 2 for its variation) plus rounding. A C1-only join would jump by O(|S_vv|).
    const auto& V = res.surface.knots_v();
    const double h = 1e-7 * (v.back() - v.front());
    for (std::size_t k = 4; k + 4 < V.size(); ++k)
      for (int j = 0; j <= 5; ++j) {
        const auto lo = res.surface.derivatives<3>(j / 5.0, V[k] - h);
        const auto hi = res.surface.derivatives<3>(j / 5.0, V[k] + h);
        const double scale = lo.S_v().norm() + lo.S_vv().norm() + lo.S_vvv().norm();
        BOOST_TEST((lo.S_v() - hi.S_v()).norm() <= 4 * h * lo.S_vv().norm() + 1e-9 * scale);
        // S_vvv itself jumps at a cubic knot: the change of S_vv is h times the sum of both sides.
        BOOST_TEST((lo.S_vv() - hi.S_vv()).norm() <= 2 * h * (lo.S_vvv().norm() + hi.S_vvv().norm()) + 1e-7 * scale);
      }
  }
}

namespace {

// Largest distance of the points c(t), t in [0, 1] (20 samples), from the chord c(0) c(1).
template <class F>
double sagitta(F&& c) {
  const Eigen::Vector3d A = c(0.0), B = c(1.0), e = (B - A).normalized();
  double s = 0;
  for (int j = 1; j < 20; ++j) {
    const Eigen::Vector3d X = c(j / 20.0) - A;
    s = std::max(s, (X - X.dot(e) * e).norm());
  }
  return s;
}

}  // namespace

BOOST_AUTO_TEST_CASE(vs_occt_thru_sections) {
  // OCCT lofts the same sections by approximation (its own v parameters and degree, 3D precision
  // 1e-6), so the surfaces agree exactly only on the sections:
  //  - on the sections: every point of our sections (our iso-curves, which reproduce the sections
  //    to rounding, see sections_reproduced_open) lies within 1e-6 of OCCT's loft (its precision);
  //  - between two sections, at a fixed u, our iso-curve and OCCT's (the straight path in OCCT's
  //    parameters between the feet of the two section points) join the same end points A and B, so
  //    a point of ours is within (our sagitta + OCCT's sagitta) of OCCT's path: both stay that close
  //    to the chord AB, and OCCT's path passes every position along it. Sagittas are measured at 20
  //    points of each curve; the loft surface is read back with occt::from_occt.
  test::Rng r(56);
  double worst_ratio = 0;
  for (int i = 0; i < 20; ++i) {
    const int K = r.integer(3, 5);
    std::vector<Curve3> s;
    BRepOffsetAPI_ThruSections loft(Standard_False, Standard_False, 1e-6);
    const int p = r.integer(2, 3);
    for (int k = 0; k < K; ++k) {
      // Smooth, similar sections (arcs of varying bulge) so both lofts are well behaved.
      const double bulge = r.uniform(1, 3), z = 4.0 * k;
      std::vector<Eigen::Vector3d> P;
      for (int j = 0; j <= p + 2; ++j) {
        const double x = -5 + 10.0 * j / (p + 2);
        P.emplace_back(x, bulge * (1 - x * x / 25) + r.uniform(-0.2, 0.2), z);
      }
      s.emplace_back(p, uniform_clamped_knots(p, static_cast<int>(P.size())), P);
      loft.AddWire(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(Handle(Geom_Curve)(occt::to_occt(s.back())))));
    }
    loft.Build();
    BOOST_TEST_REQUIRE(loft.IsDone());
    TopExp_Explorer ex(loft.Shape(), TopAbs_FACE);
    BOOST_TEST_REQUIRE(ex.More());
    const Handle(Geom_Surface) os = BRep_Tool::Surface(TopoDS::Face(ex.Current()));
    const Handle(Geom_BSplineSurface) obs = Handle(Geom_BSplineSurface)::DownCast(os);
    BOOST_TEST_REQUIRE(!obs.IsNull());
    const BSplineSurface<3> theirs = occt::from_occt(*obs);
    const SkinResult res = skin(s);
    auto foot = [&](const Eigen::Vector3d& X, double& u, double& v) {
      GeomAPI_ProjectPointOnSurf pr(gp_Pnt(X.x(), X.y(), X.z()), os);
      BOOST_TEST_REQUIRE(pr.NbPoints() > 0);
      pr.LowerDistanceParameters(u, v);
      return pr.LowerDistance();
    };
    for (int k = 0; k + 1 < K; ++k)
      for (int j = 0; j <= 10; ++j) {
        const double u = j / 10.0, v0 = res.v_params[static_cast<std::size_t>(k)], v1 = res.v_params[static_cast<std::size_t>(k + 1)];
        const Eigen::Vector3d A = res.surface.point(u, v0), B = res.surface.point(u, v1);
        double ua, va, ub, vb;
        BOOST_TEST(foot(A, ua, va) <= 1e-6);
        BOOST_TEST(foot(B, ub, vb) <= 1e-6);
        const double ours = sagitta([&](double t) { return res.surface.point(u, v0 + t * (v1 - v0)); });
        const double occt = sagitta([&](double t) { return theirs.point(ua + t * (ub - ua), va + t * (vb - va)); });
        double um, vm;
        const double gap = foot(res.surface.point(u, 0.5 * (v0 + v1)), um, vm);
        BOOST_TEST(gap <= ours + occt + 2e-6, "case " << i << " k " << k << " u " << u);
        worst_ratio = std::max(worst_ratio, gap / (ours + occt + 2e-6));
      }
  }
  BOOST_TEST_MESSAGE("largest mid-section distance from OCCT's loft over its bound: " << worst_ratio);
}

BOOST_AUTO_TEST_CASE(invalid_input) {
  test::Rng r(57);
  const Curve3 a = random_section(r, 0, false), b = random_section(r, 5, false);
  BOOST_CHECK_THROW(skin({a}), InvalidGeometry);
  BOOST_CHECK_THROW(skin({a, a}), InvalidGeometry);  // coincident sections
  SkinOptions bad;
  bad.v_params = {0.0, 0.0};
  BOOST_CHECK_THROW(skin({a, b}, bad), InvalidGeometry);
  bad.v_params = {0.0};
  BOOST_CHECK_THROW(skin({a, b}, bad), InvalidGeometry);
  BOOST_CHECK_THROW(skin({a, closed_section(r, 3)}), InvalidGeometry);  // mixed periodic / open
}
