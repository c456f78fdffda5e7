#include "problem/problem.h"

#include <cmath>
#include <fstream>
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

  Problem parse_problem(const json &j)
  {
    Problem p;
    p.source = j;
    const ObjectReader top(j, "",
                           {"geometry", "material", "loading", "die", "contact", "samples",
                            "rfm", "fem"});

    // 1. Geometry and material (required).
    if (!top.has("geometry"))
      throw InputError("problem file: missing object geometry");
    const ObjectReader g(top.at("geometry"), "geometry", {"inner_radius", "outer_radius", "length"});
    p.geometry.inner_radius = g.number("inner_radius", "must be > 0 [m]", positive);
    p.geometry.outer_radius = g.number("outer_radius", "must be > 0 [m]", positive);
    p.geometry.length = g.number("length", "must be > 0 [m]", positive);
    if (!(p.geometry.outer_radius > p.geometry.inner_radius))
      fail("geometry.outer_radius", p.geometry.outer_radius,
           "must exceed geometry.inner_radius = " + show(p.geometry.inner_radius));

    if (!top.has("material"))
      throw InputError("problem file: missing object material");
    const ObjectReader m(top.at("material"), "material", {"youngs_modulus", "poisson_ratio"});
    p.material.youngs_modulus = m.number("youngs_modulus", "must be > 0 [Pa]", positive);
    p.material.poisson_ratio = m.number("poisson_ratio", "must be in (-1, 0.5)",
                                        [](double x) { return x > -1.0 && x < 0.5; });

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
      {
        const ObjectReader c(top.at("contact"), "contact", {"method", "half_width", "curve_points"});
        if (c.has("curve_points"))
          p.contact.curve_points = c.integer("curve_points", ranges::contact_curve_points);
        if (c.has("method"))
          p.contact.method =
            c.string("method", {"edge-intensity", "fixed", "iterate", "max-force"});
        if (c.has("half_width"))
          {
            const double a = p.geometry.half_length();
            p.contact.half_width = c.number(
              "half_width", "must be in (0, length/2 = " + show(a) + "] [m]",
              [&](double x) { return x > 0.0 && x <= a * (1 + 1e-12); });
          }
      }

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

    // 4. Discretization settings.
    if (top.has("rfm"))
      {
        const ObjectReader r(top.at("rfm"), "rfm",
                             {"degree", "extra_gauss_points", "n_cells_r", "n_cells_z",
                              "n_graded_layers", "grading_ratio", "edge_modes", "edge_cutoff",
                              "edge_extra_points"});
        if (r.has("degree"))
          p.rfm.degree = r.integer("degree", ranges::rfm_degree);
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
      }
    if (top.has("fem"))
      {
        const ObjectReader f(top.at("fem"), "fem", {"degree", "refinements"});
        if (f.has("degree"))
          p.fem.degree = f.integer("degree", ranges::fem_degree);
        if (f.has("refinements"))
          p.fem.refinements = f.integer("refinements", ranges::fem_refinements);
      }
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
