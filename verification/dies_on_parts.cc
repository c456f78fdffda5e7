// dies_on_parts: frictionless rigid dies on straight parts of an outline section (issue 23,
// DESIGN.md 7.1): the FEM reference against closed forms and against independent models, and
// the RFM where its outline contact reaches (an indentation, one free end or a flat punch).
//
//   1. Hertz: a rigid paraboloid (R = 0.1 m) pressed with 2 kN on the end face of a solid
//      steel cylinder (radius and height 23 times the contact radius) on a frictionless
//      support: the contact radius a = (3 P R / 4 E*)^(1/3) and the peak pressure
//      p0 = 3 P / (2 pi a^2) of the half-space (Johnson, Contact Mechanics, 4.22-4.23),
//      against the FEM level L.
//   2. A flat punch with rounded edges (b = 0.5 mm, rho = 50 mm) pressed 2 um into the same
//      cylinder: no closed form; c and P against L.
//   3. A flat punch with a sharp edge (b = 1 mm) pressed 1 um: P against Boussinesq's
//      half-space 2 E* b delta (the finite column is stiffer), and the pressure at the centre
//      against Sneddon's P / (2 pi b^2) with the FEM's own P.
//   4. A ring die (R = 0.05 m, 2 um) at the mid-length of a shaft, modelled whole (two free
//      edges) and as the mirrored half (one free edge): both ends of the zone against the
//      half's c, and c against plane-strain Hertz for the ring's line load. Full mode: the
//      RFM at the FEM's zone (P, K at both ends and the ends' offset K implies, p(s)).
//      The RFM (outline path, the punch's face as the zone) beside the FEM: P and K against p.
//   For Hertz and the rounded punch, the RFM at its defaults beside the FEM: in quick mode at
//   the FEM's zone (P or delta, and the consistent pressure against the FEM's p(s)), in full
//   mode its own zone search (c, P, delta, p(s)).
//   5. The paper's die written as an outline (the half section, not mirrored): the RFM's
//      zone search on the outline path, the rectangle model's search on the hollow-cylinder
//      form (its P halved), and the FEM on the outline file and on the hollow-cylinder form
//      (one geometry path: the same mesh, the same c, twice the force).
//   6. The tolerance gate (verification/tolerances.json, entry "dies_on_parts").
//   7. Two dies: a solid cylinder pressed by paraboloids at both end faces, modelled whole (no
//      symmetry plane): the RFM's search of both zones at once (full mode; quick mode: P at
//      the FEM's zones) against the FEM's, and each solver's two dies against each other
//      (mirror images).
//
// Sample run:
//   build/bin/dies_on_parts --mode quick --output-dir build/verification-output
#include "fem_reference/axisymmetric_fem.h"
#include "problem/problem.h"
#include "rfm/contact/contact.h"
#include "rfm/contact/outline_contact.h"
#include "verification/driver.h"
#include "verification/fem_samples.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

namespace
{
  constexpr double pi = 3.14159265358979323846;

  fem::FemResult solve_fem(const axisym::Problem &problem, const int level,
                           const std::string &what)
  {
    fem::FemOptions o = fem::options_from_problem(problem);
    o.refinements = level;
    o.progress = false;
    fem::FemResult r = fem::solve(problem, o);
    if (!r.success || !r.contact)
      throw verification::NumericalFailure(what + ", L = " + std::to_string(level) + ": " +
                                           r.message);
    return r;
  }

  double peak_pressure(const fem::ContactResult &c)
  {
    double p0 = 0;
    for (const fem::PressurePoint &p : c.pressure)
      p0 = std::max(p0, p.p);
    return p0;
  }

  /// The contact pressure at the point nearest the centre (s = 0, off the axis).
  double centre_pressure(const fem::ContactResult &c)
  {
    const auto it = std::min_element(c.pressure.begin(), c.pressure.end(),
                                     [](const auto &a, const auto &b) {
                                       return std::abs(a.s) < std::abs(b.s);
                                     });
    return it == c.pressure.end() ? 0.0 : it->p;
  }

  double e_star(const axisym::Problem &p)
  {
    const double nu = p.material.poisson_ratio;
    return p.material.youngs_modulus / (1 - nu * nu);
  }

  /// The pressure profile of the finest level (for the report's figure): s, p, p_trace.
  nlohmann::json profile(const fem::ContactResult &c)
  {
    nlohmann::json out = nlohmann::json::array();
    for (const fem::PressurePoint &p : c.pressure)
      out.push_back({{"s", p.s}, {"p", p.p}, {"p_trace", p.p_trace}});
    return out;
  }

