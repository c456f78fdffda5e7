#include "rfm/section.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rfm
{
  const char *to_string(const Side side)
  {
    switch (side)
      {
        case Side::inner: return "inner";
        case Side::outer: return "outer";
        case Side::bottom: return "bottom";
        case Side::top: return "top";
      }
    return "?";
  }

  const char *to_string(const Condition condition)
  {
    switch (condition)
      {
        case Condition::traction: return "traction";
        case Condition::displacement: return "displacement";
        case Condition::symmetry: return "symmetry";
        case Condition::contact: return "contact";
      }
    return "?";
  }

  Section::Section(const double r_min, const double r_max, const double z_min,
                   const double z_max)
    : r_min_(r_min), r_max_(r_max), z_min_(z_min), z_max_(z_max)
  {
    if (!(r_max > r_min) || !(z_max > z_min))
      throw std::invalid_argument("Section: empty rectangle");
  }

  void Section::add_part(BoundaryPart part) { parts_.push_back(std::move(part)); }

  double Section::side_begin(const Side side) const
  {
    return (side == Side::inner || side == Side::outer) ? z_min_ : r_min_;
  }

  double Section::side_end(const Side side) const
  {
    return (side == Side::inner || side == Side::outer) ? z_max_ : r_max_;
  }

  void Section::validate() const
  {
    for (const Side side : {Side::inner, Side::outer, Side::bottom, Side::top})
      {
        std::vector<const BoundaryPart *> on_side;
        for (const auto &p : parts_)
          if (p.side == side)
            on_side.push_back(&p);
        std::sort(on_side.begin(), on_side.end(),
                  [](auto *a, auto *b) { return a->begin < b->begin; });
        const double tol = 1e-12 * (side_end(side) - side_begin(side));
        double covered = side_begin(side);
        for (const auto *p : on_side)
          {
            if (std::abs(p->begin - covered) > tol || !(p->end > p->begin))
              throw std::invalid_argument(std::string("Section: parts of side ") +
                                          to_string(side) +
                                          " must cover it without gaps or overlaps");
            covered = p->end;
            const bool radial_side = side == Side::inner || side == Side::outer;
            if (p->condition == Condition::symmetry && radial_side)
              throw std::invalid_argument("Section: part '" + p->name +
                                          "': symmetry only on bottom/top sides");
            if ((p->condition == Condition::displacement ||
                 p->condition == Condition::contact) &&
                !radial_side)
              throw std::invalid_argument("Section: part '" + p->name +
                                          "': displacement/contact only on inner/outer");
            if ((p->condition == Condition::displacement ||
                 p->condition == Condition::contact) &&
                (!p->normal_displacement || !p->normal_displacement_derivative))
              throw std::invalid_argument("Section: part '" + p->name +
                                          "' needs a normal displacement and its derivative");
          }
        if (std::abs(covered - side_end(side)) > tol)
          throw std::invalid_argument(std::string("Section: side ") + to_string(side) +
                                      " is not covered by its parts");
        // One normal stress per side keeps the particular stress field linear.
        for (const auto *p : on_side)
          for (const auto *q : on_side)
            if (p->condition == Condition::traction && q->condition == Condition::traction &&
                p->normal_stress != q->normal_stress)
              throw std::invalid_argument(std::string("Section: side ") + to_string(side) +
                                          ": traction parts must share one normal stress");
      }
  }

  RValue Section::interval_omega(const Side side, const double begin, const double end,
                                 const double r, const double z) const
  {
    // f: normalized distance to the side's line, positive inside.
    RValue f;
    switch (side)
      {
        case Side::inner: f = half_plane(r, z, r_min_, 0.0, 1.0, 0.0); break;
        case Side::outer: f = half_plane(r, z, r_max_, 0.0, -1.0, 0.0); break;
        case Side::bottom: f = half_plane(r, z, 0.0, z_min_, 0.0, 1.0); break;
        case Side::top: f = half_plane(r, z, 0.0, z_max_, 0.0, -1.0); break;
      }
    const bool radial_side = side == Side::inner || side == Side::outer;
    const double s = radial_side ? z : r;
    const double tol = 1e-12 * (side_end(side) - side_begin(side));
    const bool from_start = std::abs(begin - side_begin(side)) <= tol;
    const bool to_end = std::abs(end - side_end(side)) <= tol;
    if (from_start && to_end)
      return f;

    // t >= 0 on the part, normalized along the side.
    RValue t;
    double dt_ds;
    if (from_start)
      t.value = end - s, dt_ds = -1.0;
    else if (to_end)
      t.value = s - begin, dt_ds = 1.0;
    else
      {
        const RValue st = strip(s, begin, end);
        t.value = st.value;
        dt_ds = st.d_r;
      }
    (radial_side ? t.d_z : t.d_r) = dt_ds;
    return trimmed_segment(f, t);
  }

  std::vector<double> Section::z_breaks() const
  {
    std::vector<double> b;
    for (const auto &p : parts_)
      if (p.side == Side::inner || p.side == Side::outer)
        for (const double x : {p.begin, p.end})
          if (x > z_min_ && x < z_max_)
            b.push_back(x);
    return b;
  }

  std::vector<double> Section::r_breaks() const
  {
    std::vector<double> b;
    for (const auto &p : parts_)
      if (p.side == Side::bottom || p.side == Side::top)
        for (const double x : {p.begin, p.end})
          if (x > r_min_ && x < r_max_)
            b.push_back(x);
    return b;
  }
} // namespace rfm
