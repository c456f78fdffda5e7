#include "problem/problem.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace axisym
{
  namespace
  {
    using nlohmann::json;

    std::string show(const json &v)
    {
      std::string s = v.dump();
      return s.size() > 60 ? s.substr(0, 57) + "..." : s;
    }

    [[noreturn]] void fail(const std::string &path, const json &value, const std::string &rule)
    {
      throw InputError("problem file: " + path + " = " + show(value) + ": " + rule);
    }

    // An object whose keys must all be known; fields are read through it.
    class ObjectReader
    {
    public:
      ObjectReader(const json &j, std::string path, std::set<std::string> known)
        : j_(j), path_(std::move(path))
      {
        if (!j.is_object())
          fail(path_, j, "must be a JSON object");
        for (auto it = j.begin(); it != j.end(); ++it)
          if (!known.count(it.key()))
            {
              std::string list;
              for (const auto &k : known)
                list += (list.empty() ? "" : ", ") + k;
              throw InputError("problem file: unknown key " + field(it.key()) +
                               " (known keys: " + list + ")");
            }
      }

      bool has(const std::string &key) const { return j_.contains(key); }
      std::string field(const std::string &key) const
      {
        return path_.empty() ? key : path_ + "." + key;
      }

      /// A finite number; `rule` describes the accepted range, `ok` checks it.
      template <typename Check>
      double number(const std::string &key, const std::string &rule, Check ok) const
      {
        if (!has(key))
          throw InputError("problem file: missing field " + field(key) + " (" + rule + ")");
        const json &v = j_.at(key);
        if (!v.is_number())
          fail(field(key), v, "must be a number (" + rule + ")");
        const double x = v.get<double>();
        if (!std::isfinite(x) || !ok(x))
          fail(field(key), v, rule);
        return x;
      }

      /// An integer in the range of the table in problem/settings.h.
      int integer(const std::string &key, const IntRange &range) const
      {
        const json &v = j_.at(key);
        if (!v.is_number_integer())
          fail(field(key), v, "must be " + range.rule());
        const long long x = v.get<long long>();
        if (!range.contains(x))
          fail(field(key), v, "must be " + range.rule());
        return static_cast<int>(x);
      }

      std::string string(const std::string &key, const std::set<std::string> &allowed) const
      {
        const json &v = j_.at(key);
        std::string list;
        for (const auto &a : allowed)
          list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
        if (!v.is_string() || !allowed.count(v.get<std::string>()))
          fail(field(key), v, "must be one of " + list);
        return v.get<std::string>();
      }

      const json &at(const std::string &key) const { return j_.at(key); }

    private:
      const json &j_;
      std::string path_;
    };

    auto positive = [](double x) { return x > 0.0; };
  } // namespace

  const char *to_string(const PartCondition::Kind kind)
  {
    switch (kind)
      {
        case PartCondition::Kind::traction_free: return "traction free";
        case PartCondition::Kind::pressure: return "pressure";
        case PartCondition::Kind::traction: return "traction";
        case PartCondition::Kind::symmetry: return "symmetry";
        case PartCondition::Kind::displacement: return "displacement";
        case PartCondition::Kind::die: return "die";
        case PartCondition::Kind::axis: return "axis";
      }
    return "?";
  }

  bool BodyLoads::any() const
  {
    return angular_velocity != 0.0 || gravity != 0.0 || temperature[0] != 0.0 ||
           temperature[1] != 0.0 || temperature[2] != 0.0;
  }

  bool BodyLoads::thermal() const
  {
    return temperature[0] != 0.0 || temperature[1] != 0.0 || temperature[2] != 0.0;
  }

  std::array<double, 2> body_force(const BodyLoads &loads, const Material &material,
                                   const double r, const double /*z*/)
  {
    if (!loads.body_force())
      return {0.0, 0.0};
    const double rho = material.density.value();
    return {rho * loads.angular_velocity * loads.angular_velocity * r, -rho * loads.gravity};
  }

  double thermal_strain(const BodyLoads &loads, const Material &material, const double r,
                        const double z)
  {
    if (!loads.thermal())
      return 0.0;
    const auto &t = loads.temperature;
    return material.thermal_expansion.value() * (t[0] + t[1] * r + t[2] * z);
  }

  const PartCondition &Body::condition_of_edge(const int i) const
  {
    return conditions.at(outline.edges().at(i).part);
  }

  std::vector<std::string> Body::die_parts() const
  {
    std::vector<std::string> out;
    for (const std::string &part : outline.parts())
      if (conditions.at(part).kind == PartCondition::Kind::die)
        out.push_back(part);
    return out;
  }

  const char *to_string(const DieProfile::Shape shape)
  {
    switch (shape)
      {
        case DieProfile::Shape::paraboloid: return "paraboloid";
        case DieProfile::Shape::flat_rounded: return "flat_rounded";
        case DieProfile::Shape::flat: return "flat";
      }
    return "?";
  }

  double DieProfile::gap(const double s) const
  {
    switch (shape)
      {
        case Shape::paraboloid: return s * s / (2.0 * radius);
        case Shape::flat_rounded:
          return s <= flat_radius ? 0.0
                                  : (s - flat_radius) * (s - flat_radius) / (2.0 * edge_radius);
        case Shape::flat: return s <= radius ? 0.0 : std::numeric_limits<double>::infinity();
      }
    return 0.0;
  }

  double DieProfile::slope(const double s) const
  {
    switch (shape)
      {
        case Shape::paraboloid: return s / radius;
        case Shape::flat_rounded: return s <= flat_radius ? 0.0 : (s - flat_radius) / edge_radius;
        case Shape::flat: return 0.0;
      }
    return 0.0;
  }

  double DieProfile::curvature(const double s) const
  {
    switch (shape)
      {
        case Shape::paraboloid: return 1.0 / radius;
        case Shape::flat_rounded: return s < flat_radius ? 0.0 : 1.0 / edge_radius;
        case Shape::flat: return 0.0;
      }
    return 0.0;
  }

  std::vector<double> DieProfile::kinks() const
  {
    return shape == Shape::flat_rounded ? std::vector<double>{flat_radius} : std::vector<double>{};
  }

  double DieProfile::extent() const
  {
    return shape == Shape::flat ? radius : std::numeric_limits<double>::infinity();
  }

  namespace
  {
    // The line of a straight part: the frame with the centre at the first edge's start.
    // Throws InputError (naming `path`) for an arc or edges off one line.
    DieFrame part_line(const Outline &outline, const std::string &part, const std::string &path)
    {
      DieFrame f;
      bool first = true;
      const double tol = Outline::point_tolerance * outline.size();
      for (std::size_t i = 0; i < outline.edges().size(); ++i)
        {
          const OutlineEdge &e = outline.edges()[i];
          if (e.part != part)
            continue;
          const std::string edge = "geometry.outline[" + std::to_string(i + 1) + "]";
          if (e.kind == OutlineEdge::Kind::arc)
            throw InputError("problem file: " + path + ": part " + part + " has an arc (" +
                             edge + "); a die needs a straight part (lines on one line)");
          if (first)
            {
              f.center = e.start;
              f.tangent = e.tangent_at(0.0);
              f.normal = e.outward_normal_at(0.0);
              first = false;
            }
          for (const Point x : {e.start, e.end})
            {
              const double off = (x.r - f.center.r) * f.normal.r + (x.z - f.center.z) * f.normal.z;
              if (std::abs(off) > tol)
                throw InputError("problem file: " + path + ": the edges of part " + part +
                                 " are not on one line (" + edge + " is " + show(off) +
                                 " m off it); a die needs a straight part");
              const double s = f.coordinate(x);
              f.s_min = std::min(f.s_min, s), f.s_max = std::max(f.s_max, s);
            }
          // Edges on one line: the same direction of travel (a part that turns back on itself
          // would not be simple, which the outline already refuses).
        }
      return f;
    }
  } // namespace

  DieFrame die_frame(const Body &body, const std::string &part)
  {
    DieFrame f = part_line(body.outline, part, "boundary." + part + ".die");
    const Point c = body.conditions.at(part).die.center;
    const double s = f.coordinate(c);
    f.center = c, f.s_min -= s, f.s_max -= s;
    f.tolerance = 1e-9 * body.outline.size();
    return f;
  }

  namespace
  {
    auto any_number = [](double) { return true; };

    void parse_material(const ObjectReader &top, Problem &p)
    {
      if (!top.has("material"))
        throw InputError("problem file: missing object material");
      const ObjectReader m(top.at("material"), "material",
                           {"youngs_modulus", "poisson_ratio", "density", "thermal_expansion"});
      p.material.youngs_modulus = m.number("youngs_modulus", "must be > 0 [Pa]", positive);
      p.material.poisson_ratio = m.number("poisson_ratio", "must be in (-1, 0.5)",
                                          [](double x) { return x > -1.0 && x < 0.5; });
      if (m.has("density"))
        p.material.density = m.number("density", "must be > 0 [kg/m^3]", positive);
      if (m.has("thermal_expansion"))
        p.material.thermal_expansion =
          m.number("thermal_expansion", "a finite coefficient [1/K]", any_number);
    }

    /// [a, b] with two finite numbers.
    std::array<double, 2> pair_of_numbers(const json &v, const std::string &path,
                                          const std::string &what)
    {
      if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() ||
          !std::isfinite(v[0].get<double>()) || !std::isfinite(v[1].get<double>()))
        fail(path, v, "must be a pair " + what + " of finite numbers");
      return {v[0].get<double>(), v[1].get<double>()};
    }

    // contact: the method and its settings; a fixed half-width in (0, limit].
    void parse_contact(const ObjectReader &top, Problem &p, const double limit,
                       const std::string &limit_name)
    {
      const ObjectReader c(top.at("contact"), "contact", {"method", "half_width", "curve_points"});
      if (c.has("curve_points"))
        p.contact.curve_points = c.integer("curve_points", ranges::contact_curve_points);
      if (c.has("method"))
        p.contact.method = c.string("method", {"edge-intensity", "fixed", "iterate", "max-force"});
      if (c.has("half_width"))
        p.contact.half_width = c.number(
          "half_width", "must be in (0, " + limit_name + " = " + show(limit) + "] [m]",
          [&](double x) { return x > 0.0 && x <= limit * (1 + 1e-12); });
    }

    // boundary.PART.die of the outline form (DESIGN.md 7.1).
    DieCondition parse_die(const json &j, const std::string &path, const Body &body,
                           const std::string &part)
    {
      const ObjectReader d(j, path, {"indentation", "force", "center", "profile"});
      DieCondition die;
      if (d.has("indentation") == d.has("force"))
        fail(path, j, "needs exactly one of indentation [m] and force [N]");
      const DieFrame line = part_line(body.outline, part, path);
      const double size = body.outline.size();
      if (d.has("indentation"))
        {
          // Small strain (as the hollow-cylinder form's die): delta small against the section.
          const double limit = 1e-2 * size;
          die.indentation = d.number("indentation",
                                     "must be in (0, " + show(limit) +
                                       "] [m] (0.01 of the section's size: small strain)",
                                     [&](double x) { return x > 0.0 && x <= limit; });
        }
      else
        die.force = d.number("force", "must be > 0 [N] (the whole body of revolution)", positive);

      // The centre: given (on the part), or the part's end on a symmetry edge or the axis
      // (where the field is mirrored: a die centred there), else the part's midpoint.
      if (d.has("center"))
        {
          const auto c = pair_of_numbers(d.at("center"), path + ".center", "[r, z] [m]");
          die.center = {c[0], c[1]};
          const double off = (c[0] - line.center.r) * line.normal.r +
                             (c[1] - line.center.z) * line.normal.z;
          const double s = line.coordinate(die.center);
          const double tol = Outline::point_tolerance * size;
          if (std::abs(off) > tol || s < line.s_min - tol || s > line.s_max + tol)
            fail(path + ".center", d.at("center"), "must lie on part " + part);
        }
      else
        {
          auto mirrored_end = [&](double s) {
            const Point x = line.point_at(s);
            for (const OutlineEdge &e : body.outline.edges())
              {
                if (e.part == part)
                  continue;
                const bool touches =
                  std::hypot(e.start.r - x.r, e.start.z - x.z) < 1e-9 * size ||
                  std::hypot(e.end.r - x.r, e.end.z - x.z) < 1e-9 * size;
                const PartCondition::Kind k = body.conditions.at(e.part).kind;
                if (touches && (k == PartCondition::Kind::axis || k == PartCondition::Kind::symmetry))
                  return true;
              }
            return std::abs(x.r) < 1e-9 * size; // the part ends on the axis itself
          };
          const double s = mirrored_end(line.s_min)   ? line.s_min
                           : mirrored_end(line.s_max) ? line.s_max
                                                      : 0.5 * (line.s_min + line.s_max);
          die.center = line.point_at(s);
        }

      if (!d.has("profile"))
        throw InputError("problem file: missing field " + path + ".profile ({\"shape\": "
                         "\"paraboloid\", \"radius\": R}, {\"shape\": \"flat_rounded\", "
                         "\"flat_radius\": b, \"edge_radius\": rho} or {\"shape\": \"flat\", "
                         "\"radius\": b})");
      const json &pj = d.at("profile");
      const std::string ppath = path + ".profile";
      if (!pj.is_object() || !pj.contains("shape"))
        fail(ppath, pj, "must be an object with a shape (paraboloid, flat_rounded, flat)");
      const ObjectReader shape_reader(pj, ppath, {"shape", "radius", "flat_radius", "edge_radius"});
      const std::string shape =
        shape_reader.string("shape", {"paraboloid", "flat_rounded", "flat"});
      const std::set<std::string> wanted =
        shape == "flat_rounded" ? std::set<std::string>{"shape", "flat_radius", "edge_radius"}
                                : std::set<std::string>{"shape", "radius"};
      const ObjectReader pr(pj, ppath, wanted); // the keys of this shape only
      DieProfile &profile = die.profile;
      if (shape == "flat_rounded")
        {
          profile.shape = DieProfile::Shape::flat_rounded;
          profile.flat_radius = pr.number("flat_radius", "must be > 0 [m]", positive);
          profile.edge_radius = pr.number("edge_radius", "must be > 0 [m]", positive);
        }
      else
        {
          profile.shape =
            shape == "flat" ? DieProfile::Shape::flat : DieProfile::Shape::paraboloid;
          profile.radius = pr.number("radius", "must be > 0 [m]", positive);
        }

      // A flat face must end on the part where the part goes on beyond the centre (a punch
      // wider than its face would press on the corner).
      const double flat = shape == "flat"           ? profile.radius
                           : shape == "flat_rounded" ? profile.flat_radius
                                                     : 0.0;
      const double s_c = line.coordinate(die.center);
      const double tol = Outline::point_tolerance * size;
      for (const double reach : {s_c - line.s_min, line.s_max - s_c})
        if (reach > tol && flat >= reach)
          fail(ppath + (shape == "flat" ? ".radius" : ".flat_radius"), flat,
               "the flat face must end on part " + part + " (it reaches " + show(reach) +
                 " m from the centre there)");
      return die;
    }

    // geometry.outline, boundary, loading (body loads) and samples of the outline form.
    void parse_outline_form(const ObjectReader &top, Problem &p)
    {
      p.legacy_cylinder = false;
      if (top.has("die"))
        throw InputError("problem file: die: the top-level die is the hollow-cylinder form's "
                         "(geometry.inner_radius, outer_radius, length); with geometry.outline "
                         "a die is a condition of its part: boundary.PART.die");
      const ObjectReader g(top.at("geometry"), "geometry", {"outline"});
      const json &o = g.at("outline");
      if (!o.is_array() || o.size() < 3)
        fail("geometry.outline", o, "must be an array: {\"start\": [r, z]} and at least two edges");
      const ObjectReader first(o[0], "geometry.outline[0]", {"start"});
      if (!first.has("start"))
        throw InputError("problem file: geometry.outline[0]: must be {\"start\": [r, z]}");
      const auto s0 = pair_of_numbers(first.at("start"), "geometry.outline[0].start", "[r, z] [m]");
      std::vector<OutlineEdge> edges;
      Point previous{s0[0], s0[1]};
      for (std::size_t i = 1; i < o.size(); ++i)
        {
          const std::string path = "geometry.outline[" + std::to_string(i) + "]";
          const ObjectReader e(o[i], path, {"line_to", "arc_to", "center", "part"});
          OutlineEdge edge;
          if (e.has("line_to") == e.has("arc_to"))
            fail(path, o[i], "needs exactly one of line_to, arc_to");
          const bool arc = e.has("arc_to");
          if (!arc && e.has("center"))
            fail(path + ".center", e.at("center"), "only an arc_to edge takes a center");
          if (arc && !e.has("center"))
            throw InputError("problem file: missing field " + path + ".center (arc_to needs it)");
          edge.kind = arc ? OutlineEdge::Kind::arc : OutlineEdge::Kind::line;
          const auto end = pair_of_numbers(e.at(arc ? "arc_to" : "line_to"),
                                           path + (arc ? ".arc_to" : ".line_to"), "[r, z] [m]");
          edge.start = previous;
          edge.end = {end[0], end[1]};
          if (arc)
            {
              const auto c = pair_of_numbers(e.at("center"), path + ".center", "[r, z] [m]");
              edge.center = {c[0], c[1]};
            }
          if (!e.has("part") || !e.at("part").is_string() ||
              e.at("part").get<std::string>().empty())
            fail(path + ".part", e.has("part") ? e.at("part") : json(nullptr),
                 "must name the boundary part (a non-empty string)");
          edge.part = e.at("part").get<std::string>();
          previous = edge.end;
          edges.push_back(edge);
        }
      Body body{Outline({s0[0], s0[1]}, std::move(edges), "geometry.outline"), {}, false};
      const Outline &outline = body.outline;

      // A part lies on the axis entirely or not at all; the axis parts take no condition.
      std::set<std::string> axis_parts;
      const std::vector<int> axis_edges = outline.axis_edges();
      for (const int i : axis_edges)
        axis_parts.insert(outline.edges()[i].part);
      for (std::size_t i = 0; i < outline.edges().size(); ++i)
        {
          const OutlineEdge &e = outline.edges()[i];
          const bool on_axis = std::find(axis_edges.begin(), axis_edges.end(),
                                         static_cast<int>(i)) != axis_edges.end();
          if (axis_parts.count(e.part) && !on_axis)
            fail("geometry.outline[" + std::to_string(i + 1) + "].part", e.part,
                 "names an axis part (an edge on r = 0) for an edge off the axis");
        }
      for (const std::string &part : outline.parts())
        body.conditions[part].kind = axis_parts.count(part) ? PartCondition::Kind::axis
                                                            : PartCondition::Kind::traction_free;

      if (top.has("boundary"))
        {
          const json &b = top.at("boundary");
          if (!b.is_object())
            fail("boundary", b, "must be an object of part names");
          for (auto it = b.begin(); it != b.end(); ++it)
            {
              const std::string path = "boundary." + it.key();
              if (!body.conditions.count(it.key()))
                {
                  std::string list;
                  for (const auto &part : outline.parts())
                    list += (list.empty() ? "" : ", ") + part;
                  throw InputError("problem file: " + path + ": no such part in geometry.outline "
                                   "(parts: " + list + ")");
                }
              PartCondition &c = body.conditions[it.key()];
              if (c.kind == PartCondition::Kind::axis)
                throw InputError("problem file: " + path + ": part on the axis r = 0, which takes "
                                 "no condition (u_r = 0 and sigma_rz = 0 are implied)");
              const ObjectReader cond(it.value(), path,
                                      {"pressure", "traction", "symmetry", "displacement", "die"});
              if (it.value().size() != 1)
                fail(path, it.value(),
                     "needs exactly one of pressure, traction, symmetry, displacement, die");
              if (cond.has("die"))
                c.kind = PartCondition::Kind::die; // read below, once every part has its kind
              else if (cond.has("pressure"))
                {
                  c.kind = PartCondition::Kind::pressure;
                  c.pressure = cond.number("pressure", "a finite pressure [Pa]", any_number);
                }
              else if (cond.has("traction"))
                {
                  c.kind = PartCondition::Kind::traction;
                  c.traction = pair_of_numbers(cond.at("traction"), path + ".traction",
                                               "[t_r, t_z] [Pa]");
                }
              else if (cond.has("displacement"))
                {
                  c.kind = PartCondition::Kind::displacement;
                  c.displacement = pair_of_numbers(cond.at("displacement"),
                                                   path + ".displacement", "[u_r, u_z] [m]");
                }
              else
                {
                  if (cond.at("symmetry") != json(true))
                    fail(path + ".symmetry", cond.at("symmetry"), "must be true");
                  for (const OutlineEdge &e : outline.edges())
                    if (e.part == it.key() && e.kind == OutlineEdge::Kind::arc)
                      fail(path + ".symmetry", cond.at("symmetry"),
                           "symmetry needs straight edges, and part " + it.key() +
                             " has an arc");
                  c.kind = PartCondition::Kind::symmetry;
                }
            }
        }

      // Dies last: the default centre depends on the neighbouring parts' conditions.
      for (const std::string &part : body.die_parts())
        body.conditions[part].die = parse_die(top.at("boundary").at(part).at("die"),
                                              "boundary." + part + ".die", body, part);

      // The rigid translation in z must be fixed (a symmetry plane z = const, a
      // displacement, or a die given by its indentation on a part that is not vertical: it
      // prescribes the normal displacement on its zone), or neither solver has a unique
      // solution.
      bool fixes_u_z = false;
      for (const OutlineEdge &e : outline.edges())
        {
          const PartCondition &c = body.conditions.at(e.part);
          const bool not_vertical = std::abs(e.outward_normal_at(0.5).z) > 1e-12;
          fixes_u_z |= c.kind == PartCondition::Kind::displacement ||
                       (c.kind == PartCondition::Kind::symmetry && not_vertical) ||
                       (c.kind == PartCondition::Kind::die && c.die.indentation && not_vertical);
        }
      if (!fixes_u_z)
        throw InputError("problem file: boundary: no part fixes the rigid translation in z "
                         "(needs a displacement part, a symmetry part that is not vertical, or a "
                         "die by indentation on a part that is not vertical)");
      if (top.has("contact"))
        {
          if (body.die_parts().empty())
            throw InputError("problem file: contact: only with a die (boundary.PART.die)");
          parse_contact(top, p, std::numeric_limits<double>::infinity(), "the die's part");
        }

      if (top.has("loading"))
        {
          const ObjectReader l(top.at("loading"), "loading",
                               {"angular_velocity", "gravity", "temperature"});
          BodyLoads &loads = p.body_loads;
          if (l.has("angular_velocity"))
            loads.angular_velocity =
              l.number("angular_velocity", "a finite angular velocity [rad/s]", any_number);
          if (l.has("gravity"))
            loads.gravity = l.number("gravity", "a finite acceleration [m/s^2]", any_number);
          if (l.has("temperature"))
            {
              const ObjectReader t(l.at("temperature"), "loading.temperature", {"field"});
              const json &f = t.at("field");
              if (!f.is_array() || f.size() != 3)
                fail("loading.temperature.field", f, "must be [T0, T_r, T_z] [K, K/m, K/m]");
              for (int k = 0; k < 3; ++k)
                {
                  if (!f[k].is_number() || !std::isfinite(f[k].get<double>()))
                    fail("loading.temperature.field[" + std::to_string(k) + "]", f[k],
                         "must be a finite number");
                  loads.temperature[k] = f[k].get<double>();
                }
            }
          if ((loads.angular_velocity != 0.0 || loads.gravity != 0.0) && !p.material.density)
            throw InputError(std::string("problem file: loading.") +
                             (loads.angular_velocity != 0.0 ? "angular_velocity" : "gravity") +
                             " needs material.density (missing)");
          if ((loads.temperature[0] != 0.0 || loads.temperature[1] != 0.0 ||
               loads.temperature[2] != 0.0) &&
              !p.material.thermal_expansion)
            throw InputError("problem file: loading.temperature needs "
                             "material.thermal_expansion (missing)");
        }

      if (top.has("samples"))
        {
          const json &s = top.at("samples");
          if (!s.is_array())
            fail("samples", s, "must be an array of [r, z] pairs");
          for (std::size_t i = 0; i < s.size(); ++i)
            {
              const std::string path = "samples[" + std::to_string(i) + "]";
              const auto pt = pair_of_numbers(s[i], path, "[r, z] [m]");
              if (!outline.contains({pt[0], pt[1]}, 1e-12 * outline.size()))
                fail(path, s[i], "must lie in the section (inside geometry.outline)");
              p.samples.push_back(pt);
            }
        }
      p.body = std::move(body);
    }

    // The legacy hollow cylinder as an outline: the half section z >= 0.
    Body make_legacy_body(const Problem &p)
    {
      const double r1 = p.geometry.inner_radius, r2 = p.geometry.outer_radius;
      const double a = p.geometry.half_length();
      auto line = [](Point from, Point to, const char *part) {
        OutlineEdge e;
        e.start = from, e.end = to, e.part = part;
        return e;
      };
      Body body{Outline({r1, 0.0},
                        {line({r1, 0.0}, {r2, 0.0}, "mid_plane"),
                         line({r2, 0.0}, {r2, a}, "outer"), line({r2, a}, {r1, a}, "end"),
                         line({r1, a}, {r1, 0.0}, "inner")},
                        "geometry"),
                {}, true};
      body.conditions["mid_plane"].kind = PartCondition::Kind::symmetry;
      body.conditions["end"].kind = PartCondition::Kind::traction_free;
      PartCondition inner, outer;
      if (p.loading)
        {
          inner.kind = outer.kind = PartCondition::Kind::pressure;
          inner.pressure = p.loading->inner_pressure;
          outer.pressure = p.loading->outer_pressure;
        }
      if (p.die)
        {
          // The legacy parabolic die: u_r* = -delta (1 - 2 z^2 / a^2) is the paraboloid
          // g0 = s^2 / (2R), R = a^2 / (4 delta), centred on the mid-plane.
          outer.kind = PartCondition::Kind::die;
          outer.die.indentation = p.die->indentation;
          outer.die.center = {r2, 0.0};
          outer.die.profile.shape = DieProfile::Shape::paraboloid;
          outer.die.profile.radius = a * a / (4.0 * p.die->indentation);
        }
      body.conditions["inner"] = inner;
      body.conditions["outer"] = outer;
      return body;
    }

    void parse_settings(const ObjectReader &top, Problem &p)
  {
    // Discretization settings (both forms).
    if (top.has("rfm"))
      {
        const ObjectReader r(top.at("rfm"), "rfm",
                             {"degree", "tolerance", "max_degree", "extra_gauss_points",
                              "n_cells_r", "n_cells_z",
                              "n_graded_layers", "grading_ratio", "edge_modes", "edge_cutoff",
                              "edge_extra_points", "edge_mode_degree", "local_levels",
                              "local_degree", "local_stress_degree", "local_first_box",
                              "local_max_box", "vertex_max_exponent", "vertex_mode_degree",
                              "vertex_cutoff", "vertex_local_degree", "vertex_local_degree_ratio",
                              "vertex_local_displacement_degree", "vertex_support",
                              "resonant_displacement_degree", "axis_parity", "axis_coupling", "notch_roots",
                              "rough_vertices", "ritz_bound", "vertex_shadow", "jump_column", "vertex_inner_disc",
                              "vertex_disc_overlap",
                              "z_degree_ratio"});
        if (r.has("degree") && r.has("tolerance"))
          fail("rfm", top.at("rfm"), "give rfm.degree (fixed p) or rfm.tolerance (p rises "
                                     "until the indicator is below it), not both");
        if (r.has("degree"))
          {
            p.rfm.degree = r.integer("degree", ranges::rfm_degree);
            p.rfm.degree_given = true;
          }
        if (r.has("tolerance"))
          {
            p.rfm.tolerance = r.number("tolerance", "must be in [1e-14, 0.1]", [](double x) {
              return x >= RfmSettings::min_tolerance && x <= 0.1;
            });
            if (p.die)
              fail("rfm.tolerance", r.at("tolerance"),
                   "not for a die problem (the indicator does not see the contact-edge error; "
                   "give rfm.degree)");
          }
        if (r.has("max_degree"))
          p.rfm.max_degree = r.integer("max_degree", ranges::rfm_max_degree);
        if (r.has("extra_gauss_points"))
          p.rfm.extra_gauss_points = r.integer("extra_gauss_points", ranges::rfm_extra_gauss_points);
        if (r.has("n_cells_r"))
          p.rfm.n_cells_r = r.integer("n_cells_r", ranges::rfm_n_cells_r);
        if (r.has("n_cells_z"))
          p.rfm.n_cells_z = r.integer("n_cells_z", ranges::rfm_n_cells_z);
        if (r.has("n_graded_layers"))
          p.rfm.n_graded_layers = r.integer("n_graded_layers", ranges::rfm_n_graded_layers);
        if (r.has("grading_ratio"))
          p.rfm.grading_ratio =
            r.number("grading_ratio", "must be in (0, 1)", [](double x) { return x > 0 && x < 1; });
        if (r.has("edge_modes"))
          p.rfm.edge_modes = r.integer("edge_modes", ranges::rfm_edge_modes);
        if (r.has("edge_cutoff"))
          p.rfm.edge_cutoff = r.number(
            "edge_cutoff", "must be in (0, 1): the cutoff radius as a fraction of min(c, a - c, R2 - R1)",
            [](double x) { return x > 0 && x < 1; });
        if (r.has("edge_extra_points"))
          p.rfm.edge_extra_points = r.integer("edge_extra_points", ranges::rfm_edge_extra_points);
        if (r.has("edge_mode_degree"))
          p.rfm.edge_mode_degree = r.integer("edge_mode_degree", ranges::rfm_edge_mode_degree);
        if (r.has("vertex_max_exponent"))
          p.rfm.vertex_max_exponent = r.number(
            "vertex_max_exponent", "must be in [0, 6] (the largest Re lambda of the vertex modes; 0 is off)",
            [](double x) { return x >= 0 && x <= 6; });
        if (r.has("vertex_mode_degree"))
          p.rfm.vertex_mode_degree = r.integer("vertex_mode_degree", ranges::rfm_vertex_mode_degree);
        if (r.has("vertex_local_degree"))
          p.rfm.vertex_local_degree = r.integer("vertex_local_degree", ranges::rfm_vertex_local_degree);
        if (r.has("vertex_local_degree_ratio"))
          p.rfm.vertex_local_degree_ratio = r.number(
            "vertex_local_degree_ratio", "must be in [0.25, 1.5]: the vertex's local stress degree over p",
            [](double x) {
              return x >= RfmSettings::min_vertex_local_degree_ratio &&
                     x <= RfmSettings::max_vertex_local_degree_ratio;
            });
        if (r.has("vertex_local_displacement_degree"))
          p.rfm.vertex_local_displacement_degree =
            r.integer("vertex_local_displacement_degree", ranges::rfm_vertex_local_displacement_degree);
        if (r.has("resonant_displacement_degree"))
          p.rfm.resonant_displacement_degree =
            r.integer("resonant_displacement_degree", ranges::rfm_resonant_displacement_degree);
        if (r.has("vertex_support"))
          {
            const std::string support = r.string("vertex_support", {"local", "section", "blended"});
            p.rfm.vertex_support = support == "local"     ? RfmSettings::VertexSupport::local
                                   : support == "blended" ? RfmSettings::VertexSupport::blended
                                                          : RfmSettings::VertexSupport::section;
          }
        // The switches: JSON booleans.
        auto flag = [&](const char *key, bool &to) {
          if (!r.has(key))
            return;
          if (!r.at(key).is_boolean())
            fail(std::string("rfm.") + key, r.at(key), "must be true or false");
          to = r.at(key).get<bool>();
        };
        flag("axis_parity", p.rfm.axis_parity);
        flag("axis_coupling", p.rfm.axis_coupling);
        flag("notch_roots", p.rfm.notch_roots);
        // rough_vertices: "all" (the default: rough vertices without a jump too), or a
        // boolean (true: where a traction jumps only).
        if (r.has("rough_vertices") && r.at("rough_vertices").is_string())
          {
            if (r.at("rough_vertices").get<std::string>() != "all")
              fail("rfm.rough_vertices", r.at("rough_vertices"),
                   "must be true (where a traction jumps), false or \"all\" (every rough vertex)");
            p.rfm.rough_vertices = p.rfm.rough_vertices_everywhere = true;
          }
        else if (r.has("rough_vertices"))
          {
            flag("rough_vertices", p.rfm.rough_vertices);
            p.rfm.rough_vertices_everywhere = false;
          }
        flag("vertex_shadow", p.rfm.vertex_shadow);
        flag("jump_column", p.rfm.jump_column);
        flag("vertex_inner_disc", p.rfm.vertex_inner_disc);
        flag("vertex_disc_overlap", p.rfm.vertex_disc_overlap);
        flag("ritz_bound", p.rfm.ritz_bound);
        if (r.has("z_degree_ratio"))
          p.rfm.z_degree_ratio = r.number(
            "z_degree_ratio", "must be in [0.25, 4]: the polynomials' degree along z over the degree along r",
            [](double x) { return x >= RfmSettings::min_z_degree_ratio && x <= RfmSettings::max_z_degree_ratio; });
        if (r.has("vertex_cutoff"))
          p.rfm.vertex_cutoff = r.number(
            "vertex_cutoff", "must be in (0, 1]: the cutoff radius as a fraction of the room around the vertex",
            [](double x) { return x > 0 && x <= 1; });
        if (r.has("local_levels"))
          p.rfm.local_levels = r.integer("local_levels", ranges::rfm_local_levels);
        if (r.has("local_degree"))
          p.rfm.local_degree = r.integer("local_degree", ranges::rfm_local_degree);
        if (r.has("local_stress_degree"))
          p.rfm.local_stress_degree = r.integer("local_stress_degree", ranges::rfm_local_stress_degree);
        if (r.has("local_first_box"))
          p.rfm.local_first_box =
            r.number("local_first_box", "must be in (1, 10]", [](double x) { return x > 1 && x <= 10; });
        if (r.has("local_max_box"))
          p.rfm.local_max_box =
            r.number("local_max_box", "must be in (0, 1]", [](double x) { return x > 0 && x <= 1; });
      }
    if (top.has("fem"))
      {
        const ObjectReader f(top.at("fem"), "fem", {"degree", "refinements", "refinement"});
        if (f.has("degree"))
          p.fem.degree = f.integer("degree", ranges::fem_degree);
        if (f.has("refinements"))
          p.fem.refinements = f.integer("refinements", ranges::fem_refinements);
        if (f.has("refinement"))
          {
            const ObjectReader a(top.at("fem").at("refinement"), "fem.refinement",
                                 {"strategy", "tolerance", "max_dofs", "goal"});
            if (!a.has("strategy"))
              throw InputError("problem file: missing field fem.refinement.strategy (must be "
                               "one of \"adaptive\", \"uniform\")");
            p.fem.adaptive = a.string("strategy", {"uniform", "adaptive"}) == "adaptive";
            if (a.has("tolerance"))
              p.fem.adaptive_tolerance = a.number("tolerance", "must be in [1e-12, 1e-1]",
                                                  [](double x) { return x >= 1e-12 && x <= 1e-1; });
            if (a.has("goal"))
              p.fem.adaptive_goal_samples = a.string("goal", {"energy", "samples"}) == "samples";
            if (a.has("max_dofs"))
              p.fem.adaptive_max_dofs = static_cast<long>(a.number(
                "max_dofs", "must be a whole number in [100, 1e8]",
                [](double x) { return x >= 100 && x <= 1e8 && x == std::floor(x); }));
          }
      }
  }
  } // namespace

  Body legacy_body(const Problem &p)
  {
    return make_legacy_body(p);
  }

  Problem parse_problem(const json &j)
  {
    Problem p;
    p.source = j;
    const ObjectReader top(j, "",
                           {"geometry", "boundary", "material", "loading", "die", "contact",
                            "samples", "rfm", "fem"});

    // 1. Geometry and material (required).
    if (!top.has("geometry"))
      throw InputError("problem file: missing object geometry");
    if (top.at("geometry").is_object() && top.at("geometry").contains("outline"))
      {
        parse_material(top, p);
        parse_outline_form(top, p);
        parse_settings(top, p);
        return p;
      }
    if (top.has("boundary"))
      throw InputError("problem file: boundary: only with geometry.outline (the hollow-cylinder "
                       "form takes loading and die)");
    const ObjectReader g(top.at("geometry"), "geometry", {"inner_radius", "outer_radius", "length"});
    p.geometry.inner_radius = g.number("inner_radius", "must be > 0 [m]", positive);
    p.geometry.outer_radius = g.number("outer_radius", "must be > 0 [m]", positive);
    p.geometry.length = g.number("length", "must be > 0 [m]", positive);
    if (!(p.geometry.outer_radius > p.geometry.inner_radius))
      fail("geometry.outer_radius", p.geometry.outer_radius,
           "must exceed geometry.inner_radius = " + show(p.geometry.inner_radius));

    parse_material(top, p);

    // 2. Loads: pressures and/or a die.
    if (top.has("loading"))
      {
        const ObjectReader l(top.at("loading"), "loading", {"inner_pressure", "outer_pressure"});
        Loading loading;
        auto any = [](double) { return true; };
        if (l.has("inner_pressure"))
          loading.inner_pressure = l.number("inner_pressure", "a finite pressure [Pa]", any);
        if (l.has("outer_pressure"))
          loading.outer_pressure = l.number("outer_pressure", "a finite pressure [Pa]", any);
        p.loading = loading;
      }
    if (top.has("die"))
      {
        const ObjectReader d(top.at("die"), "die", {"indentation", "profile"});
        Die die;
        // Small strain: the indentation must be small against the wall thickness.
        const double limit = 1e-2 * (p.geometry.outer_radius - p.geometry.inner_radius);
        die.indentation = d.number("indentation",
                                   "must be in (0, " + show(limit) +
                                     "] [m] (0.01 of the wall thickness: small strain)",
                                   [&](double x) { return x > 0.0 && x <= limit; });
        if (d.has("profile"))
          die.profile = d.string("profile", {"parabolic"});
        p.die = die;
      }
    if (!p.loading && !p.die)
      throw InputError("problem file: needs at least one of the objects loading, die");

    if (top.has("contact"))
      parse_contact(top, p, p.geometry.half_length(), "length/2");

    // 3. Sample points: inside the closed section.
    if (top.has("samples"))
      {
        const json &s = top.at("samples");
        if (!s.is_array())
          fail("samples", s, "must be an array of [r, z] pairs");
        const double a = p.geometry.half_length();
        for (std::size_t i = 0; i < s.size(); ++i)
          {
            const std::string path = "samples[" + std::to_string(i) + "]";
            const json &pt = s[i];
            if (!pt.is_array() || pt.size() != 2 || !pt[0].is_number() || !pt[1].is_number())
              fail(path, pt, "must be a pair [r, z] of numbers [m]");
            const double r = pt[0].get<double>(), z = pt[1].get<double>();
            const double tol = 1e-12 * p.geometry.outer_radius;
            if (!std::isfinite(r) || !std::isfinite(z) || r < p.geometry.inner_radius - tol ||
                r > p.geometry.outer_radius + tol || std::abs(z) > a + tol)
              fail(path, pt, "must lie in the section r in [inner_radius, outer_radius], "
                             "|z| <= length/2");
            p.samples.push_back({r, z});
          }
      }

    p.body = make_legacy_body(p);
    parse_settings(top, p);
    return p;
  }

  Problem read_problem_file(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw InputError("problem file " + path + ": cannot be opened for reading");
    json j;
    try
      {
        j = json::parse(in);
      }
    catch (const json::exception &e) // parse_error, and out_of_range for 1e999
      {
        throw InputError("problem file " + path + ": malformed JSON: " + e.what());
      }
    return parse_problem(j);
  }

  double die_u_r(const Die &die, const Geometry &g, const double z)
  {
    const double a = g.half_length();
    return -die.indentation * (1.0 - 2.0 * z * z / (a * a));
  }

  double die_u_r_derivative(const Die &die, const Geometry &g, const double z)
  {
    const double a = g.half_length();
    return 4.0 * die.indentation * z / (a * a);
  }
} // namespace axisym