  double seconds_since(const std::chrono::steady_clock::time_point t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  /// The RFM's pressure against the FEM's at the FEM's points of the part: the consistent
  /// reactions (rfm::consistent_die_pressure) and the trace, max |p - p_FEM| / max p_FEM.
  std::pair<double, double> pressure_errors(const rfm::OutlineModel &m, const axisym::Problem &problem,
                                            const rfm::DieZone &zone, const fem::ContactResult &fem)
  {
    const axisym::DieFrame f = axisym::die_frame(*problem.body, zone.part);
    std::vector<double> s;
    Eigen::VectorXd r(fem.pressure.size()), z(fem.pressure.size());
    for (const fem::PressurePoint &q : fem.pressure)
      {
        r[static_cast<Eigen::Index>(s.size())] = q.r, z[static_cast<Eigen::Index>(s.size())] = q.z;
        s.push_back(q.s);
      }
    const std::vector<double> p =
      rfm::consistent_die_pressure(m, problem, zone, s, rfm::default_pressure_moments);
    const rfm::FieldValues v = m.evaluate(r, z);
    double consistent = 0, trace = 0;
    for (std::size_t i = 0; i < s.size(); ++i)
      {
        const auto k = static_cast<Eigen::Index>(i);
        const double p_trace = -(v.sigma(k, rfm::rr) * f.normal.r * f.normal.r +
                                 2 * v.sigma(k, rfm::rz) * f.normal.r * f.normal.z +
                                 v.sigma(k, rfm::zz) * f.normal.z * f.normal.z);
        const bool in_zone = s[i] >= zone.s_lo && s[i] <= zone.s_hi;
        consistent = std::max(consistent, std::abs(p[i] - fem.pressure[i].p));
        trace = std::max(trace, std::abs((in_zone ? p_trace : 0.0) - fem.pressure[i].p));
      }
    return {consistent / peak_pressure(fem), trace / peak_pressure(fem)};
  }

  /// The RFM's pressure profile at 101 points of its zone (for the report's figure).
  nlohmann::json rfm_profile(const rfm::OutlineModel &m, const axisym::Problem &problem,
                             const rfm::DieZone &zone)
  {
    std::vector<double> s;
    for (int k = 0; k <= 100; ++k)
      s.push_back(zone.s_lo + (zone.s_hi - zone.s_lo) * k / 100.0);
    const std::vector<double> p =
      rfm::consistent_die_pressure(m, problem, zone, s, rfm::default_pressure_moments);
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < s.size(); ++i)
      out.push_back({{"s", s[i]}, {"p", std::isfinite(p[i]) ? nlohmann::json(p[i]) : nlohmann::json(nullptr)}});
    return out;
  }

  /// The largest p of a pressure profile (rfm_profile's; null at a sharp edge).
  double profile_peak(const nlohmann::json &profile)
  {
    double peak = 0;
    for (const nlohmann::json &q : profile)
      if (q["p"].is_number())
        peak = std::max(peak, q["p"].get<double>());
    return peak;
  }

