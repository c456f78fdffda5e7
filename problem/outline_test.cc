#include "problem/outline.h"

#include "problem/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace axisym
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    constexpr double exact = 1e-13; // relative: integrals that are exact up to rounding
    constexpr double R1 = 0.1, R2 = 0.2;

    OutlineEdge line(const Point to, const std::string &part = "free")
    {
      OutlineEdge e;
      e.end = to, e.part = part;
      return e;
    }

    OutlineEdge arc(const Point to, const Point center, const std::string &part = "free")
    {
      OutlineEdge e;
      e.kind = OutlineEdge::Kind::arc, e.end = to, e.center = center, e.part = part;
      return e;
    }

    /// DESIGN.md 7.1: the quarter annulus R1 <= |(r, z)| <= R2, r, z >= 0.
    Outline quarter_annulus()
    {
      return Outline({R1, 0}, {line({R2, 0}, "equator"), arc({0, R2}, {0, 0}, "outer"),
                               line({0, R1}, "axis"), arc({R1, 0}, {0, 0}, "inner")});
    }

    /// The rectangle [r1, r2] x [z1, z2] (half section of a hollow cylinder).
    Outline rectangle(const double r1, const double r2, const double z1, const double z2)
    {
      return Outline({r1, z1}, {line({r2, z1}, "symmetry"), line({r2, z2}, "outer"),
                                line({r1, z2}, "end"), line({r1, z1}, "inner")});
    }

    /// Lens between two arcs of radius 0.5 with centers (0.6, 0) and (1.4, 0), vertices
    /// (1, -+0.3): the intersection of the two discs.
    constexpr double lens_d = 0.4, lens_h = 0.3, lens_R = 0.5;
    Outline lens()
    {
      return Outline({1, -lens_h}, {arc({1, lens_h}, {1 - lens_d, 0}, "right"),
                                    arc({1, -lens_h}, {1 + lens_d, 0}, "left")});
    }

    /// The rectangle [0.1, 0.3] x [0, 0.4] less a semicircular notch of radius 0.05 around
    /// (0.3, 0.2) in its right side, made of two clockwise quarter arcs.
    constexpr double notch = 0.05;
    Outline groove()
    {
      const Point c{0.3, 0.2};
      return Outline({0.1, 0}, {line({0.3, 0}), line({0.3, 0.15}),
                                arc({0.25, 0.2}, c, "notch"), arc({0.3, 0.25}, c, "notch"),
                                line({0.3, 0.4}), line({0.1, 0.4}), line({0.1, 0})});
    }

    /// The message of the InputError thrown by building the outline ("" if none is thrown).
    std::string error_of(const Point start, const std::vector<OutlineEdge> &edges,
                         const std::string &field = "geometry.outline")
    {
      try
        {
          Outline(start, edges, field);
        }
      catch (const InputError &e)
        {
          return e.what();
        }
      return "";
    }

    void expect_contains_all(const std::string &message, const std::vector<std::string> &parts)
    {
      EXPECT_FALSE(message.empty()) << "no InputError thrown";
      for (const std::string &p : parts)
        EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
    }

    void expect_point_near(const Point a, const Point b, const double tol)
    {
      EXPECT_NEAR(a.r, b.r, tol);
      EXPECT_NEAR(a.z, b.z, tol);
    }

    /// Invariants of every edge: the tangent is a unit vector and matches central differences
    /// of point_at; the points lie on the boundary; a step along the outward normal leaves
    /// the body and a step against it enters (counter-clockwise outline).
    void check_edge_frames(const Outline &o)
    {
      const double eps = 1e-6 * o.size(), h = 1e-6;
      for (std::size_t i = 0; i < o.edges().size(); ++i)
        for (const double t : {0.1, 0.5, 0.9})
          {
            SCOPED_TRACE("edge " + std::to_string(i) + ", t = " + std::to_string(t));
            const OutlineEdge &e = o.edges()[i];
            const Point p = e.point_at(t), tg = e.tangent_at(t), n = e.outward_normal_at(t);
            EXPECT_NEAR(std::hypot(tg.r, tg.z), 1.0, 1e-15);
            const Point a = e.point_at(t - h), b = e.point_at(t + h);
            const double speed = e.length(); // |dp/dt|: uniform parameterization
            EXPECT_NEAR((b.r - a.r) / (2 * h), speed * tg.r, 1e-8 * speed);
            EXPECT_NEAR((b.z - a.z) / (2 * h), speed * tg.z, 1e-8 * speed);
            EXPECT_LT(o.distance_to_boundary(p), 1e-15 * o.size());
            EXPECT_FALSE(o.contains({p.r + eps * n.r, p.z + eps * n.z}, 0.0));
            EXPECT_TRUE(o.contains({p.r - eps * n.r, p.z - eps * n.z}, 0.0));
          }
    }

    /// contains() against an independent membership test at random points of the box
    /// enlarged by 10 %; points within 1e-6 * size of the boundary (by `margin`, the signed
    /// distance-like reference, > 0 inside) are skipped.
    void check_contains(const Outline &o, const std::function<double(Point)> &margin)
    {
      const BoundingBox b = o.bounding_box();
      const double dr = 0.1 * (b.r_max - b.r_min), dz = 0.1 * (b.z_max - b.z_min);
      std::mt19937 rng(12345);
      std::uniform_real_distribution<double> ur(b.r_min - dr, b.r_max + dr),
        uz(b.z_min - dz, b.z_max + dz);
      int n_checked = 0;
      for (int k = 0; k < 4000; ++k)
        {
          const Point p{ur(rng), uz(rng)};
          const double m = margin(p);
          if (std::abs(m) < 1e-6 * o.size())
            continue;
          ++n_checked;
          EXPECT_EQ(o.contains(p, 1e-12), m > 0) << "p = (" << p.r << ", " << p.z << ")";
        }
      EXPECT_GT(n_checked, 3900);
    }
  } // namespace

  // ---------------------------------------------------------------------------------------
  // Valid sections: area, moments, bounding box, parts, containment

  TEST(Outline, QuarterAnnulusAreaMomentsAndBox)
  {
    const Outline o = quarter_annulus();
    const double area = pi * (R2 * R2 - R1 * R1) / 4;
    EXPECT_NEAR(o.signed_area(), area, exact * area);
    EXPECT_NEAR(o.moment(0, 0), area, exact * area);
    // Polar: int rho^(i+j+1) cos^i sin^j over [R1, R2] x [0, pi/2].
    const double m1 = (std::pow(R2, 3) - std::pow(R1, 3)) / 3;
    const double r2 = pi * (std::pow(R2, 4) - std::pow(R1, 4)) / 16;
    const double rz = (std::pow(R2, 4) - std::pow(R1, 4)) / 8;
    const double r3z3 = (std::pow(R2, 8) - std::pow(R1, 8)) / 96; // int cos^3 sin^3 = 1/12
    EXPECT_NEAR(o.moment(1, 0), m1, exact * m1);
    EXPECT_NEAR(o.moment(0, 1), m1, exact * m1);
    EXPECT_NEAR(o.moment(2, 0), r2, exact * r2);
    EXPECT_NEAR(o.moment(0, 2), r2, exact * r2);
    EXPECT_NEAR(o.moment(1, 1), rz, exact * rz);
    EXPECT_NEAR(o.moment(3, 3), r3z3, exact * r3z3);

    const BoundingBox b = o.bounding_box();
    EXPECT_EQ(b.r_min, 0.0);
    EXPECT_EQ(b.z_min, 0.0);
    EXPECT_NEAR(b.r_max, R2, 1e-16);
    EXPECT_NEAR(b.z_max, R2, 1e-16);
    EXPECT_NEAR(o.size(), std::sqrt(2.0) * R2, 1e-16);

    EXPECT_EQ(o.parts(), std::vector<std::string>({"equator", "outer", "axis", "inner"}));
    EXPECT_EQ(o.axis_edges(), std::vector<int>({2}));
    EXPECT_TRUE(o.edges()[2].on_axis(0.0));
    EXPECT_FALSE(o.edges()[0].on_axis(1e-3));
    EXPECT_FALSE(o.edges()[3].on_axis(1.0)); // arcs are never axis edges
    // Centers given consistently are kept bit for bit.
    EXPECT_EQ(o.edges()[1].center.r, 0.0);
    EXPECT_EQ(o.edges()[1].center.z, 0.0);
    // Edges are chained: each starts where the previous one ends.
    for (std::size_t i = 0; i < 4; ++i)
      {
        const Point s = o.edges()[i].start, e = o.edges()[(i + 3) % 4].end;
        EXPECT_EQ(s.r, e.r);
        EXPECT_EQ(s.z, e.z);
      }
  }

  TEST(Outline, QuarterAnnulusContains)
  {
    const Outline o = quarter_annulus();
    const double tol = 1e-9;
    EXPECT_TRUE(o.contains({0.1, 0.1}, tol));
    EXPECT_TRUE(o.contains({0.05, 0.1}, tol));  // ray through the vertex (0, 0.1) behind p
    EXPECT_TRUE(o.contains({0.15, 0.0}, tol));  // on the equator
    EXPECT_TRUE(o.contains({0.0, 0.15}, tol));  // on the axis
    EXPECT_TRUE(o.contains({0.1, 0.0}, tol));   // a vertex
    EXPECT_FALSE(o.contains({0.05, 0.05}, tol)); // in the box, inside the hole
    EXPECT_FALSE(o.contains({0.05, 0.0}, tol));  // ray along the equator through two vertices
    EXPECT_FALSE(o.contains({0.19, 0.19}, tol)); // in the box, beyond the outer arc
    EXPECT_FALSE(o.contains({-0.05, 0.15}, tol));
    EXPECT_FALSE(o.contains({0.15, -1e-3}, tol));
    // Just outside / inside the outer arc at 30 degrees.
    const double c = std::cos(pi / 6), s = std::sin(pi / 6);
    EXPECT_FALSE(o.contains({R2 * (1 + 1e-6) * c, R2 * (1 + 1e-6) * s}, tol));
    EXPECT_TRUE(o.contains({R2 * (1 + 1e-6) * c, R2 * (1 + 1e-6) * s}, 1e-6));
    EXPECT_TRUE(o.contains({R2 * (1 - 1e-6) * c, R2 * (1 - 1e-6) * s}, 0.0));
    check_contains(o, [](const Point p) {
      const double rho = std::hypot(p.r, p.z);
      return std::min({rho - R1, R2 - rho, p.r, p.z});
    });
  }

  TEST(Outline, RectangleAreaAndMomentsUpToDegreeSix)
  {
    const double r1 = 0.1, r2 = 0.2, z1 = 0.0, z2 = 0.15;
    const Outline o = rectangle(r1, r2, z1, z2);
    EXPECT_NEAR(o.signed_area(), (r2 - r1) * (z2 - z1), exact * 0.015);
    for (int i = 0; i <= 6; ++i)
      for (int j = 0; i + j <= 6; ++j)
        {
          const double expected = (std::pow(r2, i + 1) - std::pow(r1, i + 1)) / (i + 1) *
                                  (std::pow(z2, j + 1) - std::pow(z1, j + 1)) / (j + 1);
          EXPECT_NEAR(o.moment(i, j), expected, exact * expected) << "i = " << i << ", j = " << j;
        }
    EXPECT_EQ(o.parts(), std::vector<std::string>({"symmetry", "outer", "end", "inner"}));
    EXPECT_TRUE(o.axis_edges().empty());
    check_edge_frames(o);
  }

  TEST(Outline, LensOfTwoArcs)
  {
    const Outline o = lens();
    // Two circular segments of half-angle alpha: A = R^2 (2 alpha - sin 2 alpha).
    const double alpha = std::atan2(lens_h, lens_d);
    const double area = lens_R * lens_R * (2 * alpha - std::sin(2 * alpha));
    EXPECT_NEAR(o.signed_area(), area, exact * area);
    EXPECT_NEAR(o.moment(0, 0), area, exact * area);
    EXPECT_NEAR(o.moment(1, 0), area * 1.0, exact * area); // centroid at r = 1
    EXPECT_NEAR(o.moment(0, 1), 0.0, exact * area);
    EXPECT_NEAR(o.moment(1, 1), 0.0, exact * area);
    // int z^2 dA = int_{-h}^{h} z^2 2 (sqrt(R^2 - z^2) - d) dz, with
    // F(z) = z (2 z^2 - R^2) sqrt(R^2 - z^2) / 8 + R^4 asin(z / R) / 8 (odd in z).
    const double R = lens_R, h = lens_h;
    const double F = h * (2 * h * h - R * R) * std::sqrt(R * R - h * h) / 8 +
                     std::pow(R, 4) * std::asin(h / R) / 8;
    const double z2 = 4 * F - 4 * lens_d * h * h * h / 3;
    EXPECT_NEAR(o.moment(0, 2), z2, exact * z2);

    const BoundingBox b = o.bounding_box();
    EXPECT_NEAR(b.r_min, 0.9, 1e-15);
    EXPECT_NEAR(b.r_max, 1.1, 1e-15);
    EXPECT_NEAR(b.z_min, -0.3, 1e-15);
    EXPECT_NEAR(b.z_max, 0.3, 1e-15);

    EXPECT_TRUE(o.contains({1.0, 0.29}, 0.0));
    EXPECT_FALSE(o.contains({1.01, 0.29}, 0.0));
    EXPECT_FALSE(o.contains({0.99, 0.3}, 0.0)); // at the height of a vertex
    EXPECT_TRUE(o.contains({1.0, 0.3}, 1e-12)); // the vertex
    check_contains(o, [](const Point p) {
      return std::min(lens_R - std::hypot(p.r - (1 - lens_d), p.z),
                      lens_R - std::hypot(p.r - (1 + lens_d), p.z));
    });
    check_edge_frames(o);
  }

  TEST(Outline, GrooveWithConcaveArcs)
  {
    const Outline o = groove();
    EXPECT_NEAR(o.edges()[2].sweep(), -pi / 2, 1e-15);
    EXPECT_NEAR(o.edges()[3].sweep(), -pi / 2, 1e-15);
    const double half_disc = pi * notch * notch / 2;
    const double area = 0.2 * 0.4 - half_disc;
    EXPECT_NEAR(o.signed_area(), area, exact * area);
    // The half disc r <= 0.3 has its centroid at r = 0.3 - 4 rho / (3 pi), z = 0.2.
    const double mr = (0.3 * 0.3 - 0.1 * 0.1) / 2 * 0.4 - half_disc * (0.3 - 4 * notch / (3 * pi));
    const double mz = 0.2 * 0.4 * 0.4 / 2 - half_disc * 0.2;
    EXPECT_NEAR(o.moment(1, 0), mr, exact * mr);
    EXPECT_NEAR(o.moment(0, 1), mz, exact * mz);

    const BoundingBox b = o.bounding_box();
    EXPECT_NEAR(b.r_min, 0.1, 1e-16);
    EXPECT_NEAR(b.r_max, 0.3, 1e-16);
    EXPECT_NEAR(b.z_max, 0.4, 1e-16);

    EXPECT_FALSE(o.contains({0.27, 0.2}, 1e-9)); // in the notch
    EXPECT_FALSE(o.contains({0.3, 0.2}, 1e-9));  // the notch center
    EXPECT_TRUE(o.contains({0.24, 0.2}, 1e-9));  // ray through the notch's deepest vertex
    EXPECT_TRUE(o.contains({0.2, 0.15}, 1e-9));  // ray through the vertex (0.3, 0.15)
    EXPECT_TRUE(o.contains({0.2, 0.25}, 1e-9));
    EXPECT_FALSE(o.contains({0.35, 0.25}, 1e-9));
    // On a concave arc the outward normal points to the arc's center.
    const Point p = o.edges()[2].point_at(0.5), n = o.edges()[2].outward_normal_at(0.5);
    expect_point_near(n, {(0.3 - p.r) / notch, (0.2 - p.z) / notch}, 1e-14);
    check_contains(o, [](const Point q) {
      const double box = std::min({q.r - 0.1, 0.3 - q.r, q.z, 0.4 - q.z});
      return std::min(box, std::hypot(q.r - 0.3, q.z - 0.2) - notch);
    });
    check_edge_frames(o);
    EXPECT_EQ(o.parts(), std::vector<std::string>({"free", "notch"}));
  }

  TEST(Outline, TangentJunctionsAreSimple)
  {
    // A rectangle with a filleted corner (line - arc - line, tangent at both joints).
    const double f = 0.05;
    const Outline fillet({0.1, 0}, {line({0.25, 0}), arc({0.3, f}, {0.3 - f, f}),
                                    line({0.3, 0.2}), line({0.1, 0.2}), line({0.1, 0})});
    const double area = 0.2 * 0.2 - (f * f - pi * f * f / 4);
    EXPECT_NEAR(fillet.signed_area(), area, exact * area);
    check_edge_frames(fillet);
    // An S-curve: two arcs tangent at their joint with centers on either side; their
    // circular segments cancel, leaving the polygon area 0.12 - 0.015.
    const Outline s({0.1, 0}, {line({0.3, 0}), arc({0.35, 0.05}, {0.3, 0.05}),
                               arc({0.4, 0.1}, {0.4, 0.05}), line({0.5, 0.1}), line({0.5, 0.3}),
                               line({0.1, 0.3}), line({0.1, 0})});
    EXPECT_NEAR(s.signed_area(), 0.105, exact * 0.105);
    EXPECT_NEAR(s.moment(0, 0), 0.105, exact * 0.105);
    check_edge_frames(s);
  }

  TEST(Outline, ArcEndWithinToleranceMovesTheCenterOntoTheBisector)
  {
    const Outline o({R1, 0}, {line({R2, 0}), arc({0, R2 * (1 + 1e-8)}, {0, 0}),
                              line({0, R1}), arc({R1, 0}, {0, 0})});
    const OutlineEdge &e = o.edges()[1];
    EXPECT_NEAR(std::hypot(e.end.r - e.center.r, e.end.z - e.center.z), e.radius(), 1e-16);
    EXPECT_LT(std::hypot(e.center.r, e.center.z), 1e-8 * R2);
    const double area = pi * (R2 * R2 - R1 * R1) / 4;
    EXPECT_NEAR(o.signed_area(), area, 1e-7 * area);
  }

  // ---------------------------------------------------------------------------------------
  // Edge geometry and distances

  TEST(Outline, PointTangentAndNormalOnArcsAndLines)
  {
    const Outline o = quarter_annulus();
    const double q = std::sqrt(0.5);
    const OutlineEdge &outer = o.edges()[1], &inner = o.edges()[3], &equator = o.edges()[0],
                      &axis = o.edges()[2];
    EXPECT_NEAR(outer.radius(), R2, 1e-17);
    EXPECT_NEAR(outer.sweep(), pi / 2, 1e-15);
    EXPECT_NEAR(outer.length(), R2 * pi / 2, 1e-16);
    expect_point_near(outer.point_at(0.5), {R2 * q, R2 * q}, 1e-16);
    expect_point_near(outer.tangent_at(0.5), {-q, q}, 1e-15);
    expect_point_near(outer.outward_normal_at(0.5), {q, q}, 1e-15); // away from the origin

    EXPECT_NEAR(inner.sweep(), -pi / 2, 1e-15);
    const double th = 3 * pi / 8; // t = 0.25 from 90 degrees clockwise
    expect_point_near(inner.point_at(0.25), {R1 * std::cos(th), R1 * std::sin(th)}, 1e-16);
    expect_point_near(inner.tangent_at(0.25), {std::sin(th), -std::cos(th)}, 1e-15);
    expect_point_near(inner.outward_normal_at(0.25), {-std::cos(th), -std::sin(th)}, 1e-15);

    expect_point_near(equator.point_at(0.3), {0.13, 0}, 1e-16);
    expect_point_near(equator.tangent_at(0.3), {1, 0}, 0);
    expect_point_near(equator.outward_normal_at(0.3), {0, -1}, 0);
    expect_point_near(axis.outward_normal_at(0.5), {-1, 0}, 0);
    EXPECT_EQ(equator.radius(), 0.0);
    EXPECT_EQ(equator.sweep(), 0.0);
    check_edge_frames(o);
  }

  TEST(Outline, DistanceToBoundary)
  {
    const Outline o = quarter_annulus();
    int edge = -1;
    EXPECT_NEAR(o.distance_to_boundary({0.1, 0.1}, &edge), std::sqrt(0.02) - R1, 1e-16);
    EXPECT_EQ(edge, 3);
    EXPECT_NEAR(o.distance_to_boundary({0.01, 0.01}, &edge), R1 - std::sqrt(2e-4), 1e-16);
    EXPECT_EQ(edge, 3);
    EXPECT_NEAR(o.distance_to_boundary({0.3, 0.3}, &edge), std::sqrt(0.18) - R2, 1e-16);
    EXPECT_EQ(edge, 1);
    EXPECT_NEAR(o.distance_to_boundary({0.15, -0.05}, &edge), 0.05, 1e-16);
    EXPECT_EQ(edge, 0);
    EXPECT_NEAR(o.distance_to_boundary({-0.02, 0.13}, &edge), 0.02, 1e-16);
    EXPECT_EQ(edge, 2);
    // Beyond the outer arc's angular range the nearest arc point is its end (0.2, 0).
    EXPECT_NEAR(o.distance_to_boundary({0.25, -0.1}), std::hypot(0.05, 0.1), 1e-16);
  }

  TEST(Outline, EdgesAtVerticesAndElsewhere)
  {
    const Outline o = quarter_annulus();
    const std::vector<OutlineEdge> &e = o.edges();
    // Vertex i is the start of edge i and the end of edge i - 1 (the loop closes at 0).
    for (std::size_t i = 0; i < e.size(); ++i)
      {
        const auto [arriving, leaving] = o.edges_at(e[i].start);
        EXPECT_EQ(arriving, &e[(i + e.size() - 1) % e.size()]) << "vertex " << i;
        EXPECT_EQ(leaving, &e[i]) << "vertex " << i;
      }
    // Within point_tolerance * size() of a vertex it is that vertex; beyond, and on an
    // edge's interior, no edge arrives or leaves.
    const double tol = Outline::point_tolerance * o.size();
    EXPECT_EQ(o.edges_at({R2 + 0.5 * tol, 0.0}).first, &e[0]);
    EXPECT_EQ(o.edges_at({R2 + 2.0 * tol, 0.0}).first, nullptr);
    const auto [a, l] = o.edges_at({0.15, 0.0});
    EXPECT_EQ(a, nullptr);
    EXPECT_EQ(l, nullptr);
  }

  // ---------------------------------------------------------------------------------------
  // Invalid outlines: InputError naming the entry (edge i is geometry.outline[i + 1])

  TEST(Outline, RejectsOpenAndDegenerateOutlines)
  {
    expect_contains_all(error_of({0.1, 0}, {line({0.3, 0}), line({0.3, 0.2}), line({0.1, 0.2}),
                                            line({0.1, 0.01})}),
                        {"problem file: geometry.outline[4]", "not closed"});
    expect_contains_all(error_of({0.1, 0}, {line({0.1, 0})}),
                        {"problem file: geometry.outline", "at least 2"});
    expect_contains_all(error_of({0.1, 0}, {line({0.3, 0}), line({0.3, 0}), line({0.3, 0.2}),
                                            line({0.1, 0})}),
                        {"geometry.outline[2]", "zero length"});
    // Two lines: a 'polygon' of zero area (they overlap along their whole length).
    expect_contains_all(error_of({0.1, 0}, {line({0.2, 0}), line({0.1, 0})}),
                        {"geometry.outline[1] and geometry.outline[2]", "simple"});
    expect_contains_all(error_of({0.1, 0}, {line({0.3, NAN}), line({0.1, 0.2}), line({0.1, 0})}),
                        {"geometry.outline[1]", "not finite"});
    // The field path is the caller's.
    expect_contains_all(error_of({0.1, 0}, {line({0.2, 0}), line({0.1, 0})}, "dies[0].profile"),
                        {"dies[0].profile[1] and dies[0].profile[2]"});
  }

  TEST(Outline, RejectsSelfIntersections)
  {
    // Bow tie: edges 0 and 2 cross at (0.2, 0.1).
    expect_contains_all(error_of({0.1, 0}, {line({0.3, 0.2}), line({0.3, 0}), line({0.1, 0.2}),
                                            line({0.1, 0})}),
                        {"geometry.outline[1] and geometry.outline[3]", "(0.2, 0.1)"});
    // An arc dipping below the bottom line it does not join (crossings at r = 0.15, 0.25).
    expect_contains_all(error_of({0.1, 0}, {line({0.3, 0}), line({0.3, 0.05}),
                                            arc({0.1, 0.05}, {0.2, 0.1}), line({0.1, 0})}),
                        {"geometry.outline[1] and geometry.outline[3]"});
    // ... and touching it tangentially at (0.2, 0): touching counts.
    expect_contains_all(error_of({0.1, 0}, {line({0.3, 0}), line({0.3, 0.05}),
                                            arc({0.1, 0.05}, {0.2, 0.125}), line({0.1, 0})}),
                        {"geometry.outline[1] and geometry.outline[3]", "(0.2, "});
    // A line leaving an arc's end and crossing the arc again (consecutive edges).
    expect_contains_all(error_of({0, 0}, {line({0.3, 0}), arc({0, 0.3}, {0, 0}),
                                          line({0.35, 0.1}), line({0, 0})}),
                        {"geometry.outline[2] and geometry.outline[3]"});
    // Consecutive arcs on the circles around (0.2, 0.2) and (0.3, 0.2) of radius 0.1, joined
    // at one of their intersections and both passing the other, (0.25, 0.2 - sqrt(0.0075)).
    const double deg = pi / 180;
    const Point c1{0.2, 0.2}, c2{0.3, 0.2}, v{0.25, 0.2 + std::sqrt(0.0075)};
    const Point p{c1.r + 0.1 * std::cos(-70 * deg), c1.z + 0.1 * std::sin(-70 * deg)};
    const Point q{c2.r + 0.1 * std::cos(250 * deg), c2.z + 0.1 * std::sin(250 * deg)};
    expect_contains_all(error_of(p, {arc(v, c1), arc(q, c2), line(p)}),
                        {"geometry.outline[1] and geometry.outline[2]", "(0.25, 0.113397"});
    // Two arcs crossing: the sides of the strip [0.1, 0.2] x [0, 0.3] bulging past each other.
    expect_contains_all(error_of({0.1, 0}, {line({0.2, 0}), arc({0.2, 0.3}, {0.25, 0.15}),
                                            line({0.1, 0.3}), arc({0.1, 0}, {0.05, 0.15})}),
                        {"geometry.outline[2] and geometry.outline[4]"});
    // A line doubling back over the previous one.
    expect_contains_all(error_of({0.1, 0}, {line({0.3, 0}), line({0.2, 0}), line({0.2, 0.2}),
                                            line({0.1, 0.2}), line({0.1, 0})}),
                        {"geometry.outline[1] and geometry.outline[2]"});
    // Two arcs on one circle, there and back.
    expect_contains_all(error_of({0.2, 0}, {arc({0, 0.2}, {0, 0}), arc({0.2, 0}, {0, 0})}),
                        {"geometry.outline[1] and geometry.outline[2]"});
  }

  TEST(Outline, RejectsClockwiseLoopsAndNegativeRadii)
  {
    expect_contains_all(error_of({0.1, 0}, {line({0.1, 0.2}), line({0.3, 0.2}), line({0.3, 0}),
                                            line({0.1, 0})}),
                        {"problem file: geometry.outline:", "counter-clockwise", "-0.04"});
    expect_contains_all(error_of({0.1, 0}, {line({0.3, 0}), line({0.3, 0.2}), line({-0.1, 0.2}),
                                            line({0.1, 0})}),
                        {"geometry.outline[3]", "(-0.1, 0.2)", "r < 0"});
    expect_contains_all(error_of({-0.1, 0}, {line({0.3, 0}), line({0.3, 0.2}), line({-0.1, 0})}),
                        {"geometry.outline[0]", "r < 0"});
    // Ends on the axis, but the arc bulges to r = 0.05 - sqrt(0.0125) < 0.
    expect_contains_all(error_of({0, 0}, {line({0.2, 0}), line({0.2, 0.2}), line({0, 0.2}),
                                          arc({0, 0}, {0.05, 0.1})}),
                        {"geometry.outline[4]", "reaches r = -0.0618"});
  }

  TEST(Outline, RejectsBadArcs)
  {
    // The outer arc's end is 5e-4 (relative) off the circle through its start.
    expect_contains_all(error_of({R1, 0}, {line({R2, 0}), arc({0, R2}, {0, 1e-4}),
                                           line({0, R1}), arc({R1, 0}, {0, 0})}),
                        {"geometry.outline[2]", "distances", "from the center"});
    // Exactly 180 degrees: the shorter way is ambiguous.
    expect_contains_all(error_of({0.2, -0.1}, {arc({0.2, 0.1}, {0.2, 0}), line({0.2, -0.1})}),
                        {"geometry.outline[1]", "180 degrees"});
    // Zero radius: the start is the center.
    expect_contains_all(error_of({0.2, 0}, {arc({0.3, 0}, {0.2, 0}), line({0.2, 0.1}),
                                            line({0.2, 0})}),
                        {"geometry.outline[1]", "zero radius"});
  }
} // namespace axisym
