#include "rfm/structures/outline_structures.h"

#include "problem/test_problems.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <tuple>

namespace rfm
{
  namespace
  {
    using axisym::PartCondition;

    // A section with every edge and condition kind: the sphere of DESIGN.md 7.1 (arcs,
    // the axis, a symmetry line), or a grooved solid shaft (a concave arc off the axis'
    // center, an inclined free line, a clamped end).
    axisym::Problem sphere(const nlohmann::json &outer)
    {
      nlohmann::json j = axisym::testing::thick_sphere();
      if (!outer.empty())
        j["boundary"]["outer"] = outer;
      return axisym::parse_problem(j);
    }

    axisym::Problem grooved_shaft()
    {
      return axisym::parse_problem(nlohmann::json::parse(R"({
        "geometry": {"outline": [
          {"start": [0.0, 0.0]},
          {"line_to": [0.04, 0.0], "part": "mid"},
          {"arc_to": [0.05, 0.01], "center": [0.05, 0.0], "part": "groove"},
          {"line_to": [0.05, 0.03], "part": "surface"},
          {"line_to": [0.05, 0.05], "part": "land"},
          {"line_to": [0.045, 0.08], "part": "taper"},
          {"line_to": [0.0, 0.08], "part": "end"},
          {"line_to": [0.0, 0.0], "part": "axis"}]},
        "boundary": {"mid": {"symmetry": true}, "taper": {"traction": [2.0e6, -1.0e6]},
                     "end": {"displacement": [1.0e-6, -2.0e-6]}, "surface": {"pressure": 3.0e6}},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})"));
    }

    // A stepped solid shaft for the axis parity: lines along r and z only, a pressure, a
    // normal traction, a straight chain of two collinear free/pressure edges, an end split
    // into a loaded part from the axis and a part with u_z prescribed
    // (trimmed lines along r from r = 0 and from r1 > 0).
    axisym::Problem stepped_shaft()
    {
      return axisym::parse_problem(nlohmann::json::parse(R"({
        "geometry": {"outline": [
          {"start": [0.0, 0.0]},
          {"line_to": [0.05, 0.0], "part": "mid"},
          {"line_to": [0.05, 0.1], "part": "large"},
          {"line_to": [0.03, 0.1], "part": "shoulder"},
          {"line_to": [0.03, 0.15], "part": "small"},
          {"line_to": [0.03, 0.2], "part": "small_loaded"},
          {"line_to": [0.015, 0.2], "part": "end_outer"},
          {"line_to": [0.0, 0.2], "part": "end_inner"},
          {"line_to": [0.0, 0.0], "part": "axis"}]},
        "boundary": {"mid": {"symmetry": true}, "large": {"pressure": 3.0e6},
                     "shoulder": {"traction": [0.0, 2.0e6]}, "small_loaded": {"pressure": 1.0e6},
                     "end_outer": {"displacement": [0.0, -2.0e-6]},
                     "end_inner": {"traction": [0.0, 1.0e7]}},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})"));
    }

    // A half disc split into two arcs of one circle at its top (a smooth join of two free
    // edges), heated: the ring of verification/problems/heated_ring.json.
    axisym::Problem ring()
    {
      return axisym::parse_problem(nlohmann::json::parse(R"({
        "geometry": {"outline": [
          {"start": [0.11, 0.0]},
          {"line_to": [0.19, 0.0], "part": "equator"},
          {"arc_to": [0.15, 0.04], "center": [0.15, 0.0], "part": "outer"},
          {"arc_to": [0.11, 0.0], "center": [0.15, 0.0], "part": "inner"}]},
        "boundary": {"equator": {"symmetry": true}, "inner": {"pressure": 1.0e6}},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})"));
    }

    // A 60-degree sector of a hollow sphere cut by an inclined free line: two arcs about the
    // origin, each with one end on the equator.
    axisym::Problem sector()
    {
      return axisym::parse_problem(nlohmann::json::parse(R"({
        "geometry": {"outline": [
          {"start": [0.1, 0.0]},
          {"line_to": [0.2, 0.0], "part": "equator"},
          {"arc_to": [0.1, 0.17320508075688773], "center": [0.0, 0.0], "part": "outer"},
          {"line_to": [0.05, 0.08660254037844387], "part": "cut"},
          {"arc_to": [0.1, 0.0], "center": [0.0, 0.0], "part": "inner"}]},
        "boundary": {"equator": {"symmetry": true}, "inner": {"pressure": 1.0e6}},
        "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})"));
    }

