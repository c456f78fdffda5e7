#include "problem/outline.h"

#include "problem/input_error.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

namespace axisym
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    using Kind = OutlineEdge::Kind;

    Point operator+(const Point a, const Point b) { return {a.r + b.r, a.z + b.z}; }
    Point operator-(const Point a, const Point b) { return {a.r - b.r, a.z - b.z}; }
    Point operator*(const double s, const Point a) { return {s * a.r, s * a.z}; }
    double dot(const Point a, const Point b) { return a.r * b.r + a.z * b.z; }
    double cross(const Point a, const Point b) { return a.r * b.z - a.z * b.r; }
    double norm(const Point a) { return std::hypot(a.r, a.z); }

    std::string str(const double x)
    {
      std::ostringstream s;
      s.precision(9);
      s << x;
      return s.str();
    }
    std::string str(const Point p) { return "(" + str(p.r) + ", " + str(p.z) + ")"; }

    /// Angle from the arc's start direction to `direction` about the center, in (-pi, pi].
    double angle_from_start(const OutlineEdge &e, const Point direction)
    {
      const Point a = e.start - e.center;
      return std::atan2(cross(a, direction), dot(a, direction));
    }

    /// Whether an angle from the start (angle_from_start) lies within the sweep, ends included.
    bool within_sweep(const double phi, const double sweep)
    {
      return sweep > 0 ? (phi >= 0 && phi <= sweep) : (phi <= 0 && phi >= sweep);
    }

    /// The arc's ends and the points where it passes the directions 0, 90, 180, 270 degrees
    /// about its center, in the order of travel. Between two consecutive points the arc stays
    /// in one quadrant: monotone in r and in z. The axis points are formed exactly (c.z + R
    /// etc.), so the half-open ray rule of contains() sees one z for them.
    std::vector<Point> arc_breaks(const OutlineEdge &e)
    {
      const double R = e.radius(), sweep = e.sweep();
      std::vector<std::pair<double, Point>> inner;
      for (const Point axis : {Point{1, 0}, Point{0, 1}, Point{-1, 0}, Point{0, -1}})
        {
          const double phi = angle_from_start(e, axis);
          if (phi * sweep > 0 && std::abs(phi) < std::abs(sweep))
            inner.emplace_back(std::abs(phi), e.center + R * axis);
        }
      std::sort(inner.begin(), inner.end(),
                [](const auto &a, const auto &b) { return a.first < b.first; });
      std::vector<Point> breaks{e.start};
      for (const auto &b : inner)
        breaks.push_back(b.second);
      breaks.push_back(e.end);
      return breaks;
    }

    double distance_to_edge(const OutlineEdge &e, const Point p) { return e.distance_to(p); }

    BoundingBox bounding_box_of(const std::vector<OutlineEdge> &edges)
    {
      BoundingBox b{edges[0].start.r, edges[0].start.r, edges[0].start.z, edges[0].start.z};
      for (const OutlineEdge &e : edges)
        for (const Point q : e.kind == Kind::arc ? arc_breaks(e) : std::vector<Point>{e.end})
          {
            b.r_min = std::min(b.r_min, q.r), b.r_max = std::max(b.r_max, q.r);
            b.z_min = std::min(b.z_min, q.z), b.z_max = std::max(b.z_max, q.z);
          }
      return b;
    }

    /// n-point Gauss-Legendre rule on [0, 1] (Newton on P_n from the Chebyshev guess).
    void gauss_legendre_01(const int n, std::vector<double> &x, std::vector<double> &w)
    {
      x.resize(n), w.resize(n);
      // P_n(xi) and P_n'(xi) by the three-term recurrence.
      const auto legendre = [n](const double xi, double &p, double &dp) {
        double p0 = 1, p1 = xi;
        for (int m = 2; m <= n; ++m)
          {
            const double p2 = ((2 * m - 1) * xi * p1 - (m - 1) * p0) / m;
            p0 = p1, p1 = p2;
          }
        p = p1;
        dp = n * (xi * p1 - p0) / (xi * xi - 1);
      };
      for (int k = 0; k < n; ++k)
        {
          double xi = std::cos(pi * (k + 0.75) / (n + 0.5)), p = 0, dp = 0;
          for (int it = 0; it < 100; ++it)
            {
              legendre(xi, p, dp);
              const double dx = p / dp;
              xi -= dx;
              if (std::abs(dx) < 1e-15)
                break;
            }
          legendre(xi, p, dp);
          x[k] = 0.5 * (1 + xi);
          w[k] = 1 / ((1 - xi * xi) * dp * dp); // 2 / ((1 - xi^2) P_n'^2), halved for [0, 1]
        }
    }

    /// Candidate points where edges a and b may meet: the ends and midpoints of both (they
    /// catch touching at an end and overlaps along a stretch) and the analytic intersections
    /// of the underlying lines and circles. `through` is a vertex shared by a and b (adjacent
    /// edges) or null: through a common point the second intersection has a closed form with
    /// no square root, which stays accurate when the edges meet tangentially there.
    std::vector<Point> meeting_candidates(const OutlineEdge &a, const OutlineEdge &b,
                                          const Point *through, const double tol)
    {
      std::vector<Point> q{a.start, a.end, a.point_at(0.5), b.start, b.end, b.point_at(0.5)};
      if (a.kind == Kind::line && b.kind == Kind::line)
        {
          // Two distinct lines through a common vertex meet only there.
          const Point d1 = a.end - a.start, d2 = b.end - b.start;
          const double den = cross(d1, d2);
          if (!through && den != 0)
            q.push_back(a.start + (cross(b.start - a.start, d2) / den) * d1);
        }
      else if (a.kind != b.kind)
        {
          const OutlineEdge &l = a.kind == Kind::line ? a : b, &c = a.kind == Kind::line ? b : a;
          const Point d = l.end - l.start;
          const double R = c.radius();
          if (through) // |V + t d - c|^2 = R^2 with |V - c| = R: t = 0 or t = -2 d.(V - c) / d.d
            q.push_back(*through + (-2 * dot(d, *through - c.center) / dot(d, d)) * d);
          else
            {
              const Point foot = l.start + (dot(c.center - l.start, d) / dot(d, d)) * d;
              const double dist = norm(foot - c.center);
              if (dist <= R + tol) // tangent within tol: h = 0, both points at the foot
                {
                  const double h = std::sqrt(std::max(0.0, (R - dist) * (R + dist)));
                  q.push_back(foot + (h / norm(d)) * d), q.push_back(foot - (h / norm(d)) * d);
                }
            }
        }
      else
        {
          const double R1 = a.radius(), R2 = b.radius();
          const Point D = b.center - a.center;
          const double d = norm(D);
          if (d <= tol && std::abs(R1 - R2) <= tol)
            return q; // one circle: arcs meet or overlap only at ends or midpoints (above)
          if (through && d > 0) // the second point: V mirrored in the line of centers
            {
              const Point foot = a.center + (dot(*through - a.center, D) / (d * d)) * D;
              q.push_back(2 * foot - *through);
            }
          else if (!through && d > tol && d <= R1 + R2 + tol && d >= std::abs(R1 - R2) - tol)
            {
              const double x = (d * d + R1 * R1 - R2 * R2) / (2 * d);
              const double h = std::sqrt(std::max(0.0, (R1 - x) * (R1 + x)));
              const Point u = (1 / d) * D, n{-u.z, u.r};
              q.push_back(a.center + x * u + h * n), q.push_back(a.center + x * u - h * n);
            }
        }
      return q;
    }
  } // namespace

  // ---------------------------------------------------------------------------------------
  // OutlineEdge

  double OutlineEdge::radius() const { return kind == Kind::arc ? norm(start - center) : 0.0; }

  double OutlineEdge::sweep() const
  {
    if (kind == Kind::line)
      return 0.0;
    const Point a = start - center, b = end - center;
    return std::atan2(cross(a, b), dot(a, b));
  }

  double OutlineEdge::distance_to(const Point p) const
  {
    if (kind == Kind::line)
      {
        const Point d = end - start;
        const double t = std::clamp(dot(p - start, d) / dot(d, d), 0.0, 1.0);
        return norm(p - (start + t * d));
      }
    if (within_sweep(angle_from_start(*this, p - center), sweep()))
      return std::abs(norm(p - center) - radius());
    return std::min(norm(p - start), norm(p - end));
  }

  double OutlineEdge::length() const
  {
    return kind == Kind::line ? norm(end - start) : radius() * std::abs(sweep());
  }

  Point OutlineEdge::point_at(const double t) const
  {
    if (t == 0)
      return start;
    if (t == 1)
      return end;
    if (kind == Kind::line)
      return start + t * (end - start);
    const double theta = std::atan2(start.z - center.z, start.r - center.r) + t * sweep();
    return center + radius() * Point{std::cos(theta), std::sin(theta)};
  }

  Point OutlineEdge::tangent_at(const double t) const
  {
    if (kind == Kind::line)
      return (1 / length()) * (end - start);
    const double s = sweep(), theta = std::atan2(start.z - center.z, start.r - center.r) + t * s;
    const double sign = s > 0 ? 1.0 : -1.0;
    return {-sign * std::sin(theta), sign * std::cos(theta)};
  }

  Point OutlineEdge::outward_normal_at(const double t) const
  {
    const Point tangent = tangent_at(t);
    return {tangent.z, -tangent.r};
  }

  bool OutlineEdge::on_axis(const double tol) const
  {
    return kind == Kind::line && std::abs(start.r) <= tol && std::abs(end.r) <= tol;
  }

  // ---------------------------------------------------------------------------------------
  // Outline: construction and validation

  Outline::Outline(const Point start, std::vector<OutlineEdge> edges, const std::string &field)
    : edges_(std::move(edges))
  {
    const int n = static_cast<int>(edges_.size());
    const auto entry = [&field](const int k) { return field + "[" + std::to_string(k) + "]"; };
    const auto fail = [](const std::string &where, const std::string &rule) {
      throw InputError("problem file: " + where + ": " + rule);
    };
    if (n < 2)
      fail(field, std::to_string(n) + " edge(s) after the start point; a closed outline needs "
                                      "at least 2");

    // 1. Chain the edges; check finiteness and r >= 0 at the vertices.
    for (int i = 0; i < n; ++i)
      edges_[i].start = i == 0 ? start : edges_[i - 1].end;
    const auto finite = [](const Point p) { return std::isfinite(p.r) && std::isfinite(p.z); };
    if (!finite(start))
      fail(entry(0), "start " + str(start) + " is not finite");
    for (int i = 0; i < n; ++i)
      if (!finite(edges_[i].end) || (edges_[i].kind == Kind::arc && !finite(edges_[i].center)))
        fail(entry(i + 1), "end " + str(edges_[i].end) + " or center is not finite");
    box_ = bounding_box_of(edges_);
    size_ = std::hypot(box_.r_max - box_.r_min, box_.z_max - box_.z_min);
    const double tiny = length_tolerance * size_, same = point_tolerance * size_;
    for (int k = 0; k <= n; ++k)
      {
        const Point p = k == 0 ? start : edges_[k - 1].end;
        if (p.r < -tiny)
          fail(entry(k), "point " + str(p) + " has r < 0 (the section lies in r >= 0)");
      }

    // 2. Closed: the last edge ends at the start point.
    if (norm(edges_.back().end - start) > same)
      fail(entry(n), "the outline is not closed: the last edge ends at " +
                       str(edges_.back().end) + ", not at the start " + str(start) +
                       " (tolerance " + str(same) + ")");
    edges_.back().end = start;

    // 3. Each edge: nonzero length; arcs: ends on one circle, under 180 degrees, in r >= 0.
    for (int i = 0; i < n; ++i)
      {
        OutlineEdge &e = edges_[i];
        const double chord = norm(e.end - e.start);
        if (!(chord > tiny))
          fail(entry(i + 1), "edge from " + str(e.start) + " to " + str(e.end) +
                               " has zero length (rule: > " + str(tiny) + ")");
        if (e.kind == Kind::line)
          continue;
        const std::string arc = "arc from " + str(e.start) + " to " + str(e.end) + " around " +
                                str(e.center);
        const double R = e.radius(), R_end = norm(e.end - e.center);
        if (!(R > tiny))
          fail(entry(i + 1), arc + " has zero radius (the start is the center)");
        if (std::abs(R_end - R) > radius_tolerance * R)
          fail(entry(i + 1), arc + ": the ends are at distances " + str(R) + " and " +
                               str(R_end) + " from the center (rule: equal within " +
                               str(radius_tolerance) + " relative)");
        const Point u = (1 / chord) * (e.end - e.start), normal{-u.z, u.r};
        const double offset = dot(e.center - e.start, normal); // center from the chord line
        if (std::abs(offset) <= radius_tolerance * R)
          fail(entry(i + 1), arc + " spans 180 degrees (the ends are diametrically opposite, "
                                   "the shorter way is ambiguous): split it into two arcs of "
                                   "less than 180 degrees");
        if (R_end != R) // not already equidistant: onto the perpendicular bisector
          e.center = 0.5 * (e.start + e.end) + offset * normal;
        const double r_least = within_sweep(angle_from_start(e, {-1, 0}), e.sweep())
                                 ? e.center.r - e.radius()
                                 : std::min(e.start.r, e.end.r);
        if (r_least < -tiny)
          fail(entry(i + 1), arc + " reaches r = " + str(r_least) +
                               " < 0 (the section lies in r >= 0)");
      }
    box_ = bounding_box_of(edges_);
    size_ = std::hypot(box_.r_max - box_.r_min, box_.z_max - box_.z_min);

    // 4. Simple: edges meet only at the vertices shared by consecutive edges (with two edges,
    // both vertices are shared).
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        {
          std::vector<Point> shared;
          if (j == i + 1)
            shared.push_back(edges_[i].end);
          if (i == 0 && j == n - 1)
            shared.push_back(edges_[0].start);
          const Point *through = shared.empty() ? nullptr : &shared[0];
          for (const Point q : meeting_candidates(edges_[i], edges_[j], through, same))
            {
              const bool at_shared = std::any_of(shared.begin(), shared.end(), [&](const Point v) {
                return norm(q - v) <= same;
              });
              if (!at_shared && distance_to_edge(edges_[i], q) <= same &&
                  distance_to_edge(edges_[j], q) <= same)
                fail(entry(i + 1) + " and " + entry(j + 1),
                     "the edges meet at " + str(q) +
                       " away from a shared vertex (the outline must be simple; touching "
                       "within " + str(same) + " counts)");
            }
        }

    // 5. Counter-clockwise.
    area_ = 0;
    for (const OutlineEdge &e : edges_)
      {
        area_ += 0.5 * cross(e.start, e.end);
        if (e.kind == Kind::arc)
          {
            const double R = e.radius(), s = e.sweep();
            area_ += 0.5 * R * R * (s - std::sin(s));
          }
      }
    if (!(area_ > 0))
      fail(field, "signed area " + str(area_) + " m^2 <= 0: the outline must run "
                                               "counter-clockwise (the body on the left)");
  }

  // ---------------------------------------------------------------------------------------
  // Outline: integrals and queries

  double Outline::moment(const int i, const int j) const
  {
    assert(i >= 0 && j >= 0);
    // int r^i z^j dr dz = oint r^(i+1) z^j / (i+1) dz (Green, counter-clockwise boundary).
    const auto integrand = [i, j](const Point p) {
      return std::pow(p.r, i + 1) * std::pow(p.z, j) / (i + 1);
    };
    std::vector<double> x_line, w_line, x_arc, w_arc;
    gauss_legendre_01((i + j + 1) / 2 + 1, x_line, w_line); // polynomial of degree i + j + 1
    gauss_legendre_01(2 * (i + j + 2) + 8, x_arc, w_arc);    // trigonometric, degree i + j + 2
    double sum = 0;
    for (const OutlineEdge &e : edges_)
      if (e.kind == Kind::line)
        {
          const Point d = e.end - e.start;
          for (std::size_t q = 0; q < x_line.size(); ++q)
            sum += w_line[q] * integrand(e.start + x_line[q] * d) * d.z;
        }
      else
        {
          const double R = e.radius(), s = e.sweep();
          const double theta0 = std::atan2(e.start.z - e.center.z, e.start.r - e.center.r);
          for (std::size_t q = 0; q < x_arc.size(); ++q)
            {
              const double theta = theta0 + x_arc[q] * s; // dz = R cos(theta) dtheta
              const Point p = e.center + R * Point{std::cos(theta), std::sin(theta)};
              sum += w_arc[q] * integrand(p) * R * std::cos(theta) * s;
            }
        }
    return sum;
  }

  bool Outline::contains(const Point p, const double tol) const
  {
    if (distance_to_boundary(p) <= tol)
      return true;
    // Winding number by crossings of the ray from p toward +r. A piece from a to b that is
    // monotone in z counts if a.z <= p.z < b.z (upward, +1) or b.z <= p.z < a.z (downward,
    // -1) and it passes the height p.z at r > p.r. The half-open rule counts a vertex on the
    // ray once and a horizontal piece never; consecutive pieces share their end bit for bit.
    int winding = 0;
    const auto cross_piece = [&](const Point a, const Point b, const auto &r_at_height) {
      const int up = (a.z <= p.z && p.z < b.z) ? 1 : (b.z <= p.z && p.z < a.z) ? -1 : 0;
      if (up != 0 && r_at_height() > p.r)
        winding += up;
    };
    for (const OutlineEdge &e : edges_)
      if (e.kind == Kind::line)
        cross_piece(e.start, e.end, [&] {
          return e.start.r + (p.z - e.start.z) * (e.end.r - e.start.r) / (e.end.z - e.start.z);
        });
      else
        {
          const std::vector<Point> breaks = arc_breaks(e);
          const double R = e.radius(), dz = p.z - e.center.z;
          for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
            {
              // Within a quadrant the piece is on one side of the vertical through the center.
              const double side = breaks[k].r + breaks[k + 1].r >= 2 * e.center.r ? 1.0 : -1.0;
              cross_piece(breaks[k], breaks[k + 1], [&] {
                return e.center.r + side * std::sqrt(std::max(0.0, (R - dz) * (R + dz)));
              });
            }
        }
    return winding != 0;
  }

  double Outline::distance_to_boundary(const Point p, int *nearest_edge) const
  {
    double best = distance_to_edge(edges_[0], p);
    int best_edge = 0;
    for (int i = 1; i < static_cast<int>(edges_.size()); ++i)
      {
        const double d = distance_to_edge(edges_[i], p);
        if (d < best)
          best = d, best_edge = i;
      }
    if (nearest_edge)
      *nearest_edge = best_edge;
    return best;
  }

  std::vector<std::string> Outline::parts() const
  {
    std::vector<std::string> names;
    for (const OutlineEdge &e : edges_)
      if (std::find(names.begin(), names.end(), e.part) == names.end())
        names.push_back(e.part);
    return names;
  }

  std::vector<int> Outline::axis_edges() const
  {
    std::vector<int> indices;
    for (int i = 0; i < static_cast<int>(edges_.size()); ++i)
      if (edges_[i].on_axis(point_tolerance * size_))
        indices.push_back(i);
    return indices;
  }

  std::pair<const OutlineEdge *, const OutlineEdge *> Outline::edges_at(const Point x) const
  {
    const double tol = point_tolerance * size_;
    const OutlineEdge *arriving = nullptr, *leaving = nullptr;
    for (const OutlineEdge &e : edges_)
      {
        if (std::hypot(e.end.r - x.r, e.end.z - x.z) < tol)
          arriving = &e;
        if (std::hypot(e.start.r - x.r, e.start.z - x.z) < tol)
          leaving = &e;
      }
    return {arriving, leaving};
  }
} // namespace axisym
