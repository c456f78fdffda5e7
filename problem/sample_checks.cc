#include "problem/sample_checks.h"

#include "problem/wedge_modes.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace axisym
{
  std::vector<SampleAtVertex> samples_at_vertices(const Problem &problem)
  {
    std::vector<SampleAtVertex> out;
    if (problem.samples.empty())
      return out;
    const Body &body = *problem.body;
    const std::vector<SingularVertex> singular = singular_vertices(body, problem.material.poisson_ratio);
    const std::vector<Point> jumps = traction_jump_vertices(body);
    const double tol = 1e-9 * body.outline.size();
    for (std::size_t i = 0; i < problem.samples.size(); ++i)
      {
        const std::array<double, 2> &s = problem.samples[i];
        // A mirrored body's section is its half z >= 0: a sample below is the image's.
        const double z = body.mirrored ? std::abs(s[1]) : s[1];
        auto at = [&](const Point &v) { return std::hypot(s[0] - v.r, z - v.z) <= tol; };
        for (const SingularVertex &v : singular)
          if (at(v.at))
            {
              double lowest = std::numeric_limits<double>::infinity();
              for (const WedgeMode &m : v.modes)
                lowest = std::min(lowest, m.lambda.real());
              out.push_back({i, {s[0], s[1]}, SampleAtVertex::Kind::singular, lowest});
            }
        for (const Point &j : jumps)
          if (at(j))
            out.push_back({i, {s[0], s[1]}, SampleAtVertex::Kind::traction_jump, 0.0});
      }
    return out;
  }

  std::vector<bool> samples_with_a_value(const Problem &problem)
  {
    std::vector<bool> out(problem.samples.size(), true);
    for (const SampleAtVertex &v : samples_at_vertices(problem))
      out[v.sample] = false;
    return out;
  }

  nlohmann::json to_json(const std::vector<SampleAtVertex> &at)
  {
    nlohmann::json list = nlohmann::json::array();
    for (const SampleAtVertex &s : at)
      if (s.kind == SampleAtVertex::Kind::singular)
        list.push_back({{"r", s.at.r}, {"z", s.at.z}, {"kind", "singular"}, {"exponent", s.exponent}});
      else
        list.push_back({{"r", s.at.r}, {"z", s.at.z}, {"kind", "traction_jump"}});
    return list;
  }

  std::string samples_at_vertices_warning(const std::vector<SampleAtVertex> &at)
  {
    if (at.empty())
      return {};
    std::vector<std::string> said;
    for (const SampleAtVertex &s : at)
      said.push_back(s.kind == SampleAtVertex::Kind::singular
                       ? fmt::format("({:.6g}, {:.6g}) m is a singular vertex (the stress grows like "
                                     "rho^{:.4g} toward it)",
                                     s.at.r, s.at.z, s.exponent - 1.0)
                       : fmt::format("({:.6g}, {:.6g}) m is a vertex where the traction jumps (the "
                                     "stress there depends on the direction of approach)",
                                     s.at.r, s.at.z));
    return fmt::format("the sample {}: the stress has no value there, and the one given is not a "
                       "limit of the method; sample at a distance from the vertex",
                       fmt::join(said, "; the sample "));
  }
} // namespace axisym
