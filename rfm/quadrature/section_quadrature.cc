#include "rfm/quadrature/section_quadrature.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rfm
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    /// Terms of the power series below: for |x|, |y| <= (pi/2)^2 (sub-arcs up to 180 degrees)
    /// term k is below k 2.47^(k-1) / (2k)!, under 1e-18 from k = 12 on.
    constexpr int n_series_terms = 16;
    /// Ear clipping: areas (cross products) below this times size()^2 count as zero, so that
    /// flat vertices are not ears and vertices on a diagonal block it.
    constexpr double flat_area = 1e-14;

    using Kind = axisym::OutlineEdge::Kind;
    using Vector = Eigen::Vector2d;

    Vector vec(const axisym::Point p) { return {p.r, p.z}; }
    double cross(const Vector &a, const Vector &b) { return a.x() * b.y() - a.y() * b.x(); }

    std::string str(const double x)
    {
      std::ostringstream s;
      s.precision(9);
      s << x;
      return s.str();
    }
    std::string str(const Vector &p) { return "(" + str(p.x()) + ", " + str(p.y()) + ")"; }

    /// Polygon edge k runs from vertex k to vertex k + 1 (mod N); curved if it is a sub-arc.
    struct SubEdge
    {
      int outline_edge = 0;
      bool curved = false;
      double radius = 0, sweep = 0; ///< the sub-arc's radius and signed sweep
      Vector radial, tangential;    ///< e(theta_mid) and e(theta_mid + pi / 2)
    };

    struct ChordPolygon
    {
      std::vector<Vector> vertices;
      std::vector<SubEdge> edges;
    };

    /// Sub-arcs per outline edge (1 for lines): ceil(|sweep| / max_arc_angle), at least 2 per
    /// arc if the polygon would otherwise have fewer than 3 vertices (a lens of two arcs).
    std::vector<int> initial_pieces(const axisym::Outline &outline, const double max_arc_angle)
    {
      const std::vector<axisym::OutlineEdge> &edges = outline.edges();
      std::vector<int> n_pieces;
      int n_vertices = 0;
      for (const axisym::OutlineEdge &e : edges)
        {
          n_pieces.push_back(e.kind == Kind::line
                               ? 1
                               : std::max(1, static_cast<int>(std::ceil(std::abs(e.sweep()) /
                                                                        max_arc_angle))));
          n_vertices += n_pieces.back();
        }
      if (n_vertices < 3)
        for (std::size_t i = 0; i < edges.size(); ++i)
          if (edges[i].kind == Kind::arc)
            n_pieces[i] = std::max(n_pieces[i], 2);
      return n_pieces;
    }

    ChordPolygon chord_polygon(const axisym::Outline &outline, const std::vector<int> &n_pieces)
    {
      const std::vector<axisym::OutlineEdge> &edges = outline.edges();
      ChordPolygon polygon;
      for (std::size_t i = 0; i < edges.size(); ++i)
        {
          const axisym::OutlineEdge &e = edges[i];
          const int m = n_pieces[i];
          const double theta_0 = std::atan2(e.start.z - e.center.z, e.start.r - e.center.r);
          for (int k = 0; k < m; ++k)
            {
              polygon.vertices.push_back(vec(e.point_at(static_cast<double>(k) / m)));
              SubEdge sub;
              sub.outline_edge = static_cast<int>(i);
              if (e.kind == Kind::arc)
                {
                  sub.curved = true;
                  sub.radius = e.radius();
                  sub.sweep = e.sweep() / m;
                  const double theta_mid = theta_0 + (k + 0.5) * sub.sweep;
                  sub.radial = {std::cos(theta_mid), std::sin(theta_mid)};
                  sub.tangential = {-sub.radial.y(), sub.radial.x()};
                }
              polygon.edges.push_back(sub);
            }
        }
      return polygon;
    }

    double min_angle(const Vector &a, const Vector &b, const Vector &c)
    {
      const auto angle = [](const Vector &u, const Vector &v) {
        return std::atan2(std::abs(cross(u, v)), u.dot(v));
      };
      return std::min({angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)});
    }

    /// Ear clipping, best minimum angle first. Returns counter-clockwise triangles of vertex
    /// indices (prev, tip, next); none if some remaining polygon has no ear (not simple).
    std::vector<std::array<int, 3>> ear_clipping(const std::vector<Vector> &p, const double size)
    {
      const double tiny = flat_area * size * size;
      std::vector<int> remaining(p.size());
      for (std::size_t k = 0; k < p.size(); ++k)
        remaining[k] = static_cast<int>(k);
      std::vector<std::array<int, 3>> triangles;
      while (remaining.size() >= 3)
        {
          const int n = static_cast<int>(remaining.size());
          int best = -1;
          double best_quality = -1;
          for (int k = 0; k < n; ++k)
            {
              const int a = remaining[(k + n - 1) % n], b = remaining[k],
                        c = remaining[(k + 1) % n];
              if (!(cross(p[b] - p[a], p[c] - p[b]) > tiny))
                continue; // reflex or flat
              bool empty = true;
              for (const int q : remaining)
                if (q != a && q != b && q != c && cross(p[b] - p[a], p[q] - p[a]) >= -tiny &&
                    cross(p[c] - p[b], p[q] - p[b]) >= -tiny &&
                    cross(p[a] - p[c], p[q] - p[c]) >= -tiny)
                  {
                    empty = false;
                    break;
                  }
              const double quality = empty ? min_angle(p[a], p[b], p[c]) : -1;
              if (quality > best_quality)
                best_quality = quality, best = k;
            }
          if (best < 0)
            return {};
          triangles.push_back({remaining[(best + n - 1) % n], remaining[best],
                               remaining[(best + 1) % n]});
          remaining.erase(remaining.begin() + best);
        }
      return triangles;
    }

    /// psi(s) = phi(s) / (s (1 - s)) of a sub-arc and dpsi/ds. In the frame (e_m, t_m) at the
    /// mid angle, with a = sweep (s - 1/2), b = sweep / 2 and the entire functions
    /// C(x) = cos(sqrt x), S(x) = sin(sqrt x) / sqrt x:
    ///   phi = R [(cos a - cos b) e_m + (sin a - (a / b) sin b) t_m],
    ///   s (1 - s) = (b^2 - a^2) / sweep^2,
    ///   psi = -R sweep^2 (C[a^2, b^2] e_m + a S[a^2, b^2] t_m),
    /// with the divided differences F[x, y] = (F(x) - F(y)) / (x - y) summed as power series:
    /// (x^k - y^k) / (x - y) = h_k, h_k = x h_(k-1) + y^(k-1), exact at x = y (s = 0, 1).
    void arc_correction(const SubEdge &e, const double s, Vector &psi, Vector &dpsi)
    {
      const double alpha = e.sweep, a = alpha * (s - 0.5), x = a * a, y = 0.25 * alpha * alpha;
      double h = 0, dh = 0, y_power = 1, factorial = 1, sign = -1;
      double c = 0, dc = 0, sinc = 0, dsinc = 0; // C[x, y], d/dx C[x, y], S[x, y], d/dx S[x, y]
      for (int k = 1; k <= n_series_terms; ++k, sign = -sign)
        {
          dh = h + x * dh;
          h = x * h + y_power;
          y_power *= y;
          factorial *= (2 * k - 1) * (2 * k); // (2k)!
          c += sign * h / factorial, dc += sign * dh / factorial;
          const double odd_factorial = factorial * (2 * k + 1); // (2k + 1)!
          sinc += sign * h / odd_factorial, dsinc += sign * dh / odd_factorial;
        }
      const double scale = -e.radius * alpha * alpha, dx_ds = 2 * a * alpha;
      psi = scale * (c * e.radial + a * sinc * e.tangential);
      dpsi = scale * (dc * dx_ds * e.radial + (alpha * sinc + a * dsinc * dx_ds) * e.tangential);
    }

    /// The blending map of a (curved) triangle, see the header.
    struct CurvedTriangle
    {
      std::array<Vector, 3> vertex;
      std::array<const SubEdge *, 3> edge{}; ///< edge k: vertex k -> k + 1; null if straight

      /// X(x, y) and det dX / d(x, y).
      void map(const double x, const double y, Vector &X, double &jacobian) const
      {
        const std::array<double, 3> lambda{1 - x - y, x, y};
        static constexpr double dlambda[2][3] = {{-1, 1, 0}, {-1, 0, 1}};
        X = lambda[0] * vertex[0] + lambda[1] * vertex[1] + lambda[2] * vertex[2];
        Eigen::Matrix2d D;
        D.col(0) = vertex[1] - vertex[0];
        D.col(1) = vertex[2] - vertex[0];
        for (int k = 0; k < 3; ++k)
          if (edge[k])
            {
              const int i = k, j = (k + 1) % 3;
              Vector psi, dpsi;
              arc_correction(*edge[k], 0.5 * (1 + lambda[j] - lambda[i]), psi, dpsi);
              X += lambda[i] * lambda[j] * psi;
              for (int d = 0; d < 2; ++d)
                D.col(d) += (dlambda[d][i] * lambda[j] + lambda[i] * dlambda[d][j]) * psi +
                            (0.5 * lambda[i] * lambda[j] * (dlambda[d][j] - dlambda[d][i])) * dpsi;
            }
        jacobian = D.determinant();
      }
    };

    /// Collapsed Gauss rule on the reference triangle, on each of its 4^n_refinements
    /// sub-triangles: rows (x, y, weight), weights summing to 1/2.
    std::vector<std::array<double, 3>> reference_rule(const int n_points, const int n_refinements)
    {
      using Triangle = std::array<Vector, 3>;
      std::vector<Triangle> cells{{Vector(0, 0), Vector(1, 0), Vector(0, 1)}};
      for (int level = 0; level < n_refinements; ++level)
        {
          std::vector<Triangle> finer;
          for (const Triangle &t : cells)
            {
              const Vector m01 = 0.5 * (t[0] + t[1]), m12 = 0.5 * (t[1] + t[2]),
                           m20 = 0.5 * (t[2] + t[0]);
              finer.push_back({t[0], m01, m20});
              finer.push_back({m01, t[1], m12});
              finer.push_back({m20, m12, t[2]});
              finer.push_back({m01, m12, m20});
            }
          cells.swap(finer);
        }
      const GaussRule1D g = gauss_legendre(n_points);
      std::vector<std::array<double, 3>> rule;
      for (const Triangle &t : cells)
        {
          const Vector e1 = t[1] - t[0], e2 = t[2] - t[0];
          const double area_ratio = cross(e1, e2);
          for (int b = 0; b < n_points; ++b)
            for (int a = 0; a < n_points; ++a)
              {
                const double s = 0.5 * (1 + g.nodes[a]), u = 0.5 * (1 + g.nodes[b]);
                const Vector q = t[0] + s * (1 - u) * e1 + u * e2;
                rule.push_back({q.x(), q.y(),
                                0.25 * g.weights[a] * g.weights[b] * (1 - u) * area_ratio});
              }
        }
      return rule;
    }
  } // namespace

  void SectionQuadratureOptions::validate() const
  {
    const auto fail = [](const std::string &rule, const double value) {
      throw std::invalid_argument("SectionQuadratureOptions: Violated constraint: " + rule +
                                  " (value " + str(value) + ")");
    };
    if (n_points < 1 || n_points > max_n_points)
      fail("1 <= n_points <= " + std::to_string(max_n_points), n_points);
    if (!(max_arc_angle > 0 && max_arc_angle <= pi))
      fail("0 < max_arc_angle <= pi", max_arc_angle);
    if (n_refinements < 0 || n_refinements > max_n_refinements)
      fail("0 <= n_refinements <= " + std::to_string(max_n_refinements), n_refinements);
    if (max_arc_bisections < 0 || max_arc_bisections > max_max_arc_bisections)
      fail("0 <= max_arc_bisections <= " + std::to_string(max_max_arc_bisections),
           max_arc_bisections);
  }

  Quadrature2D section_gauss(const axisym::Outline &outline,
                             const SectionQuadratureOptions &options)
  {
    options.validate();
    const std::vector<std::array<double, 3>> rule =
      reference_rule(options.n_points, options.n_refinements);
    std::vector<int> n_pieces = initial_pieces(outline, options.max_arc_angle);
    for (int bisection = 0;; ++bisection)
      {
        const ChordPolygon polygon = chord_polygon(outline, n_pieces);
        const int N = static_cast<int>(polygon.vertices.size());
        const std::vector<std::array<int, 3>> triangles =
          ear_clipping(polygon.vertices, outline.size());
        std::vector<bool> bisect(n_pieces.size(), triangles.empty()); // no ear: all arcs
        std::string failure =
          triangles.empty() ? "ear clipping found no ear among " + std::to_string(N) +
                                " vertices: the polygon of the outline's vertices and sub-arc "
                                "points is not simple (an edge comes within a sub-arc's "
                                "sagitta of an arc)"
                            : "";

        Quadrature2D q;
        const Eigen::Index n = static_cast<Eigen::Index>(triangles.size() * rule.size());
        q.r.resize(n), q.z.resize(n), q.weights.resize(n);
        Eigen::Index node = 0;
        for (const std::array<int, 3> &v : triangles)
          {
            CurvedTriangle t;
            for (int k = 0; k < 3; ++k)
              {
                t.vertex[k] = polygon.vertices[v[k]];
                // A triangle side a -> b is polygon edge a exactly when b follows a in the
                // polygon; it is then traversed in the polygon's direction (both
                // counter-clockwise).
                const int a = v[k], b = v[(k + 1) % 3];
                if (b == (a + 1) % N && polygon.edges[a].curved)
                  t.edge[k] = &polygon.edges[a];
              }
            for (const std::array<double, 3> &ref : rule)
              {
                Vector X;
                double jacobian = 0;
                t.map(ref[0], ref[1], X, jacobian);
                if (!(jacobian > 0))
                  {
                    if (failure.empty())
                      {
                        failure = "the Jacobian of the curved triangle " + str(t.vertex[0]) +
                                  ", " + str(t.vertex[1]) + ", " + str(t.vertex[2]) +
                                  " is " + str(jacobian) + " <= 0 at " + str(X) +
                                  " (sub-arcs of";
                        for (const SubEdge *e : t.edge)
                          if (e)
                            failure += " outline edge " + std::to_string(e->outline_edge) +
                                       " (0-based): " + str(std::abs(e->sweep)) + " rad;";
                        failure += " the arc's bulge crosses the triangle)";
                      }
                    for (const SubEdge *e : t.edge)
                      if (e)
                        bisect[e->outline_edge] = true;
                    break;
                  }
                q.r[node] = X.x(), q.z[node] = X.y(), q.weights[node] = ref[2] * jacobian;
                ++node;
              }
          }
        if (failure.empty())
          return q;
        if (bisection == options.max_arc_bisections)
          throw std::invalid_argument(
            "section_gauss: " + failure + ", after " + std::to_string(bisection) +
            " automatic bisection(s) of the arcs concerned: lower max_arc_angle, or add "
            "vertices to the straight edges facing the arc (a long edge without vertices "
            "makes thin fan triangles)");
        for (std::size_t i = 0; i < n_pieces.size(); ++i)
          if (bisect[i] && outline.edges()[i].kind == Kind::arc)
            n_pieces[i] *= 2;
      }
  }

  bool is_axis_aligned_rectangle(const axisym::Outline &outline)
  {
    const axisym::BoundingBox b = outline.bounding_box();
    const double tol = 1e-12 * outline.size();
    auto on = [&](double x, double side) { return std::abs(x - side) <= tol; };
    for (const axisym::OutlineEdge &e : outline.edges())
      {
        if (e.kind != axisym::OutlineEdge::Kind::line)
          return false;
        const bool vertical = on(e.start.r, e.end.r) && (on(e.start.r, b.r_min) || on(e.start.r, b.r_max));
        const bool horizontal =
          on(e.start.z, e.end.z) && (on(e.start.z, b.z_min) || on(e.start.z, b.z_max));
        if (!vertical && !horizontal)
          return false;
      }
    return !outline.edges().empty();
  }

  Quadrature2D rectangle_gauss(const axisym::Outline &outline, const int n_points,
                               const RectangleCells &cells,
                               const std::array<std::vector<double>, 2> &extra_ends,
                               const bool even_in_r)
  {
    if (!is_axis_aligned_rectangle(outline) || n_points < 1)
      throw std::invalid_argument("rectangle_gauss: not an axis-aligned rectangle, or n_points < 1");
    const axisym::BoundingBox b = outline.bounding_box();
    // The vertices inside a side: r of those on the bottom and top, z of those on the inner
    // and outer side (not the corners: section_cells would grade toward them).
    const double tol = 1e-12 * outline.size();
    std::vector<double> r_breaks, z_breaks;
    for (const axisym::OutlineEdge &e : outline.edges())
      for (const axisym::Point &v : {e.start, e.end})
        {
          if (v.r > b.r_min + tol && v.r < b.r_max - tol)
            r_breaks.push_back(v.r);
          if (v.z > b.z_min + tol && v.z < b.z_max - tol)
            z_breaks.push_back(v.z);
        }
    // Across the side of each vertex of graded_across: the side itself as a break of its own
    // grading (section_cells grades toward a break at the interval's end from inside).
    std::array<std::vector<double>, 2> across;
    for (const axisym::Point &v : cells.graded_across)
      {
        const bool inside_r = v.r > b.r_min + tol && v.r < b.r_max - tol;
        const bool inside_z = v.z > b.z_min + tol && v.z < b.z_max - tol;
        if (inside_z && (std::abs(v.r - b.r_min) < tol || std::abs(v.r - b.r_max) < tol))
          for (const double x :
               section_cells(b.r_min, b.r_max, 1, {v.r}, cells.n_normal_layers, cells.grading_ratio))
            across[0].push_back(x);
        if (inside_r && (std::abs(v.z - b.z_min) < tol || std::abs(v.z - b.z_max) < tol))
          for (const double x :
               section_cells(b.z_min, b.z_max, 1, {v.z}, cells.n_normal_layers, cells.grading_ratio))
            across[1].push_back(x);
      }
    auto with_ends = [&](std::vector<double> ends, const int axis, double lo, double hi) {
      std::vector<double> more = extra_ends[axis];
      more.insert(more.end(), across[axis].begin(), across[axis].end());
      for (const double x : more)
        if (x > lo + tol && x < hi - tol)
          ends.push_back(x);
      std::sort(ends.begin(), ends.end());
      ends.erase(std::unique(ends.begin(), ends.end(),
                             [&](double x, double y) { return std::abs(x - y) < tol; }),
                 ends.end());
      return ends;
    };
    return tensor_gauss(with_ends(section_cells(b.r_min, b.r_max, cells.n_uniform_r, r_breaks,
                                                cells.n_graded_layers, cells.grading_ratio),
                                  0, b.r_min, b.r_max),
                        with_ends(section_cells(b.z_min, b.z_max, cells.n_uniform_z, z_breaks,
                                                cells.n_graded_layers, cells.grading_ratio),
                                  1, b.z_min, b.z_max),
                        n_points, even_in_r);
  }
} // namespace rfm
