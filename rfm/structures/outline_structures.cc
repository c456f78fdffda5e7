#include "rfm/structures/outline_structures.h"

#include <numeric>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rfm
{
  using axisym::InputError;
  using axisym::OutlineEdge;
  using axisym::PartCondition;

  namespace
  {
    // The transfinite weights of the edges e with in_set(e) at a point where their omegas are
    // w: W_e = prod_{f != e} w_f / sum_g prod_{h != g} w_h (1 on e, 0 on the set's other edges;
    // on a corner of two edges of the set, shared equally); 0 off the set.
    template <typename InSet>
    void transfinite_weights(const std::vector<double> &w, std::vector<double> &weight,
                             const InSet &in_set)
    {
      const std::size_t n = w.size();
      double den = 0.0;
      for (std::size_t e = 0; e < n; ++e)
        {
          weight[e] = 0.0;
          if (!in_set(e))
            continue;
          double p = 1.0;
          for (std::size_t f = 0; f < n; ++f)
            if (f != e && in_set(f))
              p *= w[f];
          den += (weight[e] = p);
        }
      if (den > 0.0)
        for (double &x : weight)
          x /= den;
      else
        {
          double zeros = 0.0;
          for (std::size_t e = 0; e < n; ++e)
            zeros += in_set(e) && w[e] == 0.0;
          for (std::size_t e = 0; e < n; ++e)
            weight[e] = in_set(e) && w[e] == 0.0 ? 1.0 / zeros : 0.0;
        }
    }

    double dot(const axisym::Point &a, const axisym::Point &b) { return a.r * b.r + a.z * b.z; }
    axisym::Point minus(const axisym::Point &a, const axisym::Point &b)
    {
      return {a.r - b.r, a.z - b.z};
    }
  } // namespace

  // 1. Edge omegas.
  EdgeOmega::EdgeOmega(const axisym::Outline &outline, const int edge, const bool one_sided,
                       const bool even_in_r)
    : EdgeOmega(outline, outline.edges().at(edge), one_sided, even_in_r)
  {}

  EdgeOmega::EdgeOmega(const axisym::Outline &outline, const axisym::OutlineEdge &edge,
                       const bool one_sided, const bool even_in_r)
    : edge_(edge)
    , even_(even_in_r)
  {
    if (even_ && (edge_.kind != OutlineEdge::Kind::line || one_sided))
      throw std::invalid_argument("EdgeOmega: even in r for a line along r or z only");
    const bool arc = edge_.kind == OutlineEdge::Kind::arc;
    sign_ = arc && edge_.sweep() < 0 ? -1.0 : 1.0;
    {
      const axisym::Point d = minus(edge_.end, edge_.start);
      const double length = std::sqrt(dot(d, d));
      const axisym::BoundingBox b = outline.bounding_box();
      r_box_max_ = b.r_max;
      trim_length_ = outline.size();
      s_min_ = std::numeric_limits<double>::infinity();
      s_max_ = -s_min_;
      for (const axisym::Point corner :
           {axisym::Point{b.r_min, b.z_min}, axisym::Point{b.r_min, b.z_max},
            axisym::Point{b.r_max, b.z_min}, axisym::Point{b.r_max, b.z_max}})
        {
          const double s = dot(minus(corner, edge_.start), d) / length;
          s_min_ = std::min(s_min_, s), s_max_ = std::max(s_max_, s);
        }
    }
    if (arc && !outline.contains(edge_.center, 1e-6 * outline.size()))
      {
        // The angle about the center, if the section stays in a sector about the arc's mid
        // direction (the branch cut, opposite to it, then misses the section).
        angular_ = true;
        for (const axisym::OutlineEdge &other : outline.edges())
          for (int k = 0; k <= 200 && angular_; ++k)
            {
              const axisym::Point x = other.point_at(k / 200.0);
              angular_ = std::abs(edge_coordinate(x.r, x.z).value) * 0.5 * std::abs(edge_.sweep()) <
                         0.95 * M_PI;
            }
      }
    // Trim unless the carrier meets the closed section only along the edge: sample the
    // carrier off the edge (beyond a small margin) and look for points in the section.
    const double size = outline.size(), margin = 1e-6 * size, tol = 1e-9 * size;
    const int n_samples = 4000;
    if (!arc)
      {
        const axisym::Point d = minus(edge_.end, edge_.start);
        const double length = std::sqrt(dot(d, d));
        const axisym::Point tau{d.r / length, d.z / length};
        const axisym::Point mid{0.5 * (edge_.start.r + edge_.end.r),
                                0.5 * (edge_.start.z + edge_.end.z)};
        const axisym::BoundingBox b = outline.bounding_box();
        double s_lo = 0, s_hi = 0;
        for (const axisym::Point corner :
             {axisym::Point{b.r_min, b.z_min}, axisym::Point{b.r_min, b.z_max},
              axisym::Point{b.r_max, b.z_min}, axisym::Point{b.r_max, b.z_max}})
          {
            const double s = dot(minus(corner, mid), tau);
            s_lo = std::min(s_lo, s), s_hi = std::max(s_hi, s);
          }
        bool before = false, after = false; // the carrier meets the section beyond the start, end
        for (int k = 0; k <= n_samples; ++k)
          {
            const double s = s_lo + (s_hi - s_lo) * k / n_samples;
            if (std::abs(s) <= 0.5 * length + margin)
              continue;
            if (outline.contains({mid.r + s * tau.r, mid.z + s * tau.z}, tol))
              (s < 0 ? before : after) = true;
          }
        trimmed_ = before || after;
        // One-sided: trimmed at the ends where the carrier goes on in the section only, a ray
        // beyond the other (smooth there, as the rectangle's parts that reach a corner).
        if (one_sided && trimmed_ && !(before && after))
          trim_side_ = after ? 1 : -1;
        conjunction_ends_ = one_sided && before && after;
      }
    else
      {
        const double radius = edge_.radius(), sweep = edge_.sweep();
        const double phi0 = std::atan2(edge_.start.z - edge_.center.z, edge_.start.r - edge_.center.r);
        const double phi_margin = margin / radius;
        for (int k = 0; k < n_samples && !trimmed_; ++k)
          {
            // Angle from the start in the direction of the sweep, in [0, 2 pi).
            const double a = 2.0 * M_PI * k / n_samples;
            if (a <= std::abs(sweep) + phi_margin || a >= 2.0 * M_PI - phi_margin)
              continue;
            const double phi = phi0 + (sweep > 0 ? a : -a);
            trimmed_ = outline.contains({edge_.center.r + radius * std::cos(phi),
                                         edge_.center.z + radius * std::sin(phi)},
                                        tol);
          }
      }
  }

  RValue EdgeOmega::carrier(const double r, const double z) const
  {
    if (edge_.kind == OutlineEdge::Kind::line)
      {
        const axisym::Point n = edge_.outward_normal_at(0.5);
        if (even_ && std::abs(n.z) < 1e-12 && edge_.start.r > 0.0)
          {
            // The cylinder r = a: -n_r (r^2 - a^2) / (2 a).
            const double a = edge_.start.r;
            return {-n.r * (r * r - a * a) / (2.0 * a), -n.r * r / a, 0.0};
          }
        const double f = -(n.r * (r - edge_.start.r) + n.z * (z - edge_.start.z));
        return {f, -n.r, -n.z};
      }
    const double radius = edge_.radius(), dr = r - edge_.center.r, dz = z - edge_.center.z;
    return {sign_ * (radius * radius - dr * dr - dz * dz) / (2.0 * radius), -sign_ * dr / radius,
            -sign_ * dz / radius};
  }

  RValue EdgeOmega::operator()(const double r, const double z) const
  {
    const RValue f = carrier(r, z);
    if (!trimmed_)
      return f;
    RValue t;
    if (edge_.kind == OutlineEdge::Kind::line)
      {
        const axisym::Point d = minus(edge_.end, edge_.start);
        const double length = std::sqrt(dot(d, d));
        const double tr = d.r / length, tz = d.z / length;
        const double s = (r - 0.5 * (edge_.start.r + edge_.end.r)) * tr +
                         (z - 0.5 * (edge_.start.z + edge_.end.z)) * tz;
        if (even_ && std::abs(tz) < 1e-12)
          {
            // Along r from r1 to r2: the coaxial cylinders' functions, even in r.
            const double r1 = std::min(edge_.start.r, edge_.end.r),
                         r2 = std::max(edge_.start.r, edge_.end.r);
            const RValue outer{(r2 * r2 - r * r) / (2.0 * r2), -r / r2, 0.0};
            t = r1 <= 0.0 ? outer
                          : r_conjunction({(r * r - r1 * r1) / (2.0 * r1), r / r1, 0.0}, outer);
          }
        else if (trim_side_ > 0) // trimmed at the end only: t = L/2 - s
          t = {0.5 * length - s, -tr, -tz};
        else if (trim_side_ < 0) // at the start only: t = s + L/2
          t = {s + 0.5 * length, tr, tz};
        else if (conjunction_ends_) // (L/2 - s) AND (L/2 + s)
          t = r_conjunction({0.5 * length - s, -tr, -tz}, {0.5 * length + s, tr, tz});
        else
          t = {(0.25 * length * length - s * s) / length, -2.0 * s * tr / length,
               -2.0 * s * tz / length};
      }
    else
      {
        // The chord's half-plane on the arc's side: t >= 0 exactly on the arc's part of the
        // circle (the arc is under 180 degrees).
        const axisym::Point cm{0.5 * (edge_.start.r + edge_.end.r),
                               0.5 * (edge_.start.z + edge_.end.z)};
        const axisym::Point am = edge_.point_at(0.5);
        const axisym::Point m = minus(am, cm);
        const double len = std::sqrt(dot(m, m));
        t = {((r - cm.r) * m.r + (z - cm.z) * m.z) / len, m.r / len, m.z / len};
      }
    return trimmed_segment(f, t, trim_length_);
  }

  RValue EdgeOmega::edge_coordinate(const double r, const double z) const
  {
    if (angular_)
      {
        const axisym::Point m = minus(edge_.point_at(0.5), edge_.center);
        const double dr = r - edge_.center.r, dz = z - edge_.center.z, rho2 = dr * dr + dz * dz;
        const double phi = std::atan2(m.r * dz - m.z * dr, m.r * dr + m.z * dz);
        const double scale = (edge_.sweep() > 0 ? 2.0 : -2.0) / std::abs(edge_.sweep());
        return {scale * phi, -scale * dz / rho2, scale * dr / rho2};
      }
    const axisym::Point d = minus(edge_.end, edge_.start);
    if (even_ && std::abs(d.z) < 1e-12 * std::abs(d.r))
      {
        // Along r: 2 r^2 / r_max^2 - 1 (the box starts on the axis; monotone on r >= 0).
        const double c = 2.0 / (r_box_max_ * r_box_max_);
        return {c * r * r - 1.0, 2.0 * c * r, 0.0};
      }
    const double length = std::sqrt(dot(d, d)), scale = 2.0 / ((s_max_ - s_min_) * length);
    const double s = (r - edge_.start.r) * d.r + (z - edge_.start.z) * d.z; // times length
    return {scale * (s - s_min_ * length) - 1.0, scale * d.r, scale * d.z};
  }

  std::array<double, 2> EdgeOmega::tangent(const double r, const double z) const
  {
    if (edge_.kind == OutlineEdge::Kind::line)
      {
        const axisym::Point t = edge_.tangent_at(0.5);
        return {t.r, t.z};
      }
    const double radius = edge_.radius(), s = edge_.sweep() > 0 ? 1.0 : -1.0;
    return {-s * (z - edge_.center.z) / radius, s * (r - edge_.center.r) / radius};
  }

  namespace
  {
    // The body with every die part's edges split at its zone's ends: the zone keeps the part's
    // name, the free sub-edges go to part "<part>#free" (traction free, or under the die
    // part's pressure).
    axisym::Body split_at_zones(const axisym::Body &body, const std::vector<DieZone> &zones)
    {
      if (zones.empty())
        return body;
      std::vector<OutlineEdge> edges;
      auto conditions = body.conditions;
      const double tol = 1e-9 * body.outline.size();
      for (const OutlineEdge &e : body.outline.edges())
        {
          const auto zone = std::find_if(zones.begin(), zones.end(),
                                         [&](const DieZone &z) { return z.part == e.part; });
          if (zone == zones.end())
            {
              edges.push_back(e);
              continue;
            }
          const axisym::DieFrame f = axisym::die_frame(body, e.part);
          const std::string free_part = e.part + "#free";
          // Traction free, or the die part's pressure (the legacy outer pressure) beyond the zone.
          PartCondition beyond;
          if (body.conditions.at(e.part).pressure != 0.0)
            beyond.kind = PartCondition::Kind::pressure,
            beyond.pressure = body.conditions.at(e.part).pressure;
          conditions[free_part] = beyond;
          // Cut points along the edge (t in [0, 1]) at the zone's ends.
          const double s0 = f.coordinate(e.start), s1 = f.coordinate(e.end);
          std::vector<double> cuts{0.0, 1.0};
          for (const double s : {zone->s_lo, zone->s_hi})
            {
              const double t = (s - s0) / (s1 - s0);
              if (t * std::abs(s1 - s0) > tol && (1 - t) * std::abs(s1 - s0) > tol)
                cuts.push_back(t);
            }
          std::sort(cuts.begin(), cuts.end());
          for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
            {
              OutlineEdge sub = e;
              sub.start = e.point_at(cuts[i]);
              sub.end = e.point_at(cuts[i + 1]);
              const double s_mid = f.coordinate(e.point_at(0.5 * (cuts[i] + cuts[i + 1])));
              sub.part = s_mid >= zone->s_lo && s_mid <= zone->s_hi ? e.part : free_part;
              edges.push_back(sub);
            }
        }
      axisym::Body out{axisym::Outline(body.outline.edges().front().start, std::move(edges)),
                       std::move(conditions), body.mirrored};
      // A free part that got no edge (the zone covers the part) is dropped.
      for (auto it = out.conditions.begin(); it != out.conditions.end();)
        {
          const auto parts = out.outline.parts();
          if (std::find(parts.begin(), parts.end(), it->first) == parts.end())
            it = out.conditions.erase(it);
          else
            ++it;
        }
      return out;
    }
  } // namespace

  // 2. Edge sets and the checks of what the structures support.
  std::string OutlineStructures::axis_parity_obstacle(const axisym::Body &body)
  {
    bool on_axis = false;
    for (const OutlineEdge &e : body.outline.edges())
      {
        const PartCondition &c = body.conditions.at(e.part);
        on_axis |= c.kind == PartCondition::Kind::axis;
        const axisym::Point n = e.outward_normal_at(0.5);
        const bool normal_r = std::abs(std::abs(n.r) - 1.0) < 1e-12;
        const bool normal_z = std::abs(std::abs(n.z) - 1.0) < 1e-12;
        if (e.kind != OutlineEdge::Kind::line || !(normal_r || normal_z))
          return "part " + e.part + " is not a line along r or z (even omegas of cones and tori "
                                    "are not done)";
        if (c.kind == PartCondition::Kind::die)
          return "part " + e.part + " carries a die";
        if (c.kind == PartCondition::Kind::traction && c.traction[normal_r ? 1 : 0] != 0.0)
          return "the traction on part " + e.part + " has a shear component";
        if (c.kind == PartCondition::Kind::displacement && c.displacement[0] != 0.0)
          return "part " + e.part + " prescribes u_r other than 0";
      }
    return on_axis ? "" : "the section has no edge on the axis";
  }

  OutlineStructures::OutlineStructures(const axisym::Body &body, const int degree,
                                       const std::vector<DieZone> &zones, const bool axis_parity)
    : body_(split_at_zones(body, zones)), degree_(degree), axis_parity_(axis_parity)
  {
    if (axis_parity)
      if (const std::string obstacle = axis_parity_obstacle(body); !obstacle.empty())
        throw std::invalid_argument("OutlineStructures: no axis parity here: " + obstacle);
    const auto &edges = body_.outline.edges();
    zone_of_edge_.assign(edges.size(), -1);
    for (const DieZone &z : zones)
      {
        if (!body.conditions.count(z.part) ||
            body.conditions.at(z.part).kind != PartCondition::Kind::die)
          throw std::invalid_argument("OutlineStructures: zone on part " + z.part +
                                      ", which carries no die");
        Zone zone;
        zone.frame = axisym::die_frame(body, z.part);
        zone.profile = body.conditions.at(z.part).die.profile;
        zone.indentation = z.indentation;
        if (z.fade_start != 0.0 || z.fade_end != 0.0)
          {
            const double extent = std::max(std::abs(z.s_lo), std::abs(z.s_hi));
            if (!(z.fade_start >= extent * (1 - 1e-12) && z.fade_end > z.fade_start))
              throw std::invalid_argument("OutlineStructures: a zone's fade must start beyond "
                                          "the zone and end beyond its start");
            zone.fade_start = z.fade_start, zone.fade_end = z.fade_end;
            zone.fade_normal_start = z.fade_normal_start, zone.fade_normal_end = z.fade_normal_end;
            if (zone.fade_normal_end == 0.0)
              zone.fade_normal_start = z.fade_start, zone.fade_normal_end = z.fade_end;
            if (!(zone.fade_normal_start >= 0.0 && zone.fade_normal_end > zone.fade_normal_start))
              throw std::invalid_argument("OutlineStructures: a zone's normal fade must start at "
                                          "n >= 0 and end beyond its start");
          }
        const bool normal_r = std::abs(std::abs(zone.frame.normal.r) - 1.0) < 1e-12;
        const bool normal_z = std::abs(std::abs(zone.frame.normal.z) - 1.0) < 1e-12;
        if (!normal_r && !normal_z)
          throw InputError("boundary." + z.part +
                           ".die: the RFM takes a die on a part along r or z only so far");
        zone.component = normal_r ? 0 : 1;
        zone.sign = normal_r ? zone.frame.normal.r : zone.frame.normal.z;
        for (std::size_t e = 0; e < edges.size(); ++e)
          if (edges[e].part == z.part)
            zone_of_edge_[e] = static_cast<int>(zones_.size());
        zones_.push_back(zone);
      }
    for (int e = 0; e < static_cast<int>(edges.size()); ++e)
      {
        // A die part's sub-edges (the zone and the free rest) are rays beyond the part's own
        // corners (EdgeOmega: one-sided trimming).
        const bool die_sub_edge =
          zone_of_edge_[e] >= 0 ||
          std::any_of(zones.begin(), zones.end(),
                      [&](const DieZone &z) { return edges[e].part == z.part + "#free"; });
        omegas_.emplace_back(body_.outline, e, die_sub_edge, axis_parity_);
        const PartCondition &c = body_.condition_of_edge(e);
        const axisym::Point n = edges[e].outward_normal_at(0.5);
        const bool along_r = std::abs(std::abs(n.r) - 1.0) < 1e-12;
        const bool along_z = std::abs(std::abs(n.z) - 1.0) < 1e-12;
        switch (c.kind)
          {
            case PartCondition::Kind::traction_free:
            case PartCondition::Kind::pressure:
            case PartCondition::Kind::traction: stress_edges_.push_back(e); break;
            case PartCondition::Kind::symmetry:
            case PartCondition::Kind::axis:
              if (edges[e].kind != OutlineEdge::Kind::line || !(along_r || along_z))
                throw InputError("boundary." + edges[e].part +
                                 ": the RFM structures take symmetry edges along r or z only");
              symmetry_edges_.push_back(e);
              (along_r ? u_r_edges_ : u_z_edges_).push_back(e);
              (along_r ? u_r_values_ : u_z_values_).push_back({});
              break;
            case PartCondition::Kind::displacement:
              u_r_edges_.push_back(e), u_r_values_.push_back({c.displacement[0], -1});
              u_z_edges_.push_back(e), u_z_values_.push_back({c.displacement[1], -1});
              break;
            case PartCondition::Kind::die:
              {
                // A zone: shear free (a Y edge for sigma_rz) with u.n prescribed.
                const int zone = zone_of_edge_[e];
                if (zone < 0)
                  throw InputError("boundary." + edges[e].part +
                                   ".die: the RFM solves a die on an outline part for a given "
                                   "zone only so far (contact.method \"fixed\" with "
                                   "contact.half_width); fem_solve solves for the zone");
                symmetry_edges_.push_back(e);
                (along_r ? u_r_edges_ : u_z_edges_).push_back(e);
                (along_r ? u_r_values_ : u_z_values_).push_back({0.0, zone});
                break;
              }
          }
      }

    // Smooth chains of S edges: consecutive edges (the outline is closed) whose outward
    // normals agree at the shared vertex.
    {
      const int n_edges = static_cast<int>(edges.size());
      std::vector<int> chain_of_edge(n_edges, -1);
      for (std::size_t i = 0; i < stress_edges_.size(); ++i)
        chain_of_edge[stress_edges_[i]] = static_cast<int>(i);
      // Union-find over the S edges.
      std::vector<int> parent(stress_edges_.size());
      std::iota(parent.begin(), parent.end(), 0);
      const auto root = [&parent](int i) {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      };
      for (int e = 0; e < n_edges; ++e)
        {
          const int f = (e + 1) % n_edges;
          if (chain_of_edge[e] < 0 || chain_of_edge[f] < 0 || e == f)
            continue;
          const axisym::Point n_e = edges[e].outward_normal_at(1.0),
                              n_f = edges[f].outward_normal_at(0.0);
          if (std::hypot(n_e.r - n_f.r, n_e.z - n_f.z) < 1e-9)
            parent[root(chain_of_edge[e])] = root(chain_of_edge[f]);
        }
      // The free sub-edges either side of a zone inside its part are one chain: the
      // conjunction of their omegas is ~ the distance to the nearer end of the zone on the zone,
      // where their product is ~ (s - s_lo)(s_hi - s) (1e-4 of its far values for a zone 1/100
      // of its part, which the coordinate functions would have to undo to carry the pressure).
      const auto is_free_sub_edge = [&](const int e) {
        const std::string &part = edges[e].part;
        return part.size() > 5 && part.compare(part.size() - 5, 5, "#free") == 0;
      };
      std::vector<int> same_part_free;
      for (int e = 0; e < n_edges; ++e)
        if (chain_of_edge[e] >= 0 && is_free_sub_edge(e))
          for (int f = e + 1; f < n_edges; ++f)
            if (chain_of_edge[f] >= 0 && edges[f].part == edges[e].part)
              {
                parent[root(chain_of_edge[e])] = root(chain_of_edge[f]);
                same_part_free.push_back(chain_of_edge[e]);
                same_part_free.push_back(chain_of_edge[f]);
              }
      std::vector<int> label(stress_edges_.size(), -1);
      stress_chain_.assign(stress_edges_.size(), -1);
      n_stress_chains_ = 0;
      for (std::size_t i = 0; i < stress_edges_.size(); ++i)
        {
          const int r0 = root(static_cast<int>(i));
          if (label[r0] < 0)
            label[r0] = n_stress_chains_++;
          stress_chain_[i] = label[r0];
        }
      // Lone straight S edges along r or z prescribe two stress components only; the others
      // get the boundary columns, numbered in order.
      std::vector<int> chain_size(n_stress_chains_, 0);
      for (const int c : stress_chain_)
        ++chain_size[c];
      // Straight chains: edges along r or z on one line, split into parts with different
      // tractions (a pressure on part of a bore). Their line is one edge for the structures:
      // the chain's omega is that of the segment from its first start to its last end, and
      // its edges prescribe two stress components like a lone edge. The conjunction of the
      // edges' own omegas, each trimmed at the join, is 0.59 |f| on the line through the join
      // across the section and turns to |f| within about f^2 / l of it (l the section's
      // size), a factor the polynomials must undo. On the pressure band ring
      // (verification/problems/pressure_band_ring.json) at p = 20 the line took the indicator
      // from 1.86e-5 to 1.63e-5 and the stress error against the FEM on a 21 x 21 grid (rms,
      // over the pressure) from 7.4e-4 to 6.7e-4, and its 42 boundary columns off the system:
      // assembly 4.0 s -> 2.4 s, solve 3.6 s -> 0.5 s.
      chain_line_.assign(n_stress_chains_, -1);
      line_chain_omegas_.clear();
      for (int c = 0; c < n_stress_chains_; ++c)
        {
          if (chain_size[c] < 2)
            continue;
          std::vector<int> members;
          for (std::size_t i = 0; i < stress_edges_.size(); ++i)
            if (stress_chain_[i] == c)
              members.push_back(stress_edges_[i]);
          const OutlineEdge &first = edges[members.front()];
          const axisym::Point n = first.outward_normal_at(0.5), tau = first.tangent_at(0.5);
          bool straight =
            std::abs(std::abs(n.r) - 1.0) < 1e-12 || std::abs(std::abs(n.z) - 1.0) < 1e-12;
          double s_lo = std::numeric_limits<double>::infinity(), s_hi = -s_lo;
          axisym::Point lo = first.start, hi = first.end;
          for (const int e : members)
            {
              // A die part's free sub-edges are joined across their zone (above): not a line.
              const OutlineEdge &edge = edges[e];
              const axisym::Point m = edge.outward_normal_at(0.5);
              const double off = 1e-9 * body_.outline.size();
              straight = straight && !is_free_sub_edge(e) && edge.kind == OutlineEdge::Kind::line &&
                         std::hypot(m.r - n.r, m.z - n.z) < 1e-9 &&
                         std::abs(dot(minus(edge.start, first.start), n)) < off &&
                         std::abs(dot(minus(edge.end, first.start), n)) < off;
              for (const axisym::Point x : {edge.start, edge.end})
                {
                  const double s = dot(minus(x, first.start), tau);
                  if (s < s_lo)
                    s_lo = s, lo = x;
                  if (s > s_hi)
                    s_hi = s, hi = x;
                }
            }
          if (!straight)
            continue;
          OutlineEdge line = first;
          line.start = lo, line.end = hi;
          chain_line_[c] = static_cast<int>(line_chain_omegas_.size());
          line_chain_omegas_.emplace_back(body_.outline, line, false, axis_parity_);
        }
      stress_kind_.assign(stress_edges_.size(), StressEdge::general);
      boundary_slot_.assign(stress_edges_.size(), -1);
      n_general_ = 0;
      for (std::size_t i = 0; i < stress_edges_.size(); ++i)
        {
          const OutlineEdge &edge = edges[stress_edges_[i]];
          const axisym::Point n = edge.outward_normal_at(0.5);
          // A lone line, or the free sub-edges of a die part (on one line).
          const bool lone = chain_size[stress_chain_[i]] == 1 ||
                            chain_line_[stress_chain_[i]] >= 0 ||
                            std::find(same_part_free.begin(), same_part_free.end(),
                                      static_cast<int>(i)) != same_part_free.end();
          if (edge.kind == OutlineEdge::Kind::line && lone)
            {
              if (std::abs(std::abs(n.r) - 1.0) < 1e-12)
                stress_kind_[i] = StressEdge::normal_r;
              else if (std::abs(std::abs(n.z) - 1.0) < 1e-12)
                stress_kind_[i] = StressEdge::normal_z;
            }
          if (stress_kind_[i] == StressEdge::general)
            boundary_slot_[i] = n_general_++;
        }
      chain_kind_.assign(n_stress_chains_, StressEdge::general);
      for (std::size_t i = 0; i < stress_edges_.size(); ++i)
        chain_kind_[stress_chain_[i]] = stress_kind_[i]; // a lone edge's kind, else general
    }

    // Which Y edges each S edge needs the shear factor for: T_e or s0_e has an rz component
    // on that Y edge.
    shear_y_edges_.assign(edges.size(), {});
    for (const int e : stress_edges_)
      for (const int y : symmetry_edges_)
        for (int k = 1; k < 20; ++k)
          {
            const axisym::Point p = edges[y].point_at(k / 20.0);
            const double scale = 1.0 + std::abs(body_.condition_of_edge(e).traction[0]) +
                                 std::abs(body_.condition_of_edge(e).traction[1]);
            if (std::abs(tangent_tensor(e, p.r, p.z)[2]) > 1e-12 ||
                std::abs(particular(e, p.r, p.z)[2]) > 1e-12 * scale)
              {
                shear_y_edges_[e].push_back(y);
                break;
              }
          }

    // The even ends of the arcs with boundary columns (the header's "Even ends"): an end on
    // a symmetry line or the axis whose line passes through the arc's centre.
    even_arcs_.assign(edges.size(), {});
    const double size = body_.outline.size(), tol = 1e-9 * size;
    for (std::size_t i = 0; i < stress_edges_.size(); ++i)
      {
        const int e = stress_edges_[i];
        const OutlineEdge &arc = edges[e];
        if (boundary_slot_[i] < 0 || arc.kind != OutlineEdge::Kind::arc ||
            body_.outline.contains(arc.center, 1e-6 * size))
          continue;
        EvenArc &even = even_arcs_[e];
        for (const int y : symmetry_edges_)
          {
            if (!edges[y].on_axis(tol) &&
                body_.condition_of_edge(y).kind != PartCondition::Kind::symmetry)
              continue; // a die's zone is shear free, not a mirror
            const OutlineEdge &line = edges[y];
            const axisym::Point d = minus(line.end, line.start);
            const double length = std::sqrt(dot(d, d));
            const axisym::Point c = minus(arc.center, line.start);
            if (std::abs(c.r * d.z - c.z * d.r) / length > tol)
              continue; // the centre is off the line
            auto shares = [&](const axisym::Point &p) {
              return std::hypot(p.r - line.start.r, p.z - line.start.z) < tol ||
                     std::hypot(p.r - line.end.r, p.z - line.end.z) < tol;
            };
            even.ends |= (shares(arc.start) ? 1 : 0) | (shares(arc.end) ? 2 : 0);
          }
        if (even.ends == 0)
          continue;
        // The largest angle from the even end over the section (with one even end the
        // coordinate's scale, so that it stays in [-1, 1] there). Where the section reaches
        // round the centre towards the angle's branch cut, the monotone coordinate stays.
        even.angle_max = std::abs(arc.sweep());
        for (const OutlineEdge &other : edges)
          for (int k = 0; k <= 200; ++k)
            {
              const axisym::Point x = other.point_at(k / 200.0);
              even.angle_max = std::max(even.angle_max, std::abs(angle_from_even_end(e, x.r, x.z)));
            }
        if (even.angle_max > 0.95 * M_PI)
          even = EvenArc{};
      }
  }

  double OutlineStructures::angle_from_even_end(const int e, const double r, const double z) const
  {
    // The angle about the centre from the start, positive along the arc; from the end when
    // only the end is even.
    const OutlineEdge &arc = body_.outline.edges()[e];
    const double ur = arc.start.r - arc.center.r, uz = arc.start.z - arc.center.z;
    const double vr = r - arc.center.r, vz = z - arc.center.z;
    const double from_start =
      (arc.sweep() > 0 ? 1.0 : -1.0) * std::atan2(ur * vz - uz * vr, ur * vr + uz * vz);
    return even_arcs_[e].ends == 2 ? std::abs(arc.sweep()) - from_start : from_start;
  }

  double OutlineStructures::boundary_coordinate(const int e, const double r, const double z) const
  {
    const EvenArc &even = even_arcs_[e];
    if (even.ends == 0)
      return omegas_[e].edge_coordinate(r, z).value;
    const double phi = angle_from_even_end(e, r, z);
    if (even.ends == 3)
      return -std::cos(M_PI * phi / std::abs(body_.outline.edges()[e].sweep()));
    const double eta = phi / even.angle_max;
    return 2.0 * eta * eta - 1.0;
  }

  std::array<int, 2> OutlineStructures::displacement_degree_reduction(const int m) const
  {
    std::array<int, 2> degree{0, 0}; // of the omega product, in r and in z
    for (const int e : m == 0 ? u_r_edges_ : u_z_edges_)
      {
        const OutlineEdge &edge = body_.outline.edges()[e];
        const axisym::Point n = edge.outward_normal_at(0.5);
        if (edge.kind != OutlineEdge::Kind::line)
          degree[0] += 2, degree[1] += 2;
        else if (std::abs(std::abs(n.r) - 1.0) < 1e-12)
          degree[0] += 1;
        else if (std::abs(std::abs(n.z) - 1.0) < 1e-12)
          degree[1] += 1;
        else
          degree[0] += 1, degree[1] += 1;
      }
    return {std::max(0, degree[0] - 1), std::max(0, degree[1] - 1)};
  }

  std::array<double, 3> OutlineStructures::tangent_tensor(const int e, const double r,
                                                          const double z) const
  {
    const auto t = omegas_[e].tangent(r, z);
    return {t[0] * t[0], t[1] * t[1], t[0] * t[1]};
  }

  std::array<double, 3> OutlineStructures::particular(const int e, const double r,
                                                      const double z) const
  {
    const PartCondition &c = body_.condition_of_edge(e);
    if (c.kind == PartCondition::Kind::pressure)
      return {-c.pressure, -c.pressure, 0.0};
    if (c.kind != PartCondition::Kind::traction)
      return {0.0, 0.0, 0.0};
    // t n + n t - (t . n) n n with n the outward normal field (exact on the edge).
    const auto tau = omegas_[e].tangent(r, z);
    const double n_r = tau[1], n_z = -tau[0];
    const double t_r = c.traction[0], t_z = c.traction[1], tn = t_r * n_r + t_z * n_z;
    return {2 * t_r * n_r - tn * n_r * n_r, 2 * t_z * n_z - tn * n_z * n_z,
            t_r * n_z + t_z * n_r - tn * n_r * n_z};
  }

  std::array<double, 2> OutlineStructures::prescribed_traction(const int e, const double r,
                                                               const double z) const
  {
    const PartCondition &c = body_.condition_of_edge(e);
    const auto tau = omegas_[e].tangent(r, z);
    const double norm = std::hypot(tau[0], tau[1]);
    const double n_r = tau[1] / norm, n_z = -tau[0] / norm;
    if (c.kind == PartCondition::Kind::pressure)
      return {-c.pressure * n_r, -c.pressure * n_z};
    if (c.kind == PartCondition::Kind::traction)
      return {c.traction[0], c.traction[1]};
    return {0.0, 0.0};
  }

  void OutlineStructures::set_indentations(const std::vector<double> &delta)
  {
    if (delta.size() != zones_.size())
      throw std::invalid_argument("OutlineStructures::set_indentations: " + std::to_string(delta.size()) +
                                  " values for " + std::to_string(zones_.size()) + " zones");
    for (std::size_t i = 0; i < zones_.size(); ++i)
      zones_[i].indentation = delta[i];
  }

  double OutlineStructures::die_normal_displacement(const int edge, const double r,
                                                    const double z) const
  {
    const Zone &zone = zones_.at(zone_of_edge_.at(edge));
    const double s = std::min(std::abs(zone.frame.coordinate({r, z})), zone.profile.extent());
    return zone.profile.gap(s) - zone.indentation;
  }

  RValue OutlineStructures::prescribed(const Prescribed &v, const double r, const double z) const
  {
    if (v.zone < 0)
      return {v.constant, 0.0, 0.0};
    // u_m = n_m (g0(|s|) - delta), s = (x - centre) . t; dg0/ds by a central difference of
    // the profile (smooth inside a zone: g0 is C1 at a rounded punch's flat end).
    const Zone &zone = zones_[v.zone];
    const double s = zone.frame.coordinate({r, z});
    const double h = 1e-6 * (std::abs(s) + 1e-3 * (zone.frame.s_max - zone.frame.s_min));
    // A flat punch's surface ends at its edge: its value there is continued beyond (the blend
    // evaluates the prescribed value off the zone too).
    const auto g = [&](double x) { return zone.profile.gap(std::min(std::abs(x), zone.profile.extent())); };
    const double value = zone.sign * (g(s) - zone.indentation);
    const double slope = zone.sign * (g(s + h) - g(s - h)) / (2 * h);
    if (zone.fade_end == 0.0)
      return {value, slope * zone.frame.tangent.r, slope * zone.frame.tangent.z};
    // Faded: value psi(|s|) psi(n), n into the body (-normal).
    const double n = -((r - zone.frame.center.r) * zone.frame.normal.r +
                       (z - zone.frame.center.z) * zone.frame.normal.z);
    const auto psi = [](const double x, const double start,
                        const double end) -> std::array<double, 2> {
      const double w = end - start;
      const double t = (x - start) / w;
      if (t <= 0.0)
        return {1.0, 0.0};
      if (t >= 1.0)
        return {0.0, 0.0};
      // 1 - (10 t^3 - 15 t^4 + 6 t^5): C2 at both ends.
      return {1.0 - t * t * t * (10.0 - 15.0 * t + 6.0 * t * t),
              -30.0 * t * t * (1.0 - t) * (1.0 - t) / w};
    };
    const auto ps = psi(std::abs(s), zone.fade_start, zone.fade_end);
    const auto pn = psi(std::max(n, 0.0), zone.fade_normal_start, zone.fade_normal_end);
    const double d_s = slope * ps[0] * pn[0] + value * (s < 0 ? -ps[1] : ps[1]) * pn[0];
    const double d_n = n > 0.0 ? value * ps[0] * pn[1] : 0.0;
    return {value * ps[0] * pn[0],
            d_s * zone.frame.tangent.r - d_n * zone.frame.normal.r,
            d_s * zone.frame.tangent.z - d_n * zone.frame.normal.z};
  }

  RValue OutlineStructures::blend(const std::vector<int> &edges,
                                  const std::vector<Prescribed> &values, const double r,
                                  const double z) const
  {
    // sum_e v_e prod_{f != e} w_f / sum_g prod_{h != g} w_h, with product-rule gradients.
    RValue num{0, 0, 0}, den{0, 0, 0};
    for (std::size_t e = 0; e < edges.size(); ++e)
      {
        RValue p{1, 0, 0};
        for (std::size_t f = 0; f < edges.size(); ++f)
          if (f != e)
            p = product(p, omegas_[edges[f]](r, z));
        const RValue v = prescribed(values[e], r, z);
        num = {num.value + v.value * p.value, num.d_r + v.value * p.d_r + v.d_r * p.value,
               num.d_z + v.value * p.d_z + v.d_z * p.value};
        den = {den.value + p.value, den.d_r + p.d_r, den.d_z + p.d_z};
      }
    if (den.value == 0.0)
      return {0, 0, 0}; // a corner of two constrained edges: any value is as good
    const double q = num.value / den.value;
    return {q, (num.d_r - q * den.d_r) / den.value, (num.d_z - q * den.d_z) / den.value};
  }

  double OutlineStructures::shear_factor(const int e, const double r, const double z) const
  {
    if (shear_y_edges_[e].empty())
      return 1.0;
    const double l = body_.outline.size();
    double omega_y = 1.0;
    for (const int y : shear_y_edges_[e])
      omega_y *= omegas_[y](r, z).value / l;
    const double w = omegas_[e](r, z).value / l;
    return omega_y + w > 0.0 ? omega_y / (omega_y + w) : 0.0;
  }

  double OutlineStructures::blend_normal(const std::vector<double> &w, std::vector<double> &weight,
                                         const StressEdge skip, const double r, const double z,
                                         const int component) const
  {
    const std::size_t n_s = stress_edges_.size();
    transfinite_weights(w, weight, [&](std::size_t e) { return stress_kind_[e] != skip; });
    double value = 0.0;
    for (std::size_t e = 0; e < n_s; ++e)
      if (weight[e] != 0.0)
        value += weight[e] * particular(stress_edges_[e], r, z)[component];
    return value;
  }

  // 3. Structures at points.
  OutlineStressValues OutlineStructures::stress(const Eigen::Ref<const Eigen::VectorXd> &r,
                                                const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    const Eigen::Index n = r.size(), n_s = static_cast<Eigen::Index>(stress_edges_.size());
    const int n_b = degree_ + 1;
    OutlineStressValues v;
    v.omega.resize(n, n_stress_components);
    v.s0.setZero(n, n_stress_components);
    for (auto &b : v.boundary)
      b.setZero(n, n_boundary_columns());
    std::vector<double> w(n_s), weight(n_s), weight_rr(n_s), weight_zz(n_s), chain_omega;
    Eigen::VectorXd legendre(n_b);
    for (Eigen::Index k = 0; k < n; ++k)
      {
        const double rk = r[k], zk = z[k];
        double omega_y = 1.0;
        for (Eigen::Index e = 0; e < n_s; ++e)
          w[e] = omegas_[stress_edges_[e]](rk, zk).value;
        // omega_T: the product over the smooth chains of the R0 conjunction of each chain's
        // omegas (x + y - sqrt(x^2 + y^2), zero where either is).
        chain_omega.assign(n_stress_chains_, -1.0);
        for (Eigen::Index e = 0; e < n_s; ++e)
          {
            const int chain = stress_chain_[e];
            double &c = chain_omega[chain];
            if (chain_line_[chain] >= 0) // a straight chain: its line's omega, once
              c = c < 0.0 ? line_chain_omegas_[chain_line_[chain]](rk, zk).value : c;
            else
              c = c < 0.0 ? w[e] : c + w[e] - std::hypot(c, w[e]);
          }
        double omega_t = 1.0;
        for (const double c : chain_omega)
          omega_t *= c;
        for (const int y : symmetry_edges_)
          omega_y *= omegas_[y](rk, zk).value;
        // omega_rr (omega_zz): the chains that prescribe sigma_rr (sigma_zz): all but the lone
        // edges along r (along z).
        double omega_rr = 1.0, omega_zz = 1.0;
        for (int c = 0; c < n_stress_chains_; ++c)
          {
            omega_rr *= chain_kind_[c] == StressEdge::normal_z ? 1.0 : chain_omega[c];
            omega_zz *= chain_kind_[c] == StressEdge::normal_r ? 1.0 : chain_omega[c];
          }
        v.omega(k, rr) = omega_rr;
        v.omega(k, zz) = omega_zz;
        v.omega(k, rz) = omega_t * omega_y;
        v.omega(k, tt) = 1.0;
        if (n_s == 0)
          continue;

        // Transfinite weights W_e (on an S corner, shared equally by the edges through it).
        transfinite_weights(w, weight, [](std::size_t) { return true; });

        // The normal components blend over the edges that prescribe them only (a lone edge
        // along z leaves sigma_zz free, one along r sigma_rr), so that at a corner between
        // such edges the blend is smooth: weights_rr and weights_zz.
        const std::array<double, 2> s0_normal = {
          blend_normal(w, weight_rr, StressEdge::normal_z, rk, zk, 0),
          blend_normal(w, weight_zz, StressEdge::normal_r, rk, zk, 1)};
        v.s0(k, rr) = s0_normal[0];
        v.s0(k, zz) = s0_normal[1];
        for (Eigen::Index e = 0; e < n_s; ++e)
          {
            const int edge = stress_edges_[e];
            const double g = shear_factor(edge, rk, zk);
            const auto s0 = particular(edge, rk, zk);
            v.s0(k, rz) += weight[e] * g * s0[2];
            const int slot = boundary_slot_[e];
            if (slot < 0)
              continue;
            const auto t = tangent_tensor(edge, rk, zk);
            // Legendre P_0..P_degree at the edge coordinate.
            const double xi = boundary_coordinate(edge, rk, zk);
            legendre[0] = 1.0;
            if (n_b > 1)
              legendre[1] = xi;
            for (int j = 2; j < n_b; ++j)
              legendre[j] = ((2 * j - 1) * xi * legendre[j - 1] - (j - 1) * legendre[j - 2]) / j;
            for (int j = 0; j < n_b; ++j)
              {
                const Eigen::Index col = slot * n_b + j;
                const double b = weight[e] * legendre[j];
                v.boundary[rr](k, col) = b * t[0];
                v.boundary[zz](k, col) = b * t[1];
                v.boundary[rz](k, col) = b * g * t[2];
              }
          }
      }
    return v;
  }

  OutlineDisplacementValues
  OutlineStructures::displacement(const Eigen::Ref<const Eigen::VectorXd> &r,
                                  const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    const Eigen::Index n = r.size();
    OutlineDisplacementValues v;
    for (Eigen::MatrixXd *m : {&v.omega, &v.omega_r, &v.omega_z})
      m->resize(n, 2);
    for (Eigen::MatrixXd *m : {&v.u0, &v.u0_r, &v.u0_z})
      m->setZero(n, 2);
    const std::array<const std::vector<int> *, 2> sets{&u_r_edges_, &u_z_edges_};
    const std::array<const std::vector<Prescribed> *, 2> values{&u_r_values_, &u_z_values_};
    for (int m = 0; m < 2; ++m)
      {
        const bool prescribed = std::any_of(values[m]->begin(), values[m]->end(),
                                            [](const Prescribed &x) {
                                              return x.constant != 0.0 || x.zone >= 0;
                                            });
        for (Eigen::Index k = 0; k < n; ++k)
          {
            RValue w{1, 0, 0};
            for (const int e : *sets[m])
              w = product(w, omegas_[e](r[k], z[k]));
            v.omega(k, m) = w.value, v.omega_r(k, m) = w.d_r, v.omega_z(k, m) = w.d_z;
            if (prescribed)
              {
                const RValue u0 = blend(*sets[m], *values[m], r[k], z[k]);
                v.u0(k, m) = u0.value, v.u0_r(k, m) = u0.d_r, v.u0_z(k, m) = u0.d_z;
              }
          }
      }
    return v;
  }
} // namespace rfm
