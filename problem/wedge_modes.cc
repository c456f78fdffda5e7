#include "problem/wedge_modes.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <map>
#include <mutex>
#include <optional>
#include <tuple>
#include <cmath>
#include <stdexcept>

namespace axisym
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;
    using cd = std::complex<double>;

    /// cos and sin of (lambda + 1) theta and (lambda - 1) theta.
    struct Trig
    {
      cd cp, sp, cm, sm;
    };
    Trig trig(const cd lambda, const double theta)
    {
      return {std::cos((lambda + 1.0) * theta), std::sin((lambda + 1.0) * theta),
              std::cos((lambda - 1.0) * theta), std::sin((lambda - 1.0) * theta)};
    }
  } // namespace

  Wedge::Wedge(const double angle, const WedgeFace face_minus, const WedgeFace face_plus,
               const double poisson_ratio)
    : alpha_(0.5 * angle), kappa_(3.0 - 4.0 * poisson_ratio), minus_(face_minus),
      plus_(face_plus)
  {
    if (!(angle > 0.0 && angle <= 2.0 * pi * (1.0 + 1e-12)) || !(poisson_ratio > -1.0 && poisson_ratio < 0.5))
      throw std::invalid_argument("Wedge: the angle must be in (0, 2 pi] and nu in (-1, 0.5)");
  }

  Eigen::Matrix4cd Wedge::matrix(const cd lambda) const
  {
    Eigen::Matrix4cd m;
    int row = 0;
    for (const auto &[theta, face] : {std::pair{-alpha_, minus_}, std::pair{alpha_, plus_}})
      {
        const Trig t = trig(lambda, theta);
        const cd lp = lambda + 1.0, lm = lambda - 1.0;
        const Eigen::RowVector4cd f(t.cp, t.sp, t.cm, t.sm);
        const Eigen::RowVector4cd df(-lp * t.sp, lp * t.cp, -lm * t.sm, lm * t.cm);
        const Eigen::RowVector4cd u_r(-lp * t.cp, -lp * t.sp, (kappa_ - lambda) * t.cm, (kappa_ - lambda) * t.sm);
        const Eigen::RowVector4cd u_t(lp * t.sp, -lp * t.cp, (kappa_ + lambda) * t.sm, -(kappa_ + lambda) * t.cm);
        switch (face)
          {
            case WedgeFace::free:
              m.row(row++) = f, m.row(row++) = df;
              break;
            case WedgeFace::clamped:
              m.row(row++) = u_r, m.row(row++) = u_t;
              break;
            case WedgeFace::symmetry:
              m.row(row++) = u_t, m.row(row++) = df;
              break;
          }
      }
    return m;
  }

  cd Wedge::characteristic(const cd lambda) const { return matrix(lambda).determinant(); }

  std::vector<WedgeMode> Wedge::modes(const double max_real_part) const
  {
    // Remembered per wedge: every model of a contact search asks for the same vertices again
    // (6 ms per rectangle without the memo; the search converges to the same roots).
    using Key = std::tuple<double, double, int, int, double>;
    static std::map<Key, std::vector<WedgeMode>> memo;
    static std::mutex memo_mutex;
    const Key key{alpha_, kappa_, static_cast<int>(minus_), static_cast<int>(plus_), max_real_part};
    {
      const std::lock_guard<std::mutex> lock(memo_mutex);
      const auto it = memo.find(key);
      if (it != memo.end())
        return it->second;
    }
    std::vector<WedgeMode> out = find_modes(max_real_part);
    const std::lock_guard<std::mutex> lock(memo_mutex);
    if (memo.size() < 4096)
      memo.emplace(key, out);
    return out;
  }

  std::vector<WedgeMode> Wedge::find_modes(const double max_real_part) const
  {
    std::vector<cd> roots;
    for (double re = 0.05; re <= max_real_part + 0.05; re += 0.1)
      for (const double im : {0.0, 0.3, 0.8})
        {
          cd x(re, im);
          bool converged = false;
          for (int it = 0; it < 200; ++it)
            {
              const double h = 1e-6 * (1.0 + std::abs(x));
              const cd d = characteristic(x);
              const cd dd = (characteristic(x + h) - characteristic(x - h)) / (2.0 * h);
              if (dd == 0.0)
                break;
              const cd step = d / dd;
              x -= step;
              if (!(std::abs(x) < 1e6))
                break;
              if (std::abs(step) < 1e-14 * (1.0 + std::abs(x)))
                {
                  converged = true;
                  break;
                }
            }
          if (!converged)
            continue;
          if (std::abs(x.imag()) < 1e-9 * (1.0 + std::abs(x)))
            x.imag(0.0);
          if (x.imag() < 0.0)
            x = std::conj(x);
          if (!(x.real() > 1e-6 && x.real() <= max_real_part))
            continue;
          if (x.imag() == 0.0 && std::abs(x.real() - std::round(x.real())) < 1e-6)
            continue; // integer: a polynomial field
          // A root of det M, not a point where Newton stalled: M is singular there.
          const Eigen::JacobiSVD<Eigen::Matrix4cd> svd(matrix(x));
          const auto &s = svd.singularValues();
          if (!(s[3] <= 1e-7 * s[0]))
            continue;
          if (std::none_of(roots.begin(), roots.end(), [&](const cd &r) { return std::abs(r - x) < 1e-6; }))
            roots.push_back(x);
        }
    std::sort(roots.begin(), roots.end(), [](const cd &a, const cd &b) {
      return a.real() != b.real() ? a.real() < b.real() : a.imag() < b.imag();
    });
    std::vector<WedgeMode> out;
    for (const cd &lambda : roots)
      for (WedgeMode &m : modes_at(lambda))
        out.push_back(std::move(m));
    return out;
  }

  std::vector<WedgeMode> Wedge::modes_at(const cd lambda) const
  {
    const Eigen::JacobiSVD<Eigen::Matrix4cd> svd(matrix(lambda), Eigen::ComputeFullV);
    const auto &s = svd.singularValues();
    std::vector<WedgeMode> out;
    for (int k = 3; k >= 0 && s[k] <= 1e-6 * s[0]; --k)
      {
        Eigen::Vector4cd a = svd.matrixV().col(k);
        Eigen::Index big = 0;
        a.cwiseAbs().maxCoeff(&big);
        a /= a[big]; // the largest coefficient 1
        out.push_back({lambda, a});
      }
    return out;
  }

  WedgeFieldValues Wedge::evaluate(const WedgeMode &mode, const double rho, const double theta) const
  {
    const cd l = mode.lambda, lp = l + 1.0, lm = l - 1.0;
    const Eigen::Vector4cd &a = mode.a;
    const Trig t = trig(l, theta);
    const cd f = a[0] * t.cp + a[1] * t.sp + a[2] * t.cm + a[3] * t.sm;
    const cd df = -lp * (a[0] * t.sp - a[1] * t.cp) - lm * (a[2] * t.sm - a[3] * t.cm);
    const cd d2f = -lp * lp * (a[0] * t.cp + a[1] * t.sp) - lm * lm * (a[2] * t.cm + a[3] * t.sm);
    const cd p_s = std::exp(lm * std::log(rho)), p_u = p_s * rho;
    WedgeFieldValues v;
    v.s_tt = p_s * l * lp * f;
    v.s_rt = -p_s * l * df;
    v.s_rr = p_s * (lp * f + d2f);
    v.u_r = 0.5 * p_u * (-lp * (a[0] * t.cp + a[1] * t.sp) + (kappa_ - l) * (a[2] * t.cm + a[3] * t.sm));
    v.u_t = 0.5 * p_u * (lp * (a[0] * t.sp - a[1] * t.cp) + (kappa_ + l) * (a[2] * t.sm - a[3] * t.cm));
    return v;
  }

  WedgeFace wedge_face(const PartCondition &condition)
  {
    using Kind = PartCondition::Kind;
    switch (condition.kind)
      {
        case Kind::displacement:
          return WedgeFace::clamped;
        case Kind::symmetry:
        case Kind::axis:
          return WedgeFace::symmetry;
        default:
          return WedgeFace::free;
      }
  }

  namespace
  {
    /// f(a, b) for every vertex of the outline off the axis, where edge a ends and edge b
    /// starts (neither of them on the axis).
    template <typename F>
    void for_each_vertex_off_axis(const Body &body, const F &f)
    {
      const std::vector<OutlineEdge> &edges = body.outline.edges();
      const double tol = 1e-9 * body.outline.size();
      for (std::size_t i = 0; i < edges.size(); ++i)
        {
          const OutlineEdge &a = edges[i], &b = edges[(i + 1) % edges.size()];
          if (!(a.end.r <= tol || a.on_axis(tol) || b.on_axis(tol)))
            f(a, b);
        }
    }

    /// The interior angle [rad] at the vertex where edge a ends and edge b starts: pi minus
    /// the turn from a to b (+ to the left), outlines running counter-clockwise with the body
    /// on the left (the parser's rule).
    double interior_angle(const OutlineEdge &a, const OutlineEdge &b)
    {
      const Point ta = a.tangent_at(1.0), tb = b.tangent_at(0.0);
      return pi - std::atan2(ta.r * tb.z - ta.z * tb.r, ta.r * tb.r + ta.z * tb.z);
    }

    /// A part whose condition prescribes the traction (free, pressure, traction).
    bool is_traction_part(const PartCondition &c)
    {
      using Kind = PartCondition::Kind;
      return c.kind == Kind::traction_free || c.kind == Kind::pressure || c.kind == Kind::traction;
    }
  } // namespace

  std::vector<SingularVertex> singular_vertices(const Body &body, const double poisson_ratio)
  {
    std::vector<SingularVertex> out;
    for_each_vertex_off_axis(body, [&](const OutlineEdge &a, const OutlineEdge &b) {
        const Point v = a.end;
        const double angle = interior_angle(a, b);
        if (!(angle > 1e-9))
          return; // a cusp: no wedge
        const PartCondition &ca = body.conditions.at(a.part), &cb = body.conditions.at(b.part);
        const Wedge w(angle, wedge_face(ca), wedge_face(cb), poisson_ratio);
        std::vector<WedgeMode> modes = w.modes(0.999);
        if (!modes.empty())
          out.push_back({v, angle, a.part, b.part, std::move(modes)});
      });
    return out;
  }

  std::vector<SingularVertex> rough_vertices(const Body &body, const double poisson_ratio)
  {
    std::vector<SingularVertex> out;
    for_each_vertex_off_axis(body, [&](const OutlineEdge &a, const OutlineEdge &b) {
        const double angle = interior_angle(a, b);
        if (!(angle > 1e-9))
          return;
        const PartCondition &ca = body.conditions.at(a.part), &cb = body.conditions.at(b.part);
        const Wedge w(angle, wedge_face(ca), wedge_face(cb), poisson_ratio);
        std::vector<WedgeMode> modes = w.modes(rough_vertex_max_exponent - 1e-3);
        if (std::any_of(modes.begin(), modes.end(), [](const WedgeMode &m) { return m.lambda.real() < 0.999; }))
          return; // singular: singular_vertices
        modes.erase(std::remove_if(modes.begin(), modes.end(),
                                   [](const WedgeMode &m) {
                                     return std::abs(m.lambda.imag()) < 1e-9 &&
                                            std::abs(m.lambda.real() - std::round(m.lambda.real())) < 1e-7;
                                   }),
                    modes.end());
        if (!modes.empty())
          out.push_back({a.end, angle, a.part, b.part, std::move(modes)});
      });
    return out;
  }

  std::vector<NotchRoot> notch_roots(const Body &body)
  {
    std::vector<NotchRoot> out;
    using Kind = PartCondition::Kind;
    const double size = body.outline.size();
    for_each_vertex_off_axis(body, [&](const OutlineEdge &a, const OutlineEdge &b) {
        const PartCondition &ca = body.conditions.at(a.part), &cb = body.conditions.at(b.part);
        // The arc and the symmetry line, in either order; concave: the arc runs clockwise
        // about its centre, with the body on its left.
        const OutlineEdge *arc = nullptr;
        if (a.kind == OutlineEdge::Kind::arc && is_traction_part(ca) && cb.kind == Kind::symmetry &&
            b.kind == OutlineEdge::Kind::line)
          arc = &a;
        else if (b.kind == OutlineEdge::Kind::arc && is_traction_part(cb) && ca.kind == Kind::symmetry &&
                 a.kind == OutlineEdge::Kind::line)
          arc = &b;
        if (arc == nullptr || !(arc->sweep() < 0.0) || !(arc->radius() < notch_root_max_radius * size))
          return;
        out.push_back({a.end, interior_angle(a, b), arc->radius()});
      });
    return out;
  }

  std::optional<Point> edge_traction(const Body &body, const OutlineEdge &e, const double t)
  {
    const PartCondition &c = body.conditions.at(e.part);
    switch (c.kind)
      {
        case PartCondition::Kind::traction_free: return Point{0.0, 0.0};
        case PartCondition::Kind::pressure:
          {
            const Point n = e.outward_normal_at(t);
            return Point{-c.pressure * n.r, -c.pressure * n.z};
          }
        case PartCondition::Kind::traction: return Point{c.traction[0], c.traction[1]};
        default: return std::nullopt;
      }
  }

  std::vector<Point> traction_jump_vertices(const Body &body)
  {
    std::vector<Point> out;
    for_each_vertex_off_axis(body, [&](const OutlineEdge &a, const OutlineEdge &b) {
        const std::optional<Point> ta = edge_traction(body, a, 1.0), tb = edge_traction(body, b, 0.0);
        if (!ta || !tb)
          return;
        const double scale = std::max(std::hypot(ta->r, ta->z), std::hypot(tb->r, tb->z));
        if (!(scale > 0.0))
          return;
        const Point na = a.outward_normal_at(1.0), nb = b.outward_normal_at(0.0);
        const bool straight = std::abs(na.r * nb.z - na.z * nb.r) < 1e-9 && na.r * nb.r + na.z * nb.z > 0.0;
        const bool jump = straight ? std::hypot(ta->r - tb->r, ta->z - tb->z) > 1e-9 * scale
                                   : std::abs(nb.r * ta->r + nb.z * ta->z - na.r * tb->r - na.z * tb->z) >
                                       1e-9 * scale;
        if (jump)
          out.push_back(a.end);
      });
    return out;
  }

  std::vector<ResonantSite> resonant_vertices(const Body &body, const BodyLoads &loads)
  {
    std::vector<ResonantSite> out;
    const double t_grad = std::hypot(loads.temperature[1], loads.temperature[2]);
    if (!(t_grad > 0.0))
      return out;
    using Kind = PartCondition::Kind;
    for_each_vertex_off_axis(body, [&](const OutlineEdge &a, const OutlineEdge &b) {
        if (!(std::abs(interior_angle(a, b) - 0.5 * pi) < 1e-9))
          return;
        const PartCondition &ca = body.conditions.at(a.part), &cb = body.conditions.at(b.part);
        const bool sym_a = ca.kind == Kind::symmetry && is_traction_part(cb);
        const bool sym_b = cb.kind == Kind::symmetry && is_traction_part(ca);
        if (!sym_a && !sym_b)
          return;
        const OutlineEdge &line = sym_a ? a : b;
        const Point n = line.outward_normal_at(0.5);
        if (std::abs(n.r * loads.temperature[1] + n.z * loads.temperature[2]) > 1e-12 * t_grad)
          out.push_back({a.end, line.part, (sym_a ? b : a).part});
      });
    return out;
  }
} // namespace axisym