    // Random points on edge e (away from its ends), and just inside the section.
    std::vector<axisym::Point> points_on(const axisym::OutlineEdge &e, std::mt19937 &rng)
    {
      std::uniform_real_distribution<double> t(0.02, 0.98);
      std::vector<axisym::Point> p;
      for (int k = 0; k < 12; ++k)
        p.push_back(e.point_at(t(rng)));
      return p;
    }
  } // namespace

  // omega = 0 on its edge, > 0 inside, |grad omega| = 1 on the edge; gradients against
  // central differences; trimmed where the carrier runs on in the section.
  TEST(EdgeOmega, VanishesOnItsEdgeIsPositiveInsideAndNormalized)
  {
    std::mt19937 rng(7);
    for (const axisym::Problem &p : {sphere({{"pressure", 1.0}}), grooved_shaft()})
      {
        const axisym::Outline &outline = p.body->outline;
        for (int e = 0; e < static_cast<int>(outline.edges().size()); ++e)
          {
            const EdgeOmega w(outline, e);
            for (const axisym::Point &x : points_on(outline.edges()[e], rng))
              {
                EXPECT_NEAR(w(x.r, x.z).value, 0.0, 1e-15) << outline.edges()[e].part;
                // Normalized: |grad omega| = 1 just inside the edge (a trimmed omega is
                // |f| across its edge, with a kink on it).
                const axisym::OutlineEdge &edge = outline.edges()[e];
                axisym::Point n = edge.outward_normal_at(0.5);
                if (edge.kind == axisym::OutlineEdge::Kind::arc)
                  {
                    const double s_out = edge.sweep() > 0 ? 1.0 : -1.0;
                    n = {s_out * (x.r - edge.center.r) / edge.radius(),
                         s_out * (x.z - edge.center.z) / edge.radius()};
                  }
                const double h = 1e-7 * outline.size();
                const RValue v = w(x.r - h * n.r, x.z - h * n.z);
                EXPECT_NEAR(std::hypot(v.d_r, v.d_z), 1.0, 1e-5) << edge.part;
              }
            // Positive at interior points; gradient against central differences.
            std::uniform_real_distribution<double> ur(outline.bounding_box().r_min,
                                                      outline.bounding_box().r_max);
            std::uniform_real_distribution<double> uz(outline.bounding_box().z_min,
                                                      outline.bounding_box().z_max);
            int checked = 0;
            while (checked < 30)
              {
                const axisym::Point x{ur(rng), uz(rng)};
                if (!outline.contains(x, 0.0) || outline.distance_to_boundary(x) < 1e-3 * outline.size())
                  continue;
                ++checked;
                const RValue v = w(x.r, x.z);
                EXPECT_GT(v.value, 0.0) << outline.edges()[e].part;
                const double h = 1e-6;
                EXPECT_NEAR(v.d_r, (w(x.r + h, x.z).value - w(x.r - h, x.z).value) / (2 * h), 1e-6);
                EXPECT_NEAR(v.d_z, (w(x.r, x.z + h).value - w(x.r, x.z - h).value) / (2 * h), 1e-6);
              }
          }
        // The sphere's carriers never re-enter the section: all untrimmed (polynomial).
        if (outline.edges().size() == 4)
          {
            for (int e = 0; e < 4; ++e)
              EXPECT_FALSE(EdgeOmega(outline, e).trimmed()) << e;
          }
      }
    // The surface and the land share the line r = 0.05: trimmed; the groove's circle and
    // the other lines leave the shaft: untrimmed.
    const axisym::Problem shaft = grooved_shaft();
    for (int e = 0; e < 7; ++e)
      EXPECT_EQ(EdgeOmega(shaft.body->outline, e).trimmed(), e == 2 || e == 3) << e;
  }