  /// The RFM on a die of one free end at the defaults: in quick mode at the FEM's zone (c_fem,
  /// by the problem's indentation or force: P or delta against the FEM's, p(s) against the
  /// FEM's p; 3 s), in full mode its own zone search (c, P, delta against the FEM's; 16-20 s).
  nlohmann::json rfm_rows(const axisym::Problem &problem, const std::string &part,
                          const fem::ContactResult &fem, const bool search, const std::string &what)
  {
    const axisym::DieFrame f = axisym::die_frame(*problem.body, part);
    const bool up = f.s_max > 0;
    const double c_fem = fem.half_width;
    nlohmann::json out;
    fmt::print("RFM p = {}: {:>10} {:>13} {:>10} {:>12} {:>10} {:>9} {:>9} {:>9} {:>8}\n",
               problem.rfm.degree, "", "c [m]", "vs FEM", "P [N]", "vs FEM", "delta vs",
               "p(s) err", "trace", "time [s]");
    auto row = [&](const std::string &key, const rfm::OutlineContactResult &r, const double seconds) {
      if (!r.success || !r.model)
        throw verification::NumericalFailure(what + " RFM (" + key + "): " + r.message);
      const double c = up ? r.zone.s_hi : -r.zone.s_lo;
      const double force = r.model->die_force(part).domain;
      const auto [p_err, trace_err] = pressure_errors(*r.model, problem, r.zone, fem);
      const double indicator = r.model->functionals().indicator();
      out[key] = {{"half_width", c},
                  {"half_width_vs_fem", c / c_fem - 1},
                  {"force", force},
                  {"force_vs_fem", force / fem.force - 1},
                  {"indentation", r.zone.indentation},
                  {"indentation_vs_fem", r.zone.indentation / fem.indentation - 1},
                  {"edge_intensity", r.model->edge_intensity(0)},
                  {"pressure_error_relative", p_err},
                  {"pressure_trace_error_relative", trace_err},
                  {"indicator", indicator},
                  {"solves", r.history.size()},
                  {"seconds", seconds},
                  {"pressure", rfm_profile(*r.model, problem, r.zone)}};
      out[key]["peak_pressure"] = profile_peak(out[key]["pressure"]);
      fmt::print("           {:>10} {:>13.6e} {:>10.2e} {:>12.6e} {:>10.2e} {:>9.2e} {:>9.2e} {:>9.2e} {:>8.2f}\n",
                 key, c, c / c_fem - 1, force, force / fem.force - 1,
                 r.zone.indentation / fem.indentation - 1, p_err, trace_err, seconds);
    };
    // At the FEM's zone a die under force control is solved at the FEM's indentation (one
    // solve instead of two: the quick run stays under the tests' 30 s), so that its P, not
    // its delta, is what differs from the FEM's.
    std::optional<axisym::Problem> by_indentation;
    if (!search && problem.body->conditions.at(part).die.force)
      {
        nlohmann::json j = problem.source;
        j["boundary"][part]["die"].erase("force");
        j["boundary"][part]["die"]["indentation"] = fem.indentation;
        by_indentation = axisym::parse_problem(j);
      }
    const axisym::Problem &solved = by_indentation ? *by_indentation : problem;
    const auto t0 = std::chrono::steady_clock::now();
    const rfm::OutlineContactResult r =
      search ? rfm::solve_outline_contact(solved, solved.rfm)
             : rfm::solve_outline_zone(solved, solved.rfm, up ? 0.0 : -c_fem, up ? c_fem : 0.0);
    row(search ? "search" : "at_fem_zone", r, seconds_since(t0));
    return out;
  }
} // namespace