  // Every condition holds at random boundary points for random coefficients, to 1e-12
  // relative: sigma . n = t on traction edges, sigma_rz = 0 and u . n = 0 on symmetry edges
  // and the axis, u = u_bar on displacement edges.
  // Dies with a given zone (a bilateral solve): a one-edge zone on the end face of a solid
  // cylinder (centre on the axis), a two-edge zone on the side of a shaft, and the legacy
  // cylinder's die on its outer side (centre on the mirror plane).
  std::vector<std::pair<axisym::Problem, std::vector<DieZone>>> die_cases()
  {
    std::vector<std::pair<axisym::Problem, std::vector<DieZone>>> out;
    out.emplace_back(axisym::parse_problem(axisym::testing::punched_cylinder()),
                     std::vector<DieZone>{{"top", -0.004, 0.0, 2e-5}});
    nlohmann::json shaft = axisym::testing::punched_cylinder();
    shaft["boundary"]["top"] = {{"symmetry", true}};
    shaft["boundary"]["side"]["die"] = {{"indentation", 3e-6},
                                        {"center", {0.02, 0.01}},
                                        {"profile", {{"shape", "paraboloid"}, {"radius", 0.05}}}};
    out.emplace_back(axisym::parse_problem(shaft), std::vector<DieZone>{{"side", -0.003, 0.002, 3e-6}});
    out.emplace_back(axisym::parse_problem(nlohmann::json::parse(R"({
      "geometry": {"inner_radius": 0.1, "outer_radius": 0.2, "length": 0.4},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
      "die": {"indentation": 1.0e-6}})")),
                     std::vector<DieZone>{{"outer", 0.0, 0.1, 1e-6}});
    return out;
  }

  TEST(OutlineStructures, EveryConditionHoldsForRandomCoefficients)
  {
    std::mt19937 rng(11);
    std::normal_distribution<double> coef(0.0, 1.0);
    std::vector<std::tuple<axisym::Problem, std::vector<DieZone>, bool>> cases;
    for (const axisym::Problem &p :
         {sphere({{"traction", {1.0e6, -3.0e6}}}), sphere(nlohmann::json::object()),
          grooved_shaft(), ring(), stepped_shaft()})
      cases.emplace_back(p, std::vector<DieZone>{}, false);
    cases.emplace_back(stepped_shaft(), std::vector<DieZone>{}, true); // axis parity
    for (const auto &[p, zones] : die_cases())
      cases.emplace_back(p, zones, false);
    for (const auto &[p, zones, parity] : cases)
      {
        const OutlineStructures s(*p.body, 6, zones, parity);
        const axisym::Body &body = s.body(); // split at the zones' ends
        Eigen::VectorXd q_b(s.n_boundary_columns());
        for (Eigen::Index j = 0; j < q_b.size(); ++j)
          q_b[j] = coef(rng) * 1e6;
        const double scale = 1e7; // stress scale of the loads and coefficients
        for (int e = 0; e < static_cast<int>(body.outline.edges().size()); ++e)
          {
            const axisym::OutlineEdge &edge = body.outline.edges()[e];
            const PartCondition &c = body.condition_of_edge(e);
            const std::vector<axisym::Point> pts = points_on(edge, rng);
            Eigen::VectorXd r(pts.size()), z(pts.size());
            for (std::size_t k = 0; k < pts.size(); ++k)
              r[k] = pts[k].r, z[k] = pts[k].z;
            const OutlineStressValues sv = s.stress(r, z);
            const OutlineDisplacementValues dv = s.displacement(r, z);
            for (Eigen::Index k = 0; k < r.size(); ++k)
              {
                double sigma[4];
                for (int comp = 0; comp < 4; ++comp)
                  sigma[comp] = sv.s0(k, comp) + sv.omega(k, comp) * coef(rng) * 1e6 +
                                sv.boundary[comp].row(k).dot(q_b);
                double u[2];
                for (int m = 0; m < 2; ++m)
                  u[m] = dv.u0(k, m) + dv.omega(k, m) * coef(rng) * 1e-5;
                const axisym::Point n = edge.outward_normal_at(0.5);
                // The normal at this point (arcs: radial).
                double n_r = n.r, n_z = n.z;
                if (edge.kind == axisym::OutlineEdge::Kind::arc)
                  {
                    const double s_out = edge.sweep() > 0 ? 1.0 : -1.0;
                    n_r = s_out * (r[k] - edge.center.r) / edge.radius();
                    n_z = s_out * (z[k] - edge.center.z) / edge.radius();
                  }
                const double t_r = sigma[rr] * n_r + sigma[rz] * n_z;
                const double t_z = sigma[rz] * n_r + sigma[zz] * n_z;
                switch (c.kind)
                  {
                    case PartCondition::Kind::traction_free:
                    case PartCondition::Kind::pressure:
                    case PartCondition::Kind::traction:
                      {
                        const auto t = s.prescribed_traction(e, r[k], z[k]);
                        EXPECT_NEAR(t_r, t[0], 1e-12 * scale) << edge.part;
                        EXPECT_NEAR(t_z, t[1], 1e-12 * scale) << edge.part;
                        break;
                      }
                    case PartCondition::Kind::symmetry:
                    case PartCondition::Kind::axis:
                      EXPECT_NEAR(sigma[rz], 0.0, 1e-12 * scale) << edge.part;
                      EXPECT_NEAR(u[0] * n_r + u[1] * n_z, 0.0, 1e-18) << edge.part;
                      break;
                    case PartCondition::Kind::displacement:
                      EXPECT_NEAR(u[0], c.displacement[0], 1e-18) << edge.part;
                      EXPECT_NEAR(u[1], c.displacement[1], 1e-18) << edge.part;
                      break;
                    case PartCondition::Kind::die:
                      {
                        // The zone: shear free, u.n = g0(|s|) - delta, written here from the
                        // die's frame and profile.
                        const axisym::DieCondition &die = p.body->conditions.at(edge.part).die;
                        const axisym::DieFrame f = axisym::die_frame(*p.body, edge.part);
                        const double target =
                          die.profile.gap(std::abs(f.coordinate({r[k], z[k]}))) - zones[0].indentation;
                        ASSERT_TRUE(s.in_die_zone(e));
                        EXPECT_NEAR(s.die_normal_displacement(e, r[k], z[k]), target, 1e-20);
                        EXPECT_NEAR(sigma[rz], 0.0, 1e-12 * scale) << edge.part;
                        EXPECT_NEAR(u[0] * n_r + u[1] * n_z, target, 1e-18) << edge.part;
                        break;
                      }
                    default: break;
                  }
              }
          }
      }
  }

  // Axis parity: every omega but the axis' (r) and every edge coordinate is even in r, and the
  // stress structures give even rr, zz, tt and odd rz parts, the displacement omegas an odd u_r
  // and an even u_z factor; without it the cylinders' omegas are not even. Not for arcs, dies
  // or a shear traction.
  TEST(OutlineStructures, AxisParityMakesTheStructuresEvenInR)
  {
    const axisym::Problem p = stepped_shaft();
    EXPECT_EQ(OutlineStructures::axis_parity_obstacle(*p.body), "");
    const OutlineStructures s(*p.body, 6, {}, true), plain(*p.body, 6);
    ASSERT_TRUE(s.axis_parity());
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ur(0.001, 0.03), uz(0.0, 0.2);
    Eigen::VectorXd r(40), z(40);
    for (Eigen::Index k = 0; k < r.size(); ++k)
      r[k] = ur(rng), z[k] = uz(rng);
    const Eigen::VectorXd minus_r = -r;
    bool plain_even = true;
    for (std::size_t e = 0; e < s.omegas().size(); ++e)
      {
        if (p.body->condition_of_edge(static_cast<int>(e)).kind == PartCondition::Kind::axis)
          continue;
        for (Eigen::Index k = 0; k < r.size(); ++k)
          {
            const RValue a = s.omegas()[e](r[k], z[k]), b = s.omegas()[e](-r[k], z[k]);
            EXPECT_NEAR(a.value, b.value, 1e-15) << e;
            EXPECT_NEAR(a.d_r, -b.d_r, 1e-13) << e;
            EXPECT_NEAR(a.d_z, b.d_z, 1e-13) << e;
            if (s.omegas()[e].edge().kind == axisym::OutlineEdge::Kind::line)
              {
                EXPECT_NEAR(s.omegas()[e].edge_coordinate(r[k], z[k]).value,
                            s.omegas()[e].edge_coordinate(-r[k], z[k]).value, 1e-14) << e;
              }
            plain_even &= std::abs(plain.omegas()[e](r[k], z[k]).value -
                                   plain.omegas()[e](-r[k], z[k]).value) < 1e-15;
          }
      }
    EXPECT_FALSE(plain_even);
    // The collinear pair small / small_loaded is one line for the structures (a straight
    // chain), with no boundary columns; its omega (not among omegas()) enters the stress
    // omegas, whose parity is checked below.
    EXPECT_EQ(s.n_boundary_columns(), 0);
    const OutlineStressValues a = s.stress(r, z), b = s.stress(minus_r, z);
    for (const int c : {rr, zz, tt})
      {
        EXPECT_LT((a.omega.col(c) - b.omega.col(c)).cwiseAbs().maxCoeff(), 1e-15) << c;
        EXPECT_LT((a.s0.col(c) - b.s0.col(c)).cwiseAbs().maxCoeff(), 1e-8) << c;
      }
    EXPECT_LT((a.omega.col(rz) + b.omega.col(rz)).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LT((a.s0.col(rz) + b.s0.col(rz)).cwiseAbs().maxCoeff(), 1e-8);
    const OutlineDisplacementValues u = s.displacement(r, z), v = s.displacement(minus_r, z);
    EXPECT_LT((u.omega.col(0) + v.omega.col(0)).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LT((u.omega.col(1) - v.omega.col(1)).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LT((u.u0.col(1) - v.u0.col(1)).cwiseAbs().maxCoeff(), 1e-20);

    EXPECT_NE(OutlineStructures::axis_parity_obstacle(*grooved_shaft().body), "");
    EXPECT_NE(OutlineStructures::axis_parity_obstacle(*sphere({}).body), "");
    nlohmann::json shear = nlohmann::json::parse(p.source.dump());
    shear["boundary"]["end_inner"] = {{"traction", {1.0e6, 1.0e7}}};
    EXPECT_NE(OutlineStructures::axis_parity_obstacle(*axisym::parse_problem(shear).body), "");
    EXPECT_THROW(OutlineStructures(*grooved_shaft().body, 6, {}, true), std::invalid_argument);
  }

  // The boundary columns carry the tangential normal stress of their edge: on the outer
  // arc of the sphere, sigma_ss = sum_j q_j P_j(xi) exactly.
  TEST(OutlineStructures, BoundaryColumnsCarryTheTangentialStressOfTheirEdge)
  {
    const axisym::Problem p = sphere(nlohmann::json::object());
    const OutlineStructures s(*p.body, 3);
    ASSERT_EQ(s.n_boundary_columns(), 2 * 4); // outer and inner arcs, P_0..P_3
    const axisym::OutlineEdge &outer = p.body->outline.edges()[1];
    Eigen::VectorXd r(1), z(1);
    const axisym::Point x = outer.point_at(0.3);
    r << x.r;
    z << x.z;
    const OutlineStressValues v = s.stress(r, z);
    const double xi = s.boundary_coordinate(1, x.r, x.z);
    const axisym::Point t = outer.tangent_at(0.3);
    // Column 2 (outer edge listed first among the S edges: P_2(xi)).
    const double p2 = 0.5 * (3 * xi * xi - 1);
    const double s_ss = v.boundary[rr](0, 2) * t.r * t.r + v.boundary[zz](0, 2) * t.z * t.z +
                        2 * v.boundary[rz](0, 2) * t.r * t.z;
    EXPECT_NEAR(s_ss, p2, 1e-14);
    // The inner edge's columns vanish on the outer edge.
    for (int j = 4; j < 8; ++j)
      EXPECT_NEAR(v.boundary[rr](0, j), 0.0, 1e-14);
  }

  // An arc that ends at a right angle on a symmetry line or the axis through its centre
  // continues smoothly in its mirror image, and sigma_ss is even about that end: the
  // coordinate of its boundary columns is even there (outline_structures.h, "Even ends").
  // The sphere's arcs end on the equator and the axis (both even); the sector's arcs each on
  // the equator (their other ends on the inclined cut); the grooved shaft's groove on the
  // mid-plane at its start; the shaft's inclined taper is a line and keeps its chord
  // coordinate. With the monotone coordinate of EdgeOmega the values at mirrored angles differ
  // by the full slope. (An arc whose centre is in the section, as the ring's half disc, keeps
  // it too.)
  TEST(OutlineStructures, BoundaryColumnsAreEvenAboutAMirroredArcEnd)
  {
    struct Case
    {
      axisym::Problem problem;
      int edge;
      bool start, end; // the even ends
    };
    const std::vector<Case> cases = {{sphere(nlohmann::json::object()), 1, true, true},
                                     {sphere(nlohmann::json::object()), 3, true, true},
                                     {sector(), 1, true, false},
                                     {sector(), 3, false, true},
                                     {grooved_shaft(), 1, true, false}};
    for (const Case &c : cases)
      {
        const OutlineStructures s(*c.problem.body, 4);
        const axisym::OutlineEdge &arc = c.problem.body->outline.edges()[static_cast<std::size_t>(c.edge)];
        const double radius = arc.radius(), sweep = arc.sweep();
        const double a0 = std::atan2(arc.start.z - arc.center.z, arc.start.r - arc.center.r);
        auto at = [&](const double angle) { // the coordinate at an angle from the start
          return s.boundary_coordinate(c.edge, arc.center.r + radius * std::cos(a0 + angle),
                                       arc.center.z + radius * std::sin(a0 + angle));
        };
        const double d = 0.05 * std::abs(sweep), sg = sweep > 0 ? 1.0 : -1.0;
        // Mirrored about the start, and about the end.
        if (c.start)
          EXPECT_NEAR(at(sg * d), at(-sg * d), 1e-12) << arc.part << " start";
        else
          EXPECT_GT(std::abs(at(sg * d) - at(-sg * d)), 1e-3) << arc.part << " start";
        if (c.end)
          EXPECT_NEAR(at(sweep - sg * d), at(sweep + sg * d), 1e-12) << arc.part << " end";
        else
          EXPECT_GT(std::abs(at(sweep - sg * d) - at(sweep + sg * d)), 1e-3) << arc.part << " end";
        // Monotone along the arc, within [-1, 1] on it.
        double last = at(0.0);
        EXPECT_GE(last, -1.0 - 1e-12);
        for (int k = 1; k <= 20; ++k)
          {
            const double xi = at(sweep * k / 20.0);
            EXPECT_GT(std::abs(xi - last), 0.0) << arc.part;
            EXPECT_LE(std::abs(xi), 1.0 + 1e-12) << arc.part;
            last = xi;
          }
      }
    // The ring's half disc (centre on the section) and the taper (a line): as before.
    const axisym::Problem h = ring();
    const OutlineStructures sr(*h.body, 4);
    const axisym::Point y = h.body->outline.edges()[1].point_at(0.3);
    EXPECT_EQ(sr.boundary_coordinate(1, y.r, y.z), sr.omegas()[1].edge_coordinate(y.r, y.z).value);
    const axisym::Problem g = grooved_shaft();
    const OutlineStructures s(*g.body, 4);
    const axisym::Point x = g.body->outline.edges()[4].point_at(0.3);
    EXPECT_EQ(s.boundary_coordinate(4, x.r, x.z), s.omegas()[4].edge_coordinate(x.r, x.z).value);
  }

  // Where two S edges join smoothly (the ring's arcs at (0.15, 0.04); the shaft's pressure
  // and free lines at (0.05, 0.03)) omega_T vanishes to first order, as the distance to the
  // boundary, not to second order as the product of the two edges' omegas would: the
  // stress does not vanish there. At a right-angle corner of S edges (the shaft's groove lip
  // at (0.05, 0.01)) it is the product, second order.
  TEST(OutlineStructures, OmegaOfASmoothJoinIsFirstOrder)
  {
    struct Case
    {
      axisym::Problem problem;
      axisym::Point join, inward;
      double order;
    };
    for (const Case &c : {Case{ring(), {0.15, 0.04}, {0.0, -1.0}, 1.0},
                          Case{grooved_shaft(), {0.05, 0.03}, {-1.0, 0.0}, 1.0},
                          Case{grooved_shaft(), {0.05, 0.01}, {-std::sqrt(0.5), std::sqrt(0.5)}, 2.0}})
      {
        const OutlineStructures s(*c.problem.body, 4);
        Eigen::VectorXd r(2), z(2);
        const double h = 1e-5;
        for (int k = 0; k < 2; ++k)
          r[k] = c.join.r + (k + 1) * h * c.inward.r, z[k] = c.join.z + (k + 1) * h * c.inward.z;
        const OutlineStressValues v = s.stress(r, z);
        const double ratio = v.omega(1, rr) / v.omega(0, rr);
        EXPECT_NEAR(std::log2(ratio), c.order, 0.05) << "join (" << c.join.r << ", " << c.join.z << ")";
      }
  }

  // A line split into parts with different tractions (the grooved shaft's pressed surface and
  // free land, both on r = 0.05) is one edge for the structures: the chain's omega is the
  // line's, smooth across the join, and its edges prescribe sigma_rr and sigma_rz only, with
  // no boundary columns (the groove's arc and the inclined taper keep theirs). omega_zz leaves
  // the chain out (it prescribes no sigma_zz), so omega_rr / omega_zz is the chain's factor.
  // The conjunction of the two edges' own omegas, each trimmed at the join, turns from |f| to
  // the distance to the join within about f^2 / l of the line z = 0.03 through it, and is
  // 0.59 f on that line: at 1 mm from the surface the second difference of omega_rr over 10
  // micrometres in z was 5.0e-5 of its value (3.3e-7 now: the other edges' curvature).
  TEST(OutlineStructures, AStraightChainIsOneLineForTheStructures)
  {
    const axisym::Problem p = grooved_shaft();
    const OutlineStructures s(*p.body, 4);
    EXPECT_EQ(s.n_boundary_columns(), 2 * 5);
    const double h = 1e-5, z_join = 0.03;
    Eigen::VectorXd r = Eigen::VectorXd::Constant(3, 0.049), z(3);
    z << z_join - h, z_join, z_join + h;
    const OutlineStressValues v = s.stress(r, z);
    for (Eigen::Index k = 0; k < 3; ++k)
      EXPECT_NEAR(v.omega(k, rr) / v.omega(k, zz), 0.05 - 0.049, 1e-14);
    const double second = v.omega(0, rr) - 2.0 * v.omega(1, rr) + v.omega(2, rr);
    EXPECT_LT(std::abs(second), 5e-6 * v.omega(1, rr));
  }

  // The split: a one-edge zone leaves one free sub-edge, a two-edge zone two, a zone over
  // the whole part none; the zone's sub-edge keeps the part's name.
  TEST(OutlineStructures, DieZoneSplitsItsPart)
  {
    const auto cases = die_cases();
    auto count = [](const axisym::Body &b, const std::string &part) {
      return std::count_if(b.outline.edges().begin(), b.outline.edges().end(),
                           [&](const axisym::OutlineEdge &e) { return e.part == part; });
    };
    const OutlineStructures one(*cases[0].first.body, 4, cases[0].second);
    EXPECT_EQ(count(one.body(), "top"), 1);
    EXPECT_EQ(count(one.body(), "top#free"), 1);
    const OutlineStructures two(*cases[1].first.body, 4, cases[1].second);
    EXPECT_EQ(count(two.body(), "side"), 1);
    EXPECT_EQ(count(two.body(), "side#free"), 2);
    const OutlineStructures whole(*cases[2].first.body, 4, {{"outer", 0.0, 0.2, 1e-6}});
    EXPECT_EQ(count(whole.body(), "outer"), 1);
    EXPECT_EQ(count(whole.body(), "outer#free"), 0);
    EXPECT_TRUE(whole.body().mirrored);
    // A die part without a zone, and a zone on a part without a die.
    EXPECT_THROW(OutlineStructures(*cases[0].first.body, 4), axisym::InputError);
    EXPECT_THROW(OutlineStructures(*cases[0].first.body, 4, {{"side", 0.0, 0.01, 1e-6}}),
                 std::invalid_argument);
  }

  // A zone inside its part (two free ends): its omega grows like the distance to the
  // segment along the part's line, not like s^2 / L (the trimming of an ordinary segment, 2.4
  // times the distance at the shaft's end here: for a ring die 1/100 of its part it reached
  // 40 section sizes and the force came out negative).
  TEST(OutlineStructures, AZoneInsideItsPartHasAnOmegaLikeTheDistance)
  {
    const auto cases = die_cases();
    const OutlineStructures two(*cases[1].first.body, 4, cases[1].second);
    const auto &edges = two.body().outline.edges();
    int zone = -1;
    for (int e = 0; e < static_cast<int>(edges.size()); ++e)
      if (edges[e].part == "side")
        zone = e;
    ASSERT_GE(zone, 0);
    const EdgeOmega omega(two.body().outline, zone, true);
    // The zone is z in [0.007, 0.012] on r = 0.02.
    const auto distance = [](const double r, const double z) {
      const double dz = z < 0.007 ? 0.007 - z : (z > 0.012 ? z - 0.012 : 0.0);
      return std::hypot(0.02 - r, dz);
    };
    for (const auto &[r, z] : std::vector<std::pair<double, double>>{
           {0.02, 0.0}, {0.02, 0.02}, {0.0, 0.0}, {0.01, 0.02}, {0.015, 0.0095}})
      {
        const double w = omega(r, z).value, d = distance(r, z);
        EXPECT_GT(w, 0.5 * d) << "at (" << r << ", " << z << ")";
        EXPECT_LT(w, 1.5 * d) << "at (" << r << ", " << z << ")";
      }
    // Zero on the zone, positive on the free rest of the part.
    EXPECT_NEAR(omega(0.02, 0.0095).value, 0.0, 1e-15);
    EXPECT_GT(omega(0.02, 0.005).value, 1e-3);
  }

  // A faded zone: u . n = g0(|s|) - delta on the zone, the continuation zero outside the box
  // of half size fade_end, and its gradient that of its values (central differences).
  TEST(OutlineStructures, AFadedZoneValueVanishesOutsideItsBox)
  {
    auto cases = die_cases();
    DieZone z{"side", -0.001, 0.001, 3e-6};
    z.fade_start = 0.002, z.fade_end = 0.004;
    const OutlineStructures faded(*cases[1].first.body, 4, {z});
    const OutlineStructures plain(*cases[1].first.body, 4, {DieZone{"side", -0.001, 0.001, 3e-6}});
    const auto u_r = [](const OutlineStructures &s, const double r, const double zz) {
      const OutlineDisplacementValues v =
        s.displacement(Eigen::VectorXd::Constant(1, r), Eigen::VectorXd::Constant(1, zz));
      return std::array<double, 3>{v.u0(0, 0), v.u0_r(0, 0), v.u0_z(0, 0)};
    };
    // The centre (0.02, 0.01) and a point of the zone: the outward normal is +e_r.
    const double g_half = 0.0005 * 0.0005 / (2 * 0.05);
    EXPECT_NEAR(u_r(faded, 0.02, 0.01)[0], -3e-6, 1e-18);
    EXPECT_NEAR(u_r(faded, 0.02, 0.0105)[0], g_half - 3e-6, 1e-18);
    // Beyond the box, along the part and into the body: zero (unfaded: g0 - delta there).
    EXPECT_EQ(u_r(faded, 0.02, 0.0145)[0], 0.0);
    EXPECT_EQ(u_r(faded, 0.0155, 0.01)[0], 0.0);
    EXPECT_GT(std::abs(u_r(plain, 0.02, 0.0145)[0]), 1e-4);
    // Inside the fading band.
    for (const auto &[r, zz] : std::vector<std::pair<double, double>>{
           {0.0185, 0.0128}, {0.0195, 0.0072}, {0.0172, 0.0101}})
      {
        const double h = 1e-7;
        const auto v = u_r(faded, r, zz);
        const double d_r = (u_r(faded, r + h, zz)[0] - u_r(faded, r - h, zz)[0]) / (2 * h);
        const double d_z = (u_r(faded, r, zz + h)[0] - u_r(faded, r, zz - h)[0]) / (2 * h);
        EXPECT_NEAR(v[1], d_r, 1e-6 * (std::abs(d_r) + 1e-3)) << "at (" << r << ", " << zz << ")";
        EXPECT_NEAR(v[2], d_z, 1e-6 * (std::abs(d_z) + 1e-3)) << "at (" << r << ", " << zz << ")";
      }
    // A fade that starts inside the zone is refused.
    z.fade_start = 0.0005;
    EXPECT_THROW(OutlineStructures(*cases[1].first.body, 4, {z}), std::invalid_argument);
  }

  TEST(OutlineStructures, RejectsAnInclinedSymmetryLine)
  {
    nlohmann::json j = nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.1, 0.0]}, {"line_to": [0.2, 0.0], "part": "bottom"},
        {"line_to": [0.2, 0.1], "part": "side"}, {"line_to": [0.1, 0.05], "part": "slope"},
        {"line_to": [0.1, 0.0], "part": "inner"}]},
      "boundary": {"bottom": {"symmetry": true}, "slope": {"symmetry": true}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
    const axisym::Problem p = axisym::parse_problem(j);
    EXPECT_THROW(OutlineStructures(*p.body, 2), axisym::InputError);
  }
} // namespace rfm