nlohmann::json run(const verification::DriverContext &context)
{
  const bool full = context.full();
  nlohmann::json results = {{"driver", "dies_on_parts"}, {"mode", context.mode}};
  const std::vector<int> levels = full ? std::vector<int>{2, 3, 4} : std::vector<int>{2, 3};

  // 1. Hertz.
  {
    const std::string file = "hertz_paraboloid_force.json";
    const axisym::Problem problem = axisym::read_problem_file(context.problem_path(file));
    const axisym::DieCondition &die = problem.body->conditions.at("top").die;
    const double force = *die.force, radius = die.profile.radius;
    const double a = std::cbrt(3 * force * radius / (4 * e_star(problem)));
    const double p0 = 3 * force / (2 * pi * a * a);
    nlohmann::json c = {{"problem_file", "verification/problems/" + file},
                        {"hertz", {{"contact_radius", a}, {"peak_pressure", p0},
                                   {"indentation_half_space", a * a / radius}}}};
    fmt::print("== Hertz: paraboloid R = {} m, P = {} N on a solid cylinder; a = {:.6e} m, "
               "p0 = {:.6e} Pa ==\n",
               radius, force, a, p0);
    fmt::print("FEM Q2: {:>2} {:>8} {:>13} {:>10} {:>13} {:>10} {:>12} {:>8}\n", "L", "dofs",
               "a [m]", "a err", "p0 [Pa]", "p0 err", "delta [m]", "time [s]");
    fem::FemResult last;
    for (const int level : levels)
      {
        last = solve_fem(problem, level, "Hertz");
        const fem::ContactResult &k = *last.contact;
        const double a_err = (k.half_width - a) / a, p_err = (peak_pressure(k) - p0) / p0;
        fmt::print("        {:>2} {:>8} {:>13.6e} {:>10.2e} {:>13.6e} {:>10.2e} {:>12.5e} {:>8.2f}\n",
                   level, last.n_dofs, k.half_width, a_err, peak_pressure(k), p_err,
                   k.indentation, last.total_seconds);
        c["fem"]["L" + std::to_string(level)] = {
          {"dofs", last.n_dofs},        {"contact_radius", k.half_width},
          {"peak_pressure", peak_pressure(k)}, {"indentation", k.indentation},
          {"force", k.force},           {"force_trace", k.force_trace},
          {"contact_radius_error_relative", std::abs(a_err)},
          {"peak_pressure_error_relative", std::abs(p_err)},
          {"seconds", last.total_seconds}};
      }
    c["fem"]["finest"] = c["fem"]["L" + std::to_string(levels.back())];
    c["fem"]["pressure"] = profile(*last.contact);
    c["rfm"] = rfm_rows(problem, "top", *last.contact, full, "Hertz");
    for (auto &[key, row] : c["rfm"].items())
      {
        row["contact_radius_vs_hertz"] = row["half_width"].get<double>() / a - 1;
        row["peak_pressure_vs_hertz"] = row["peak_pressure"].get<double>() / p0 - 1;
        fmt::print("RFM {}: a / a_Hertz - 1 = {:.2e}, p0 / p0_Hertz - 1 = {:.2e} (the consistent "
                   "pressure's peak)\n",
                   key, row["contact_radius_vs_hertz"].get<double>(),
                   row["peak_pressure_vs_hertz"].get<double>());
      }
    results["hertz"] = c;
  }

  // 2. Flat punch with rounded edges, and 3. with a sharp edge: c and P against L. `at_level`
  // sees each level's result (the sharp punch's edge intensity).
  auto punch = [&](const std::string &key, const axisym::Problem &problem, const std::string &file,
                   const std::string &title,
                   const std::function<void(int, const fem::FemResult &)> &at_level) {
    nlohmann::json c = {{"problem_file", "verification/problems/" + file}};
    fmt::print("\n== {} ==\n", title);
    fmt::print("FEM Q2: {:>2} {:>8} {:>13} {:>13} {:>13} {:>8}\n", "L", "dofs", "c [m]", "P [N]",
               "p(0) [Pa]", "time [s]");
    double c_prev = 0, p_prev = 0;
    fem::FemResult last;
    for (const int level : levels)
      {
        last = solve_fem(problem, level, key);
        const fem::ContactResult &k = *last.contact;
        fmt::print("        {:>2} {:>8} {:>13.6e} {:>13.6e} {:>13.6e} {:>8.2f}\n", level,
                   last.n_dofs, k.half_width, k.force, centre_pressure(k), last.total_seconds);
        nlohmann::json &l = c["fem"]["L" + std::to_string(level)];
        l = {{"dofs", last.n_dofs},         {"half_width", k.half_width},
             {"force", k.force},            {"force_trace", k.force_trace},
             {"centre_pressure", centre_pressure(k)}, {"seconds", last.total_seconds}};
        if (level != levels.front())
          {
            c["fem"]["half_width_change_last_relative"] = std::abs(k.half_width - c_prev) / k.half_width;
            c["fem"]["force_change_last_relative"] = std::abs(k.force - p_prev) / k.force;
          }
        c_prev = k.half_width, p_prev = k.force;
        if (at_level)
          at_level(level, last);
      }
    c["fem"]["finest"] = c["fem"]["L" + std::to_string(levels.back())];
    c["fem"]["pressure"] = profile(*last.contact);
    return std::pair{c, last};
  };
  {
    const std::string file = "flat_rounded_punch_indentation.json";
    const axisym::Problem problem = axisym::read_problem_file(context.problem_path(file));
    auto [c, last] = punch("flat_rounded", problem, file,
                           "Flat punch with rounded edges (b = 0.5 mm, rho = 50 mm), 2 um", {});
    c["rfm"] = rfm_rows(problem, "top", *last.contact, full, "rounded flat punch");
    results["flat_rounded"] = c;
  }
  {
    // The edge intensity by the interaction integral (rfm/contact/contact.h) on the FEM's field, in
    // the frame of the punch's edge (b, h): t = -e_r (into the zone), n = -e_z (into the
    // body); the flat face prescribes u.n = -delta everywhere. Against Sneddon's half-space
    // pressure near the edge, P / (2 pi b sqrt(2 b x)): K = -sqrt(2 pi) P / (2 pi b sqrt(2 b)).
    // The FEM is solved with the integral's points as its samples.
    const std::string file = "flat_punch_indentation.json";
    axisym::Problem problem = axisym::read_problem_file(context.problem_path(file));
    const axisym::DieCondition &die = problem.body->conditions.at("top").die;
    const double b = die.profile.radius, delta = *die.indentation;
    const rfm::EdgeFrame frame{b, die.center.z, {{-1.0, 0.0}}, {{0.0, -1.0}}};
    const double rho_1 = 0.9 * b;
    verification::add_interaction_samples(problem.samples, rfm::interaction_quadrature(frame, rho_1),
                                          frame.r, frame.z);
    nlohmann::json k_levels;
    double k_fem = 0, k_prev = 0;
    auto [c, last] = punch(
      "flat", problem, file, "Flat punch with a sharp edge (b = 1 mm), 1 um",
      [&](int level, const fem::FemResult &fr) {
        k_prev = k_fem;
        k_fem = rfm::edge_intensity_interaction(verification::sampled_interaction_field(fr), frame,
                                                problem.material, rho_1,
                                                [&](double) { return -delta; });
        const double k_sneddon =
          -std::sqrt(2 * pi) * fr.contact->force / (2 * pi * b * std::sqrt(2 * b));
        k_levels["L" + std::to_string(level)] = {{"edge_intensity", k_fem},
                                                 {"sneddon_edge_intensity", k_sneddon},
                                                 {"over_sneddon", k_fem / k_sneddon}};
        fmt::print("        edge intensity K = {:.6e} Pa m^1/2; Sneddon with this P {:.6e} "
                   "(ratio {:.4f})\n",
                   k_fem, k_sneddon, k_fem / k_sneddon);
      });
    const double boussinesq = 2 * e_star(problem) * b * delta;
    const double force = last.contact->force;
    const double sneddon_centre = force / (2 * pi * b * b);
    c["boussinesq_force"] = boussinesq;
    c["force_over_boussinesq"] = force / boussinesq;
    c["centre_pressure_over_sneddon"] = centre_pressure(*last.contact) / sneddon_centre;
    fmt::print("P / (2 E* b delta) = {:.4f} (the half-space's; the finite column is stiffer); "
               "p(0) / (P / 2 pi b^2) = {:.4f}\n",
               force / boussinesq, centre_pressure(*last.contact) / sneddon_centre);
    c["fem"]["edge_intensity"] = k_levels;
    c["fem"]["edge_intensity_finest"] = k_levels["L" + std::to_string(levels.back())];
    c["fem"]["edge_intensity_change_last_relative"] = std::abs(k_fem - k_prev) / std::abs(k_fem);
    // The RFM: the punch's face as the zone, K at its edge (rfm/contact/outline_contact.h).
    fmt::print("RFM: {:>3} {:>13} {:>10} {:>15} {:>10} {:>10} {:>8}\n", "p", "P [N]", "vs FEM",
               "K [Pa m^1/2]", "vs FEM", "indicator", "time [s]");
    // The RFM in full mode only (3 s of the quick run's 28 s; its K is gated in full mode).
    for (const int p : full ? std::vector<int>{8, 12} : std::vector<int>{})
      {
        rfm::DiscretizationOptions o = problem.rfm;
        o.degree = p;
        const auto t0 = std::chrono::steady_clock::now();
        const rfm::OutlineContactResult r = rfm::solve_outline_contact(problem, o);
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!r.success)
          throw verification::NumericalFailure("flat punch RFM, p = " + std::to_string(p) + ": " +
                                               r.message);
        const double rfm_force = r.model->die_force("top").domain;
        const double rfm_k = r.model->edge_intensity(0);
        const double indicator = r.model->functionals().indicator();
        fmt::print("     {:>3} {:>13.6e} {:>10.2e} {:>15.6e} {:>10.2e} {:>10.2e} {:>8.2f}\n", p,
                   rfm_force, rfm_force / force - 1, rfm_k, rfm_k / k_fem - 1, indicator, seconds);
        c["rfm"]["p" + std::to_string(p)] = {{"force", rfm_force},
                                             {"force_vs_fem", rfm_force / force - 1},
                                             {"edge_intensity", rfm_k},
                                             {"edge_intensity_vs_fem", rfm_k / k_fem - 1},
                                             {"indicator", indicator},
                                             {"seconds", seconds}};
      }
    results["flat"] = c;
  }

  // 4. Ring die on a shaft: whole (two free edges) against the mirrored half.
  {
    const std::string file = "ring_die_shaft.json";
    const axisym::Problem whole = axisym::read_problem_file(context.problem_path(file));
    // The mirrored half: z in [0, h] with the centre on the symmetry plane z = 0.
    nlohmann::json half_json = whole.source;
    half_json["geometry"]["outline"][0]["start"][1] = 0.0;
    half_json["geometry"]["outline"][1]["line_to"][1] = 0.0;
    half_json["geometry"]["outline"][4]["line_to"][1] = 0.0;
    half_json["boundary"]["side"]["die"].erase("center");
    const axisym::Problem half = axisym::parse_problem(half_json);
    const int level = levels.back();
    const fem::FemResult fw = solve_fem(whole, level, "ring die (whole)");
    const fem::FemResult fh = solve_fem(half, level, "ring die (half)");
    const auto [lo, hi] = fw.contact->zone.value_or(std::array<double, 2>{0.0, 0.0});
    const double c_half = fh.contact->half_width;
    const double r = whole.body->conditions.at("side").die.center.r;
    const double p_line = fw.contact->force / (2 * pi * r);
    const double b_line = std::sqrt(4 * p_line * whole.body->conditions.at("side").die.profile.radius /
                                    (pi * e_star(whole)));
    nlohmann::json c = {{"problem_file", "verification/problems/" + file},
                        {"level", level},
                        {"whole", {{"zone", {lo, hi}}, {"force", fw.contact->force},
                                   {"dofs", fw.n_dofs}, {"seconds", fw.total_seconds}}},
                        {"half", {{"half_width", c_half}, {"force", fh.contact->force},
                                  {"dofs", fh.n_dofs}, {"seconds", fh.total_seconds}}},
                        {"start_vs_half_relative", std::abs(-lo - c_half) / c_half},
                        {"end_vs_half_relative", std::abs(hi - c_half) / c_half},
                        {"force_vs_half_relative",
                         std::abs(fw.contact->force - 2 * fh.contact->force) / fw.contact->force},
                        {"plane_strain_hertz_half_width", b_line}};
    fmt::print("\n== Ring die (R = 0.05 m, 2 um) at the mid-length of a shaft, FEM L = {} ==\n",
               level);
    fmt::print("whole: zone [{:.6e}, {:.6e}] m, P = {:.6g} N; mirrored half: c = {:.6e} m, "
               "2 P = {:.6g} N; plane-strain Hertz b = {:.6e} m\n",
               lo, hi, fw.contact->force, c_half, 2 * fh.contact->force, b_line);
    // Full mode: the RFM at its defaults on the FEM's zone (one solve, about 60 s on one
    // thread; its own search of both ends takes eight, beyond the report's time). K at each
    // end says how far the RFM's end lies from the FEM's: to first order, an end moved by
    // dc adds -A dc sqrt(pi / 2) to K where the pressure falls like A sqrt(c - s), and
    // A = p_max sqrt(2 / h) for an elliptic pressure of half-width h (plane-strain Hertz,
    // the ring's line contact): dc = -K / (A sqrt(pi / 2)) (K < 0: the zone too short).
    if (full)
      {
        const auto t0 = std::chrono::steady_clock::now();
        const rfm::OutlineContactResult r = rfm::solve_outline_zone(whole, whole.rfm, lo, hi);
        const double seconds = seconds_since(t0);
        if (!r.success || !r.model)
          throw verification::NumericalFailure("ring die RFM at the FEM's zone: " + r.message);
        const double force = r.model->die_force("side").domain;
        const auto [p_err, trace_err] = pressure_errors(*r.model, whole, r.zone, *fw.contact);
        const nlohmann::json pressure = rfm_profile(*r.model, whole, r.zone);
        const double p_max = profile_peak(pressure);
        const double h = 0.5 * (hi - lo), slope = p_max * std::sqrt(2 / h) * std::sqrt(pi / 2);
        const double k_lo = r.model->edge_intensity(0), k_hi = r.model->edge_intensity(1);
        c["rfm"] = {{"degree", whole.rfm.degree},
                    {"force", force},
                    {"force_vs_fem", force / fw.contact->force - 1},
                    {"edge_intensity", {k_lo, k_hi}},
                    {"end_offset_estimate_relative", {-k_lo / slope / h, -k_hi / slope / h}},
                    {"pressure_error_relative", p_err},
                    {"pressure_trace_error_relative", trace_err},
                    {"indicator", r.model->functionals().indicator()},
                    {"peak_pressure", p_max},
                    {"seconds", seconds},
                    {"pressure", pressure}};
        c["fem_pressure"] = profile(*fw.contact);
        fmt::print("RFM p = {} at the FEM's zone: P = {:.6g} N ({:+.2e} from the FEM's), K = {:.4g}, "
                   "{:.4g} Pa m^1/2 (the ends {:+.2e}, {:+.2e} of h from the FEM's, first order), "
                   "p(s) {:.2e} of p_max, {:.1f} s\n",
                   whole.rfm.degree, force, force / fw.contact->force - 1, k_lo, k_hi,
                   -k_lo / slope / h, -k_hi / slope / h, p_err, seconds);
      }
    results["ring"] = c;
  }

  // 5. The paper's die as an outline: both RFM paths; the FEM on both file forms.
  {
    const std::string file = "die_paper_outline.json";
    const axisym::Problem outline = axisym::read_problem_file(context.problem_path(file));
    nlohmann::json legacy_json = {{"geometry", {{"inner_radius", 0.1}, {"outer_radius", 0.2},
                                                {"length", 0.4}}},
                                  {"material", outline.source["material"]},
                                  {"die", {{"indentation", 1.0e-6}}}};
    const axisym::Problem legacy = axisym::parse_problem(legacy_json);
    nlohmann::json c = {{"problem_file", "verification/problems/" + file}};
    fmt::print("\n== The paper's die written as an outline (half section; forces of the half) ==\n");
    fmt::print("RFM: {:>3} {:>13} {:>13} {:>13} {:>13} {:>8} {:>8}\n", "p", "c outline", "P outline",
               "c rectangle", "P rect. / 2", "t out.", "t rect.");
    for (const int p : std::vector<int>{8, 12})
      {
        rfm::DiscretizationOptions o = outline.rfm;
        o.degree = p;
        auto t0 = std::chrono::steady_clock::now();
        const rfm::OutlineContactResult r = rfm::solve_outline_contact(outline, o);
        const double t_outline =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        t0 = std::chrono::steady_clock::now();
        const rfm::ContactResult l = rfm::solve_contact(legacy, o, rfm::ContactOptions{});
        const double t_rect =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!r.success || !l.success)
          throw verification::NumericalFailure("paper's die as an outline, p = " + std::to_string(p) +
                                               ": " + (r.success ? l.message : r.message));
        const double p_outline = r.model->die_force("outer").domain;
        fmt::print("     {:>3} {:>13.7e} {:>13.7e} {:>13.7e} {:>13.7e} {:>8.2f} {:>8.2f}\n", p,
                   r.zone.s_hi, p_outline, l.final.half_width, 0.5 * l.final.force, t_outline,
                   t_rect);
        c["rfm"]["p" + std::to_string(p)] = {{"outline_half_width", r.zone.s_hi},
                                             {"outline_force", p_outline},
                                             {"outline_edge_intensity", r.model->edge_intensity(0)},
                                             {"outline_solves", r.history.size()},
                                             {"outline_seconds", t_outline},
                                             {"rectangle_half_width", l.final.half_width},
                                             {"rectangle_force_half", 0.5 * l.final.force},
                                             {"rectangle_solves", l.history.size()},
                                             {"rectangle_seconds", t_rect}};
        c["rfm"]["last"] = c["rfm"]["p" + std::to_string(p)];
      }
    const int level = levels.back();
    const fem::FemResult fo = solve_fem(outline, level, "paper's die as an outline (FEM)");
    // The hollow-cylinder form is the same half section mirrored (one geometry path): at the
    // same level, the same mesh, c and twice the force.
    const fem::FemResult fl = solve_fem(legacy, level, "paper's die (FEM, hollow-cylinder form)");
    c["fem"] = {{"level_outline", level},
                {"outline_half_width", fo.contact->half_width},
                {"outline_force", fo.contact->force},
                {"level_rectangle", level},
                {"rectangle_half_width", fl.contact->half_width},
                {"rectangle_force_half", 0.5 * fl.contact->force}};
    fmt::print("FEM: outline file L = {}: c = {:.7e} m, P = {:.7e} N; hollow-cylinder form L = {}: "
               "c = {:.7e} m, P / 2 = {:.7e} N\n",
               level, fo.contact->half_width, fo.contact->force, level, fl.contact->half_width,
               0.5 * fl.contact->force);
    const nlohmann::json &last = c["rfm"]["last"];
    c["outline_rfm_vs_fem_half_width"] =
      std::abs(last["outline_half_width"].get<double>() - fo.contact->half_width) / fo.contact->half_width;
    c["outline_rfm_vs_fem_force"] =
      std::abs(last["outline_force"].get<double>() - fo.contact->force) / fo.contact->force;
    c["outline_vs_rectangle_rfm_force"] =
      std::abs(last["outline_force"].get<double>() - last["rectangle_force_half"].get<double>()) /
      last["rectangle_force_half"].get<double>();
    c["fem_outline_vs_rectangle_half_width"] =
      std::abs(fo.contact->half_width - fl.contact->half_width) / fl.contact->half_width;
    c["fem_outline_vs_rectangle_force"] =
      std::abs(fo.contact->force - 0.5 * fl.contact->force) / (0.5 * fl.contact->force);
    results["paper_die_outline"] = c;
  }

  // 7. Two dies: a cylinder pressed at both end faces, modelled whole (no symmetry plane).
  {
    const std::string file = "cylinder_between_two_dies.json";
    const axisym::Problem problem = axisym::read_problem_file(context.problem_path(file));
    nlohmann::json c = {{"problem_file", "verification/problems/" + file}};
    // The FEM at L = 2, 3 (L = 4 moves c by 1.5e-5 and P by 2e-7 from L = 3: measured).
    double c_fem = 0.0, p_fem = 0.0;
    for (const int level : {2, 3})
      {
        const fem::FemResult f = solve_fem(problem, level, "two dies (FEM)");
        if (f.other_dies.size() != 1)
          throw verification::NumericalFailure("two dies (FEM): " + std::to_string(1 + f.other_dies.size()) +
                                               " dies in the result");
        const fem::ContactResult &bottom = *f.contact, &top = f.other_dies[0];
        c["fem"]["L" + std::to_string(level)] = {
          {"half_width_bottom", bottom.half_width}, {"half_width_top", top.half_width},
          {"force_bottom", bottom.force}, {"force_top", top.force},
          {"dofs", f.n_dofs}, {"seconds", f.total_seconds}};
        c["fem"]["top_vs_bottom_half_width"] = std::abs(top.half_width - bottom.half_width) / bottom.half_width;
        c_fem = 0.5 * (bottom.half_width + top.half_width), p_fem = 0.5 * (bottom.force + top.force);
      }
    // Quick mode: the RFM on the FEM's zones (one solve); full mode: its own search of both.
    const auto t0 = std::chrono::steady_clock::now();
    const rfm::OutlineDiesResult r =
      full ? rfm::solve_outline_dies(problem, problem.rfm)
           : rfm::solve_outline_dies_on_zones(problem, problem.rfm,
                                              {{"bottom", 0.0, c_fem, 0.0}, {"top", -c_fem, 0.0, 0.0}});
    const double seconds = seconds_since(t0);
    if (!r.success || !r.model)
      throw verification::NumericalFailure("two dies (RFM): " + r.message);
    const double c_bottom = r.zones.at(0).s_hi, c_top = -r.zones.at(1).s_lo;
    const double p_bottom = r.model->die_force("bottom").domain, p_top = r.model->die_force("top").domain;
    const std::string key = full ? "search" : "at_fem_zone";
    c["rfm"][key] = {{"degree", problem.rfm.degree}, {"half_width_bottom", c_bottom},
                     {"half_width_top", c_top}, {"force_bottom", p_bottom}, {"force_top", p_top},
                     {"solves", r.history.size()}, {"seconds", seconds},
                     {"top_vs_bottom_half_width", std::abs(c_top - c_bottom) / c_bottom},
                     {"top_vs_bottom_force", std::abs(p_top - p_bottom) / p_bottom},
                     {"half_width_vs_fem", (c_bottom - c_fem) / c_fem},
                     {"force_vs_fem", (p_bottom - p_fem) / p_fem}};
    fmt::print("\n== Two dies: a cylinder pressed 0.25 mm at both end faces (R = 0.1 m), whole ==\n");
    fmt::print("FEM L = 3: c = {:.7e} m, P = {:.7e} N; RFM p = {} ({}): c = {:.7e} / {:.7e} m (bottom "
               "/ top), P = {:.7e} N, {} solves, {:.1f} s: c {:+.2e}, P {:+.2e} from the FEM\n",
               c_fem, p_fem, problem.rfm.degree, full ? "its search" : "at the FEM's zones", c_bottom,
               c_top, p_bottom, r.history.size(), seconds, (c_bottom - c_fem) / c_fem,
               (p_bottom - p_fem) / p_fem);
    results["two_dies"] = c;
  }
  return results;
}

int main(int argc, char **argv)
{
  return verification::run_driver(argc, argv, "dies_on_parts",
                                  "Dies on parts of outline sections: the FEM against closed "
                                  "forms and independent models",
                                  run);
}
