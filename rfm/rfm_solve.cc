// rfm_solve: the R-function method with Reissner's mixed principle on one problem file.
//
// Solves the axisymmetric elastic problem of PROBLEM.json (DESIGN.md section 7) with
// N = (p + 1)^2 coordinate functions per unknown component and writes the result JSON:
// discretization, the Lagrange/Castigliano/Reissner functionals (J per radian), the
// contact half-width and force when the problem has a die, fields at the sample points,
// solver diagnostics and timings.
//
// Sample run:
//   build/bin/rfm_solve verification/problems/lame_paper.json --degree 7 --output lame.json
//   build/bin/rfm_solve verification/problems/die_paper.json --vtu out/   # out/rfm_solution.vtu
//
// Exit status: 0 success, 2 bad input (nothing written), 3 numerical failure.
#include "problem/json_io.h"
#include "problem/problem.h"
#include "problem/sample_checks.h"
#include "problem/wedge_modes.h"
#include "rfm/allocator.h"
#include "rfm/contact/contact.h"
#include "rfm/contact/outline_contact.h"
#include "rfm/fields/vertex_intensity.h"
#include "rfm/fields/vtu_output.h"
#include "rfm/outline_model.h"
#include "rfm/spaces/traction_jump.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <unistd.h>

namespace
{
  /// A vertex's entry in diagnostics.singular_vertices and .rough_vertices: its point, interior
  /// angle, parts and exponents (real, imaginary), and enrichment (null here).
  nlohmann::json vertex_entry(const rfm::SingularVertex &v)
  {
    nlohmann::json exponents = nlohmann::json::array();
    for (const rfm::WedgeMode &m : v.modes)
      exponents.push_back({m.lambda.real(), m.lambda.imag()});
    return {{"r", v.at.r},
            {"z", v.at.z},
            {"angle_degrees", v.angle * 180.0 / 3.14159265358979323846},
            {"parts", {v.part_before, v.part_after}},
            {"exponents", exponents},
            {"enrichment", nullptr}};
  }
  /// Above this indicator a solve at a fixed degree warns (status "warning", exit 0).
  constexpr double fixed_degree_indicator_limit = 1e-5;
  /// Phi_C above Phi_L by more than this (relative to |Phi_R|) is not rounding.
  constexpr double indicator_rounding = 1e-12;

  /// Marks the result as in doubt with `why` (after any warning already there) and says so;
  /// diagnostics.warnings lists each with the `check` that raised it (a short key, for
  /// drivers and reports; README, 'Running one solver on one problem file', lists them).
  void add_warning(nlohmann::json &result, const std::string &check, const std::string &why)
  {
    nlohmann::json &d = result["diagnostics"];
    if (d.value("status", "") == "warning")
      d["message"] = d["message"].get<std::string>() + "; " + why;
    else
      d["status"] = "warning", d["message"] = why;
    d["warnings"].push_back({{"check", check}, {"message", why}});
    fmt::print(stderr, "rfm_solve: warning: {}\n", why);
  }

  /// The limit of every sample check, over the sample's scale: 2 sqrt(t), t the tolerance
  /// (which promises about sqrt(t) in stress) or fixed_degree_indicator_limit at a fixed degree.
  double sample_limit(const std::optional<double> tolerance)
  {
    return 2.0 * std::sqrt(tolerance.value_or(fixed_degree_indicator_limit));
  }

  /// `die`: a die problem, which takes no tolerance. `measure`: the indicator, or E / |Phi_R|
  /// where that is larger (Functionals::error_measure), as `name` says.
  std::string fixed_degree_warning(const double measure, const int p, const bool die = false,
                                   const std::string &name = "the indicator |Phi_L - Phi_C| / |Phi_R|")
  {
    return fmt::format("{} is {:.3g} at the fixed degree p = {}, "
                       "above {:g} (about 0.3 % in stress): the answer is in doubt; raise "
                       "rfm.degree{}",
                       name, measure, p, fixed_degree_indicator_limit, die ? "" : ", or give rfm.tolerance");
  }

  /// The stress that stores |Phi_R| uniaxially over the section, sqrt(2 E |Phi_R| /
  /// int r dr dz) (a mirrored body's functionals and section are twice its half's), and a
  /// sample's scale: its largest stress component, but at least that (a sample where every
  /// stress is small is not judged against itself).
  double energy_stress(const axisym::Problem &problem, const rfm::Functionals &phi)
  {
    const axisym::Body &body = *problem.body;
    return std::sqrt(2.0 * problem.material.youngs_modulus * std::abs(phi.reissner) /
                     ((body.mirrored ? 2.0 : 1.0) * body.outline.moment(1, 0)));
  }
  double sample_scale(const nlohmann::json &sample, const double floor)
  {
    double scale = floor;
    for (const char *c : {"sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz"})
      scale = std::max(scale, std::abs(sample.at(c).get<double>()));
    return scale;
  }

  template <typename Model>
  nlohmann::json fields_to_json(const axisym::Problem &problem, const Model &model);

  /// Where a sample lies on a die's zone: the zone, its part's frame, the distance s along the
  /// part, and whether it is at one of the zone's ends (within 1e-3 of the zone's length; not
  /// the die's centre on the axis or a symmetry edge). A mirrored body's samples below z = 0
  /// are taken at their image.
  struct OnZone
  {
    const rfm::DieZone *zone;
    axisym::DieFrame frame;
    double s;
    bool at_end;
  };
  std::optional<OnZone> on_zone(const axisym::Problem &problem, const std::vector<rfm::DieZone> &zones,
                                const double r, const double z)
  {
    const axisym::Body &body = *problem.body;
    const double tol = 1e-9 * body.outline.size();
    const axisym::Point x{r, body.mirrored ? std::abs(z) : z};
    for (const rfm::DieZone &zone : zones)
      {
        const axisym::DieFrame f = axisym::die_frame(body, zone.part);
        const double s = f.coordinate(x);
        const double off = (x.r - f.center.r) * f.normal.r + (x.z - f.center.z) * f.normal.z;
        const double band = 1e-3 * (zone.s_hi - zone.s_lo);
        if (std::abs(off) > tol || s < zone.s_lo - band || s > zone.s_hi + band)
          continue;
        const bool at_end = (f.runs_down() && std::abs(s - zone.s_lo) <= band) ||
                            (f.runs_up() && std::abs(s - zone.s_hi) <= band);
        return OnZone{&zone, f, s, at_end};
      }
    return std::nullopt;
  }

  /// One sample's change since p - 2: its largest stress component's, over its scale.
  struct SampleChange
  {
    std::size_t index; ///< in result["samples"]
    double change, scale, relative;
  };
  /// The changes of the samples with a value (samples at vertices and at a die zone's ends left
  /// out) from the model
  /// `lower` to the samples in `result`.
  std::vector<SampleChange> sample_changes(const axisym::Problem &problem, const rfm::OutlineModel &lower,
                                           const rfm::Functionals &phi, const nlohmann::json &result)
  {
    const nlohmann::json &samples = result.at("samples");
    const nlohmann::json before = fields_to_json(problem, lower);
    const std::vector<bool> with_a_value = axisym::samples_with_a_value(problem);
    const double floor = energy_stress(problem, phi);
    std::vector<SampleChange> out;
    for (std::size_t k = 0; k < samples.size(); ++k)
      {
        const nlohmann::json &now = samples[k], &then = before[k];
        if (!with_a_value[k])
          continue;
        if (const auto on = on_zone(problem, lower.zones(), now.at("r").get<double>(), now.at("z").get<double>());
            on && on->at_end)
          continue;
        double change = 0.0;
        for (const char *c : {"sigma_rr", "sigma_zz", "sigma_tt", "sigma_rz"})
          change = std::max(change, std::abs(now.at(c).get<double>() - then.at(c).get<double>()));
        const double scale = sample_scale(now, floor);
        out.push_back({k, change, scale, change / scale});
      }
    return out;
  }

  /// The samples' change from p - 2 at a fixed degree (issue 24 item 6). The indicator weighs
  /// the whole section, and a single point can move while it falls: the filleted groove's
  /// sigma_zz(0, 0) was 13.4 % and 1.6 % off the FEM's at p = 14 and 22 with indicators of
  /// 1.1e-6 and 4.2e-8, and sigma_rr = sigma_tt held there to 0.22 % and 0.20 % of the
  /// net-section stress (the axis check was quiet), but the sample had moved by 17.9 % and
  /// 3.1 % of its scale since p - 2. For a
  /// converging sequence that change is about p - 2's error, which is at least p's: a sample
  /// that moved by more than 2 sqrt(t) of its scale (sample_scale), with t =
  /// fixed_degree_indicator_limit as for the axis check, is not settled within the sqrt(t) a
  /// fixed degree promises, and warns. Samples at a vertex (sample_checks.h) are left out:
  /// they have no value to settle. Recorded in diagnostics.check_at_lower_degree.samples.
  void check_sample_changes(const axisym::Problem &problem, const rfm::OutlineModel &lower,
                            const rfm::Functionals &phi, const int p, nlohmann::json &result)
  {
    const nlohmann::json &samples = result["samples"];
    if (samples.empty())
      return;
    const double limit = sample_limit(std::nullopt);
    nlohmann::json list = nlohmann::json::array();
    std::vector<std::string> doubtful;
    for (const SampleChange &c : sample_changes(problem, lower, phi, result))
      {
        const nlohmann::json &now = samples[c.index];
        list.push_back({{"r", now.at("r")}, {"z", now.at("z")}, {"change", c.change}, {"scale", c.scale},
                        {"relative", c.relative}, {"limit", limit}});
        if (c.relative > limit)
          doubtful.push_back(fmt::format("({:.6g}, {:.6g}) m by {:.2g} %", now.at("r").get<double>(),
                                         now.at("z").get<double>(), 100.0 * c.relative));
      }
    result["diagnostics"]["check_at_lower_degree"]["samples"] = list;
    if (!doubtful.empty())
      add_warning(result, "sample_moved",
                  fmt::format("from p = {} to the fixed degree p = {} the sample{} moved by more "
                              "than {:.2g} % of {} stress: {}; the indicator weighs the whole "
                              "section and does not see one point's value, and {} not settled "
                              "within the {:.2g} % a fixed degree is allowed: raise rfm.degree, "
                              "or compare with fem_solve",
                              p - 2, p, doubtful.size() > 1 ? "s" : "", 100.0 * limit,
                              doubtful.size() > 1 ? "their" : "its", fmt::join(doubtful, ", "),
                              doubtful.size() > 1 ? "they are" : "it is", 50.0 * limit));
  }

  /// The samples where the tolerance path stops (issue 24 item 6). The tolerance t is met by
  /// the indicator, which weighs the whole section; t promises about sqrt(t) in stress (the
  /// Lame calibration), but a single point can be further off. Measured at the defaults (t =
  /// 1e-8) against the FEM's L = 4 (graded), in units of the sample's scale (sample_scale):
  /// the stepped ring stops at p = 18 with (0.2, 0.1) 1.9e-4 off (the FEM's L = 3 is 2.1e-5
  /// off its L = 4 there), the heated ring with an axial gradient at p = 22 with (0.8, 0),
  /// where its bore meets the symmetry plane, 7.5e-4 off (L = 3: 1.4e-4; the RFM 6.3e-4 and
  /// 5.2e-4 at p = 24 and 26). If a sample's error falls by rho per step of two degrees, its
  /// change since p - 2 is e_p (1 / rho - 1), so e_p ~ change rho / (1 - rho), with rho taken
  /// from the indicator, which is quadratic in the stress error: rho = sqrt(I_p / I_(p-2)),
  /// below 1 here (p - 2 was above the tolerance). A sample warns where that estimate passes
  /// 2 sqrt(t), the axis check's limit: the two cases above estimate 7.7e-4 and 3.7e-4 and
  /// warn; the thick sphere (p = 12, 3.9e-5; Lame: at most 6.1e-5 off), the clamped cylinder
  /// (p = 12, 2.4e-5), the heated plane-strain cylinder (p = 6, 7.8e-5) and the spinning solid
  /// cylinder (p = 8, 5.8e-5) stay quiet. The change alone, without the rate, would have
  /// flagged the sphere (2.6e-4). Samples at a vertex are left out (no value to settle).
  /// Recorded in diagnostics.check_at_lower_degree, as at a fixed degree, with the rate and
  /// each sample's estimate.
  void check_tolerance_samples(const axisym::Problem &problem, const rfm::OutlineModel &lower,
                               const rfm::Functionals &phi, const int p, const double tolerance,
                               nlohmann::json &result)
  {
    const nlohmann::json &samples = result["samples"];
    const double before = lower.functionals().indicator();
    const auto d_lower = lower.n_dropped_directions();
    const double rate = before > 0.0 ? std::sqrt(phi.indicator() / before) : 1.0;
    const double factor = rate < 1.0 ? rate / (1.0 - rate) : 1.0;
    const double limit = sample_limit(tolerance);
    nlohmann::json &check = result["diagnostics"]["check_at_lower_degree"];
    check = {{"degree", p - 2},
             {"indicator", before},
             {"dropped_directions", {d_lower[0], d_lower[1]}},
             {"rate", rate}};
    if (samples.empty())
      return;
    nlohmann::json list = nlohmann::json::array();
    std::vector<std::string> doubtful;
    for (const SampleChange &c : sample_changes(problem, lower, phi, result))
      {
        const nlohmann::json &now = samples[c.index];
        const double estimate = factor * c.relative;
        list.push_back({{"r", now.at("r")}, {"z", now.at("z")}, {"change", c.change}, {"scale", c.scale},
                        {"relative", c.relative}, {"estimate", estimate}, {"limit", limit}});
        if (estimate > limit)
          doubtful.push_back(fmt::format("({:.6g}, {:.6g}) m about {:.2g} % (moved {:.2g} %)",
                                         now.at("r").get<double>(), now.at("z").get<double>(),
                                         100.0 * estimate, 100.0 * c.relative));
      }
    check["samples"] = list;
    if (!doubtful.empty())
      add_warning(result, "samples_unsettled",
                  fmt::format("the indicator met the tolerance {:g} at p = {}, but from p = {} the "
                              "sample{} moved so that, at the rate the indicator falls ({:.2g} per "
                              "two degrees in stress), {} still off by more than {:.2g} % of {} "
                              "stress: {}; the tolerance promises about {:.2g} %: raise rfm.degree "
                              "above {}, tighten rfm.tolerance, or compare with fem_solve",
                              tolerance, p, p - 2, doubtful.size() > 1 ? "s" : "", rate,
                              doubtful.size() > 1 ? "they are" : "it is", 100.0 * limit,
                              doubtful.size() > 1 ? "their" : "its", fmt::join(doubtful, ", "),
                              50.0 * limit, p));
  }

  /// Below this indicator a fixed degree has met the default tolerance: no check at p - 2.
  constexpr double fixed_degree_check_floor = 1e-8;

  /// A fixed degree's doubt (issue 24 item 6): above fixed_degree_indicator_limit the error
  /// measure alone; above fixed_degree_check_floor also a solve at p - 2, whose measure and
  /// dropped directions say whether p still converges: a warning where the measure grows
  /// (rounding or an unresolved singularity wins), or where it falls by less than half while
  /// the orthonormalization drops more directions than at p - 2 (the basis loses its
  /// independence in rounding: the hub section drops 20, 22, 26, 35 stress directions
  /// at p = 8, 12, 16, 20, where its enriched vertex alone accounts for 20). Recorded as
  /// diagnostics.check_at_lower_degree.
  ///
  /// The measure is the one rfm.tolerance compares (Functionals::error_measure): the
  /// indicator, or E / |Phi_R| where that is larger. Where u_h has a fixed part (a traction
  /// jump's particular displacement) Phi_L - Phi_C = E + a defect that can cross zero, and
  /// the indicator alone grew on issue 24's pressed hub from 5.15e-8 at p = 18 to 5.40e-8 at
  /// p = 20 (Phi_L below Phi_C there: it measured no error) while E fell from 8.87e-8 to
  /// 4.98e-8 of |Phi_R|; the measure falls from 8.87e-8 to 5.40e-8. With a die's zones the
  /// indicator alone, as before (Phi_C then carries the zone's prescribed displacement, and a
  /// die problem takes no rfm.tolerance).
  void check_fixed_degree(const axisym::Problem &problem, const rfm::OutlineModel &model,
                          const rfm::Functionals &phi, const int p, nlohmann::json &result,
                          const std::vector<rfm::DieZone> &zones = {})
  {
    auto measure_of = [&zones](const rfm::Functionals &f) {
      return zones.empty() ? f.error_measure() : f.indicator();
    };
    const double measure = measure_of(phi);
    const bool is_indicator = measure == phi.indicator();
    if (measure > fixed_degree_indicator_limit)
      add_warning(result, "indicator",
                  is_indicator ? fixed_degree_warning(measure, p, !zones.empty())
                               : fixed_degree_warning(measure, p, !zones.empty(),
                                                      "the constitutive-relation error E / |Phi_R|"));
    if (!(measure > fixed_degree_check_floor) || p < 4)
      return;
    rfm::DiscretizationOptions o = problem.rfm;
    o.degree = p - 2;
    o.tolerance.reset();
    o.ritz_bound = false; // the check reads the indicator and E alone
    fmt::print(stderr, "rfm_solve: checking the fixed degree against p = {}\n", p - 2);
    const rfm::OutlineModel lower(problem, o, rfm::SolverOptions{}, zones);
    if (!lower.ok())
      {
        add_warning(result, "check_failed",
                    fmt::format("the check at p = {} failed ({}): the fixed degree's "
                                "convergence is not known",
                                p - 2, lower.summary().message));
        return;
      }
    const rfm::Functionals phi_lower = lower.functionals();
    const double before = measure_of(phi_lower);
    const auto d = model.n_dropped_directions(), d_lower = lower.n_dropped_directions();
    result["diagnostics"]["check_at_lower_degree"] = {{"degree", p - 2},
                                                      {"indicator", phi_lower.indicator()},
                                                      {"error_measure", before},
                                                      {"dropped_directions", {d_lower[0], d_lower[1]}}};
    check_sample_changes(problem, lower, phi, p, result);
    if (measure > before)
      add_warning(result, "indicator_grows",
                  fmt::format("{} grows from {:.3g} at p = {} to {:.3g} at the "
                              "fixed degree p = {}: rounding or an unresolved singularity "
                              "wins; the answer is in doubt",
                              is_indicator && before == phi_lower.indicator()
                                ? "the indicator"
                                : "the error measure (the indicator, or E / |Phi_R| where larger)",
                              before, p - 2, measure, p));
    // More dropped directions alone are no doubt while the indicator still falls (the clamped
    // cylinder at p = 12: 4 more than at p = 10, the indicator 2.6 times smaller, Phi_R 2.3e-8
    // from the FEM's limit); with a stalling indicator they say why it stalls.
    const Eigen::Index more = d[0] + d[1] - d_lower[0] - d_lower[1];
    if (more > 0 && measure > 0.5 * before)
      add_warning(result, "dropped_directions",
                  fmt::format("the orthonormalization drops {} more dependent directions at "
                              "p = {} than at p = {} ({} and {} of the stresses, {} and {} of "
                              "the displacements): the basis loses its independence in "
                              "rounding; the answer is in doubt",
                              more, p, p - 2, d[0], d_lower[0], d[1], d_lower[1]));
  }

  /// The samples on the axis (issue 24 items 5 and 6). There a regular field has sigma_rr =
  /// sigma_tt, and the r-weighted functionals do not see values on r = 0: a sample there can
  /// be off while the indicator meets the tolerance. Measured at the defaults against the FEM
  /// (L = 3): the filleted groove's sigma_zz(0, 0) 2.8 % low at indicator 4.5e-7 (p = 16),
  /// the heated sphere's sigma_zz(0, 0.15) 13 % high at 6.1e-6 (p = 12), both with status
  /// "ok" before this check. Whatever the exact value s, |sigma_rr - s| + |sigma_tt - s| >=
  /// |sigma_rr - sigma_tt|: half the mismatch is a lower bound of the error of one of the two.
  /// Its scale is the sample's largest stress component, but at least the stress that stores
  /// |Phi_R| uniaxially, sqrt(2 E |Phi_R| / int r dr dz) (a sample where all stresses are
  /// small is not judged against itself). The tolerance t promises about sqrt(t) in stress
  /// (the Lame calibration: 1e-8 gives 1e-4, 1e-5 gives 0.3 %); a fixed degree is judged as
  /// t = fixed_degree_indicator_limit. A sample warns where the lower bound passes sqrt(t),
  /// i.e. the mismatch 2 sqrt(t) of the scale. Recorded as diagnostics.axis_samples. With
  /// rfm.axis_coupling sigma_rr = sigma_tt on the axis by construction, and the check says
  /// nothing.
  void check_axis_samples(const axisym::Problem &problem, const rfm::Functionals &phi,
                          const std::optional<double> tolerance, nlohmann::json &result)
  {
    const double limit = sample_limit(tolerance);
    const axisym::Outline &outline = problem.body->outline;
    const double floor = energy_stress(problem, phi);
    nlohmann::json list = nlohmann::json::array();
    std::vector<std::string> doubtful;
    for (const nlohmann::json &s : result["samples"])
      {
        if (std::abs(s.at("r").get<double>()) > 1e-9 * outline.size())
          continue;
        const double scale = sample_scale(s, floor);
        const double mismatch = s.at("sigma_rr").get<double>() - s.at("sigma_tt").get<double>();
        const double relative = std::abs(mismatch) / scale;
        list.push_back({{"r", s.at("r")},
                        {"z", s.at("z")},
                        {"sigma_rr_minus_sigma_tt", mismatch},
                        {"scale", scale},
                        {"relative", relative},
                        {"limit", limit}});
        if (relative > limit)
          doubtful.push_back(fmt::format("{:.2g} % of the stress at ({:.6g}, {:.6g}) m", 100.0 * relative,
                                         s.at("r").get<double>(), s.at("z").get<double>()));
      }
    if (list.empty())
      return;
    result["diagnostics"]["axis_samples"] = list;
    if (!doubtful.empty())
      add_warning(result, "axis_samples",
                  fmt::format("on the axis sigma_rr = sigma_tt, but they differ by {} (limit {:.2g} %): at "
                              "least half of that is the error of sigma_rr or sigma_tt there, more than "
                              "{}, and the indicator does not see it (the functionals weigh with r); "
                              "the axis values are in doubt: raise rfm.degree, or compare with fem_solve",
                              fmt::join(doubtful, ", "), 100.0 * limit,
                              tolerance ? fmt::format("the tolerance {:g} promises ({:.2g} %)", *tolerance,
                                                      50.0 * limit)
                                        : fmt::format("the {:.2g} % a fixed degree is allowed", 50.0 * limit)));
  }

  /// Samples at a vertex where the stress has no value (issue 24 item 6;
  /// problem/sample_checks.h, the same check as fem_solve's): diagnostics.samples_at_vertices,
  /// with a warning.
  void check_vertex_samples(const axisym::Problem &problem, nlohmann::json &result)
  {
    const std::vector<axisym::SampleAtVertex> at = axisym::samples_at_vertices(problem);
    if (at.empty())
      return;
    result["diagnostics"]["samples_at_vertices"] = axisym::to_json(at);
    add_warning(result, "samples_at_vertices", axisym::samples_at_vertices_warning(at));
  }

  /// A resonant vertex's field against the local problem (issue 24 item 6): the amplitude a of
  /// the stress's rho ln rho term there is fixed by the temperature gradient across the
  /// symmetry line (rfm::ResonantVertex::theory_amplitude), while the solve finds it as the
  /// coefficient of a column that the polynomials nearly span, so that it can also stand in
  /// for smooth detail they miss near the vertex. Each entry of diagnostics.resonant_vertices
  /// gets `log_amplitude` (`solution`, `theory` [Pa/m], `ratio`), and a ratio off 1 by more
  /// than resonant_amplitude_limit warns (`resonant_log_amplitude`): the field near the vertex
  /// is not the local problem's. Measured (ratio at p = 12, 16, 20): the heated ring of
  /// verification/problems/heated_ring_axial_gradient.json 1.00, 0.94, 0.94 (the vertex's
  /// sample 1.1e-3, 1.1e-3, 7.3e-4 of the largest sample stress off the FEM's), the heated
  /// sphere of heated_sphere.json at its equator's vertices 0.77 and 0.84 (0.98 and 1.14 at
  /// p = 16; 0.70 and -1.03 at p = 8, where it warns); issue 24's heated hub at (0.8, 0) 0.47,
  /// 2.5, 2.3 (sigma_zz there +0.20 %, -0.82 %, -0.47 % off the FEM's), its other three
  /// between -3.9 and 7.1. The limit lies between the two groups.
  constexpr double resonant_amplitude_limit = 0.5;
  void check_resonant_amplitudes(const rfm::OutlineModel &model, nlohmann::json &result)
  {
    const std::vector<rfm::OutlineModel::LogAmplitude> a = model.resonant_log_amplitudes();
    if (a.empty() || !result["diagnostics"].contains("resonant_vertices"))
      return;
    nlohmann::json &list = result["diagnostics"]["resonant_vertices"];
    std::string off;
    for (std::size_t i = 0; i < a.size() && i < list.size(); ++i)
      {
        const bool known = a[i].theory != 0.0;
        const double ratio = known ? a[i].solution / a[i].theory : 0.0;
        list[i]["log_amplitude"] = {{"solution", a[i].solution},
                                    {"theory", a[i].theory},
                                    {"ratio", known ? nlohmann::json(ratio) : nlohmann::json(nullptr)},
                                    {"units", "Pa/m"}};
        const rfm::ResonantVertex &v = model.resonant_vertices()[i];
        fmt::print(stderr,
                   "rfm_solve: resonant vertex at ({:.6g}, {:.6g}) m: the stress's rho ln rho term has the "
                   "amplitude {:.4g} Pa/m, the local problem's {:.4g} Pa/m\n",
                   v.vertex().r, v.vertex().z, a[i].solution, a[i].theory);
        if (known && std::abs(ratio - 1.0) > resonant_amplitude_limit)
          off += fmt::format("{}({:.6g}, {:.6g}) m {:.2f} times it", off.empty() ? "" : ", ", v.vertex().r,
                             v.vertex().z, ratio);
      }
    if (!off.empty())
      add_warning(result, "resonant_log_amplitude",
                  fmt::format("at a resonant vertex the stress's rho ln rho term, whose amplitude the temperature "
                              "gradient across the symmetry line fixes (2 E alpha g / (pi (1 - nu))), is off "
                              "that value by more than {:.0f} %: {}; the field near the vertex, its own value "
                              "included, is not the local problem's and is in doubt: raise rfm.degree, or "
                              "compare with fem_solve",
                              100.0 * resonant_amplitude_limit, off));
  }

  /// Samples on a die's contact zone (issue 24 item 6). There the sample's stresses are the
  /// stress space's traces, and its normal stress is a worse estimate of the contact pressure
  /// than the consistent reactions (rfm::consistent_die_pressure; README, 'contact.pressure').
  /// Measured on die_unilateral.json at the default p = 8, sample (0.2, 0): sigma_rr -0.8784 MPa
  /// (trace), -0.9152 MPa (consistent), the FEM's L4 -0.9153 MPa. Each such sample gets
  /// `contact_pressure` (the consistent p [Pa], positive pushing on the body) and is listed in
  /// diagnostics.contact_samples; it warns (`sample_on_contact_zone`) when its trace and the
  /// consistent pressure differ by more than the limit of the axis check, over the sample's
  /// scale. Not where the consistent form does not apply (rfm::consistent_pressure_applies:
  /// the trace is then the best estimate there is) nor at a sharp edge (infinite there). A
  /// sample at a zone's end (within 1e-3 of the zone's length; a mirrored body's below z = 0
  /// at its image; not the die's centre on the axis or a symmetry edge) warns
  /// (`samples_at_zone_ends`): the stress is not smooth there (measured on die_bilateral.json
  /// at (0.2, 0.2), where the zone meets the free end face: sigma_rr 1.818, 1.856, 1.872 MPa
  /// at p = 8, 12, 16, the FEM's 1.893, 1.895, 1.896, 1.896 at L = 2-5).
  void check_contact_samples(const axisym::Problem &problem, const rfm::OutlineModel &model,
                             const std::vector<rfm::DieZone> &zones, const rfm::Functionals &phi,
                             const std::optional<double> tolerance, nlohmann::json &result)
  {
    const double limit = sample_limit(tolerance);
    const double floor = energy_stress(problem, phi);
    nlohmann::json &samples = result["samples"];
    // Where each sample lies, and the consistent pressure there: one call per zone (each
    // takes the zone's moments from the model).
    std::vector<std::optional<OnZone>> where;
    for (const nlohmann::json &sample : samples)
      where.push_back(on_zone(problem, zones, sample.at("r").get<double>(), sample.at("z").get<double>()));
    std::vector<double> pressure(where.size(), std::numeric_limits<double>::quiet_NaN());
    for (const rfm::DieZone &zone : zones)
      {
        std::vector<std::size_t> at;
        std::vector<double> s;
        for (std::size_t k = 0; k < where.size(); ++k)
          if (where[k] && where[k]->zone == &zone)
            at.push_back(k), s.push_back(where[k]->s);
        if (at.empty())
          continue;
        const std::vector<double> p = rfm::consistent_die_pressure(model, problem, zone, s,
                                                                   rfm::default_pressure_moments);
        for (std::size_t i = 0; i < at.size(); ++i)
          pressure[at[i]] = p[i];
      }
    nlohmann::json list = nlohmann::json::array();
    std::vector<std::string> doubtful, at_ends;
    for (std::size_t k = 0; k < where.size(); ++k)
      {
        if (!where[k])
          continue;
        nlohmann::json &sample = samples[k];
        const double r = sample.at("r").get<double>(), z = sample.at("z").get<double>();
        const rfm::DieZone &zone = *where[k]->zone;
        const axisym::DieFrame &f = where[k]->frame;
        const double s = where[k]->s;
        if (where[k]->at_end)
          at_ends.push_back(fmt::format("({:.6g}, {:.6g}) m on part {}", r, z, zone.part));
        const double p = pressure[k];
        if (!std::isfinite(p))
          continue;
        const double trace = -(sample.at("sigma_rr").get<double>() * f.normal.r * f.normal.r +
                               2.0 * sample.at("sigma_rz").get<double>() * f.normal.r * f.normal.z +
                               sample.at("sigma_zz").get<double>() * f.normal.z * f.normal.z);
        const double scale = sample_scale(sample, floor);
        const double relative = std::abs(trace - p) / scale;
        sample["contact_pressure"] = p;
        list.push_back({{"r", r},
                        {"z", z},
                        {"part", zone.part},
                        {"s", s},
                        {"contact_pressure", p},
                        {"pressure_trace", trace},
                        {"scale", scale},
                        {"relative", relative},
                        {"limit", limit}});
        if (relative > limit)
          doubtful.push_back(fmt::format("at ({:.6g}, {:.6g}) m its trace {:.6g} Pa against {:.6g} Pa, "
                                         "{:.2g} % of its stress",
                                         r, z, trace, p, 100.0 * relative));
      }
    if (!list.empty())
      result["diagnostics"]["contact_samples"] = list;
    if (!doubtful.empty())
      add_warning(result, "sample_on_contact_zone",
                  fmt::format("samples on a die's contact zone: their stresses are the stress space's "
                              "traces, and the normal stress differs from the consistent contact "
                              "pressure (the more accurate estimate) {} (limit {:.2g} %): their "
                              "stresses are in doubt; each sample's contact_pressure holds the "
                              "consistent value",
                              fmt::join(doubtful, "; "), 100.0 * limit));
    if (!at_ends.empty())
      add_warning(result, "samples_at_zone_ends",
                  fmt::format("samples at the end of a die's contact zone, {}: the stress is not "
                              "smooth there and its value converges slowly; move the sample off "
                              "the end",
                              fmt::join(at_ends, ", ")));
  }

  // The fields at the problem's sample points (any model with evaluate(r, z)).
  template <typename Model>
  nlohmann::json fields_to_json(const axisym::Problem &problem, const Model &model)
  {
    nlohmann::json out = nlohmann::json::array();
    if (problem.samples.empty())
      return out;
    const Eigen::Index n = static_cast<Eigen::Index>(problem.samples.size());
    Eigen::VectorXd r(n), z(n);
    for (Eigen::Index k = 0; k < n; ++k)
      r[k] = problem.samples[k][0], z[k] = problem.samples[k][1];
    const rfm::FieldValues f = model.evaluate(r, z);
    for (Eigen::Index k = 0; k < n; ++k)
      out.push_back({{"r", r[k]},
                     {"z", z[k]},
                     {"u_r", f.u(k, 0)},
                     {"u_z", f.u(k, 1)},
                     {"sigma_rr", f.sigma(k, rfm::rr)},
                     {"sigma_zz", f.sigma(k, rfm::zz)},
                     {"sigma_tt", f.sigma(k, rfm::tt)},
                     {"sigma_rz", f.sigma(k, rfm::rz)}});
    return out;
  }

  // A degree sequence (rfm.tolerance): one line per degree on stderr.
  void print_sequence(const std::vector<rfm::DegreeStep> &steps)
  {
    for (const rfm::DegreeStep &step : steps)
      if (step.measure > step.indicator)
        fmt::print(stderr, "rfm_solve:   p = {:2d}: indicator {:.3e}, E / |Phi_R| {:.3e} (compared) ({:.3f} s)\n",
                   step.degree, step.indicator, step.measure, step.seconds);
      else
        fmt::print(stderr, "rfm_solve:   p = {:2d}: indicator {:.3e} ({:.3f} s)\n", step.degree,
                   step.indicator, step.seconds);
  }

  // ... and its record in the result's discretization.
  void record_sequence(nlohmann::json &discretization, const double tolerance,
                       const std::vector<rfm::DegreeStep> &steps)
  {
    nlohmann::json seq = nlohmann::json::array();
    for (const rfm::DegreeStep &step : steps)
      seq.push_back({{"degree", step.degree},
                     {"indicator", step.indicator},
                     {"error_measure", step.measure},
                     {"seconds", step.seconds}});
    discretization["tolerance"] = tolerance;
    discretization["degree_sequence"] = seq;
  }

  // P(c) at curve_points zone widths in (0, a] (bilateral solves).
  nlohmann::json force_curve(const axisym::Problem &problem)
  {
    const double a = problem.geometry.half_length();
    const int n = problem.contact.curve_points;
    nlohmann::json out = nlohmann::json::array();
    for (int k = 1; k <= n; ++k)
      {
        const double c = a * k / n;
        const std::unique_ptr<rfm::OutlineModel> m = rfm::solve_cylinder_zone(problem, problem.rfm, c);
        if (!m->ok())
          continue;
        const rfm::OutlineModel::DieForce f = m->die_force("outer");
        const double k_edge =
          c < a && m->n_zone_edges() > 0
            ? rfm::edge_intensity_interaction(*m, problem, c, rfm::interaction_radius(problem.geometry, c))
            : std::numeric_limits<double>::quiet_NaN();
        out.push_back({{"half_width", c},
                       {"force", f.domain},
                       {"force_trace", f.trace},
                       {"edge_intensity", std::isfinite(k_edge) ? nlohmann::json(k_edge)
                                                                : nlohmann::json(nullptr)}});
      }
    return out;
  }
  // The dies on outline parts (DESIGN.md 7.1), one zone per die part in Body::die_parts()
  // order: the bilateral problem's zone (contact.method "fixed", contact.half_width c for every
  // die: the zone is [0, c] from a centre at the part's end, [-c, c] otherwise, within the
  // part; default the whole part; the searches start from their own estimates). Throws
  // InputError for what the outline RFM cannot do yet.
  std::vector<rfm::DieZone> die_zones(const axisym::Problem &problem)
  {
    const std::vector<std::string> parts = problem.body->die_parts();
    if (parts.size() > 1 && (problem.contact.method == "iterate" || problem.contact.method == "max-force"))
      throw axisym::InputError(
        "contact.method = \"" + problem.contact.method + "\": it searches one die's zone, and the "
        "problem has " + std::to_string(parts.size()) + " (boundary." + parts[0] + ".die, boundary." +
        parts[1] + ".die, ...); use \"edge-intensity\" (the default) or \"fixed\"");
    std::vector<rfm::DieZone> out;
    for (const std::string &part : parts)
      {
        const axisym::DieFrame f = axisym::die_frame(*problem.body, part);
        const axisym::DieCondition &die = problem.body->conditions.at(part).die;
        const double c = problem.contact.half_width.value_or(std::max(-f.s_min, f.s_max));
        // Under force control the zone's delta is found by the solve (outline_contact.h).
        out.push_back(rfm::DieZone{part, std::max(f.s_min, -c), std::min(f.s_max, c),
                                   die.indentation.value_or(0.0)});
      }
    return out;
  }

  bool zone_has_free_end(const axisym::Problem &problem, const rfm::DieZone &zone)
  {
    const axisym::DieFrame f = axisym::die_frame(*problem.body, zone.part);
    return f.free_low_end(zone.s_lo) || f.free_high_end(zone.s_hi);
  }

  /// No die, or dies whose zones have no free end (bilateral zones over whole parts): no
  /// contact edge, whose singular error the indicator does not see (DESIGN.md 4.4), so a fixed
  /// degree is judged as without a die (check_fixed_degree, on the same zones at p - 2).
  /// Measured on die_bilateral.json at the default p = 8: the indicator 1.4e-5, sigma_zz at
  /// (0.2, 0) -0.9436 MPa against the FEM's -0.9649 (L = 3-5), 2.2 % off, status ok before.
  bool without_free_ends(const axisym::Problem &problem, const std::vector<rfm::DieZone> &zones)
  {
    return std::none_of(zones.begin(), zones.end(),
                        [&](const rfm::DieZone &z) { return zone_has_free_end(problem, z); });
  }

  // K at each free end of a die's zone (null without one): one number, or [low end, high end].
  nlohmann::json edge_intensity_json(const rfm::OutlineModel &m, const std::string &part)
  {
    std::vector<double> k;
    for (std::size_t i = 0; i < m.n_zone_edges(); ++i)
      if (m.zone_edge_part(i) == part)
        k.push_back(m.edge_intensity(i));
    if (k.empty())
      return nullptr;
    if (k.size() == 1)
      return k[0];
    return k;
  }

  // The die's record (DESIGN.md 7: `contact` and `dies`), for a bilateral zone: c, the zone
  // when it has two free ends, P two ways, the pressure trace along the part.
  nlohmann::json outline_die_to_json(const axisym::Problem &problem, const rfm::OutlineModel &m,
                                     const rfm::DieZone &zone, const rfm::Functionals &phi)
  {
    const axisym::DieFrame f = axisym::die_frame(*problem.body, zone.part);
    const rfm::OutlineModel::DieForce force = m.die_force(zone.part);
    const bool has_up = f.runs_up(), has_down = f.runs_down();
    const double half_width =
      has_up && has_down ? 0.5 * (zone.s_hi - zone.s_lo) : (has_up ? zone.s_hi : -zone.s_lo);
    nlohmann::json c = {{"part", zone.part},
                        {"method", "fixed"},
                        {"half_width", half_width},
                        {"indentation", zone.indentation},
                        {"force", force.domain},
                        {"force_trace", force.trace},
                        {"edge_intensity", edge_intensity_json(m, zone.part)},
                        {"iterations",
                         {{{"half_width", half_width},
                           {"force", force.domain},
                           {"lagrange", phi.lagrange},
                           {"castigliano", phi.castigliano},
                           {"reissner", phi.reissner}}}}};
    if (has_up && has_down)
      c["zone"] = {zone.s_lo, zone.s_hi};
    // The pressure at 101 points of the zone: p the consistent reactions
    // (rfm::consistent_die_pressure; null at a sharp edge, where it is infinite) where they
    // apply (rfm::consistent_pressure_applies), the trace otherwise; p_trace the trace
    // -sigma_nn.
    const int n = 101;
    Eigen::VectorXd r(n), z(n);
    std::vector<double> s(n);
    for (int k = 0; k < n; ++k)
      {
        s[k] = zone.s_lo + (zone.s_hi - zone.s_lo) * k / (n - 1.0);
        const axisym::Point x = f.point_at(s[k]);
        r[k] = x.r, z[k] = x.z;
      }
    const rfm::FieldValues v = m.evaluate(r, z);
    const std::vector<double> consistent =
      rfm::consistent_die_pressure(m, problem, zone, s, rfm::default_pressure_moments);
    const bool consistent_applies = rfm::consistent_pressure_applies(f, zone);
    nlohmann::json pressure = nlohmann::json::array();
    for (int k = 0; k < n; ++k)
      {
        const double trace = -(v.sigma(k, rfm::rr) * f.normal.r * f.normal.r +
                                2 * v.sigma(k, rfm::rz) * f.normal.r * f.normal.z +
                                v.sigma(k, rfm::zz) * f.normal.z * f.normal.z);
        pressure.push_back({{"s", s[k]}, {"r", r[k]}, {"z", z[k]},
                            {"p", std::isfinite(consistent[k]) ? nlohmann::json(consistent[k])
                                  : consistent_applies         ? nlohmann::json(nullptr)
                                                               : nlohmann::json(trace)},
                            {"p_trace", trace}});
      }
    c["pressure"] = pressure;
    return c;
  }

  // A section given by its outline (DESIGN.md 7.1): the outline structures, at a fixed
  // degree or to a tolerance, and a die on a given zone.
  /// The displacement space's own bound (OutlineModel::ritz_lagrange; rfm.ritz_bound) beside
  /// the mixed one: both are upper bounds of Phi. functionals.lagrange_ritz, indicator_ritz
  /// (|Phi_L - Phi_C| / |Phi_R| with it), diagnostics.stress_space_gap
  /// (OutlineModel::stress_space_gap over |Phi_R|: `projected`, the constitutive-relation
  /// error of the Ritz displacement with the stress space's best stress for it, `mixed_stress`
  /// that with s_h, and `share`, projected over the mixed solution's E) and
  /// timing.ritz_bound_s (the Ritz solve and the projection are made with the model, in its
  /// construction: OutlineModel::ritz_seconds). No die.
  void add_ritz_bound(const rfm::OutlineModel &model, const rfm::Functionals &phi, nlohmann::json &result)
  {
    const auto t0 = std::chrono::steady_clock::now();
    // (The Ritz bound from the same pass over u_R as the gap's E: OutlineModel::ritz_lagrange
    // would evaluate it again.)
    const rfm::OutlineModel::StressSpaceGap gap = model.stress_space_gap();
    const double ritz = gap.lagrange;
    const double indicator = std::abs(ritz - phi.castigliano) / std::abs(phi.reissner);
    result["functionals"]["lagrange_ritz"] = ritz;
    result["functionals"]["indicator_ritz"] = indicator;
    const double scale = std::abs(phi.reissner);
    // E is integrated as the assembly integrates (the polynomial part on the section's rule,
    // the rest on the near rules), which is no sum of squares: where those rules miss part of
    // a field's density E can come out negative, and then says nothing (issue 24's pressed
    // hub at p = 12: -7.5e-7 of |Phi_R| projected).
    const bool resolved = gap.projected >= 0.0 && phi.constitutive_error > 0.0;
    result["diagnostics"]["stress_space_gap"] = {
      {"projected", gap.projected / scale},
      {"mixed_stress", gap.ritz / scale},
      {"share", resolved ? nlohmann::json(gap.projected / phi.constitutive_error) : nlohmann::json(nullptr)}};
    result["timing"]["ritz_bound_s"] =
      model.ritz_seconds() + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fmt::print(stderr, "rfm_solve: the displacement space's bound Phi_L = {:.9e} J/rad (Phi_L(u_h) {:.9e}); "
               "|Phi_L - Phi_C| / |Phi_R| with it {:.3g}\n", ritz, phi.lagrange, indicator);
    if (!resolved)
      {
        fmt::print(stderr, "rfm_solve: the stress space's best stress for that displacement leaves E = {:.3g} of "
                   "|Phi_R| (the mixed solution's {:.3g}): below zero, the rules do not resolve it, and the "
                   "comparison says nothing here\n", gap.projected / scale, phi.constitutive_error / scale);
        return;
      }
    fmt::print(stderr, "rfm_solve: the stress space's best stress for that displacement leaves E = {:.3g} of |Phi_R|, "
               "{:.0f} % of the mixed solution's E ({:.3g}): {}\n", gap.projected / scale,
               100.0 * gap.projected / phi.constitutive_error, phi.constitutive_error / scale,
               gap.projected > 0.5 * phi.constitutive_error
                 ? "the stress space holds the solution back, not the displacement"
                 : "most of it is the mixed displacement's distance from the Ritz one (u_h, the multiplier of "
                   "equilibrium, falls behind its own space's best), not the stress space");
  }

  /// Where the indicator's gap lies (OutlineModel::constitutive_error_map): the
  /// constitutive-relation error E and its map on 8 x 8 cells of the section's box, as
  /// diagnostics.constitutive_error: total [J/rad], relative (E / |Phi_R|),
  /// gap_minus_error ((Phi_L - Phi_C - E) / |Phi_R|: zero to rounding unless u_h has a fixed
  /// part, the model's header), the cells' edges [m], shares and sum [J/rad], and the three
  /// largest cells, which stderr names too.
  void add_constitutive_error(const rfm::OutlineModel &model, const rfm::Functionals &phi, nlohmann::json &result)
  {
    constexpr int n_cells = 8;
    const auto t0 = std::chrono::steady_clock::now();
    const rfm::OutlineModel::ErrorMap map = model.constitutive_error_map(n_cells, n_cells);
    const double mapped = map.cells.sum();
    nlohmann::json r_edges = nlohmann::json::array(), z_edges = nlohmann::json::array(),
                   share = nlohmann::json::array();
    for (int i = 0; i <= n_cells; ++i)
      r_edges.push_back(map.r_edge(i)), z_edges.push_back(map.z_edge(i));
    for (int i = 0; i < n_cells; ++i)
      {
        nlohmann::json row = nlohmann::json::array();
        for (int j = 0; j < n_cells; ++j)
          row.push_back(mapped > 0.0 ? map.cells(i, j) / mapped : 0.0);
        share.push_back(row);
      }
    nlohmann::json largest = nlohmann::json::array();
    std::string said;
    if (mapped > 0.0)
      for (const auto &[i, j] : map.largest(3))
        {
          const double fraction = map.cells(i, j) / mapped;
          largest.push_back({{"r", {map.r_edge(i), map.r_edge(i + 1)}},
                             {"z", {map.z_edge(j), map.z_edge(j + 1)}},
                             {"share", fraction}});
          said += fmt::format("{}{:.0f} % in r [{:.4g}, {:.4g}], z [{:.4g}, {:.4g}] m", said.empty() ? "" : "; ",
                              100.0 * fraction, map.r_edge(i), map.r_edge(i + 1), map.z_edge(j), map.z_edge(j + 1));
        }
    const double scale = std::abs(phi.reissner);
    result["diagnostics"]["constitutive_error"] = {
      {"total", map.total},
      {"relative", map.total / scale},
      {"gap_minus_error", (phi.lagrange - phi.castigliano - map.total) / scale},
      {"units", "total and cells.sum in J per radian, cell edges in m; relative and gap_minus_error "
                "over |Phi_R|; shares of cells.sum"},
      {"cells", {{"r", r_edges}, {"z", z_edges}, {"share", share}, {"sum", mapped}}},
      {"largest", largest}};
    result["timing"]["constitutive_error_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (map.total > indicator_rounding * scale)
      fmt::print(stderr, "rfm_solve: constitutive error E = {:.4e} J/rad ({:.3g} of |Phi_R|; Phi_L - Phi_C = {:.6g} E): {}\n",
                 map.total, map.total / scale, (phi.lagrange - phi.castigliano) / map.total, said);
    else
      fmt::print(stderr, "rfm_solve: constitutive error E = {:.4e} J/rad, at rounding ({:.3g} of |Phi_R|)\n",
                 map.total, map.total / scale);
  }

  // The result after a numerical failure (exit 3): to --output when given, else to stdout as
  // a success's would go (DESIGN.md 7: any partial history is still written).
  void write_failed_result(const std::string &output_path, const nlohmann::json &result)
  {
    if (!output_path.empty())
      axisym::write_json_atomically(output_path, result);
    else
      std::cout << result.dump(2) << '\n';
  }

  int solve_outline(axisym::Problem problem, const std::optional<double> target_indicator,
                    const std::string &output_path, const std::string &vtu_directory)
  {
    std::unique_ptr<rfm::OutlineModel> model;
    std::optional<rfm::DegreeSequence<rfm::OutlineModel>> sequence;
    std::vector<rfm::DieZone> zones = die_zones(problem);
    std::optional<rfm::OutlineContactResult> search;
    std::optional<rfm::ContactResult> checked;
    std::optional<rfm::OutlineDiesResult> several;
    if (zones.size() > 1)
      {
        // Several dies: all zones together (outline_contact.h).
        const bool search_zones = problem.contact.method == "edge-intensity";
        fmt::print(stderr, "rfm_solve: outline section, degree p = {}, {} dies ({}): {}\n",
                   problem.rfm.degree, zones.size(), fmt::join(problem.body->die_parts(), ", "),
                   search_zones ? "every free end where its edge intensity K vanishes"
                                : "bilateral zones as given");
        // Each trial as it is solved (the searches take minutes on fine zones).
        auto clock = std::chrono::steady_clock::now();
        auto print_step = [&clock](const rfm::OutlineDiesStep &step) {
          const auto now = std::chrono::steady_clock::now();
          std::vector<std::string> z;
          for (std::size_t d = 0; d < step.zones.size(); ++d)
            z.push_back(fmt::format("{} [{:.6g}, {:.6g}] m P = {:.6g} N delta = {:.6g} m",
                                    step.zones[d].part, step.zones[d].s_lo, step.zones[d].s_hi,
                                    step.forces[d], step.zones[d].indentation));
          fmt::print(stderr, "rfm_solve:   {}; K = {:.5g} Pa m^1/2 ({}, {:.1f} s)\n", fmt::join(z, "; "),
                     fmt::join(step.edge_intensities, ", "), step.phase,
                     std::chrono::duration<double>(now - clock).count());
          clock = now;
        };
        if (search_zones)
          {
            rfm::OutlineContactOptions options;
            options.on_dies_step = print_step;
            several = rfm::solve_outline_dies(problem, problem.rfm, options);
          }
        else
          {
            several = rfm::solve_outline_dies_on_zones(problem, problem.rfm, zones);
            for (const rfm::OutlineDiesStep &step : several->history)
              print_step(step);
          }
        if (!several->success || !several->model)
          {
            nlohmann::json failed = {{"solver", "rfm"}, {"problem", problem.source},
                                     {"diagnostics", {{"status", "failed"}, {"message", several->message}}}};
            write_failed_result(output_path, failed);
            fmt::print(stderr, "rfm_solve: numerical failure: {}\n", several->message);
            return 3;
          }
        zones = several->zones;
        model = std::move(several->model);
      }
    else if (!zones.empty() && problem.contact.method == "edge-intensity")
      {
        fmt::print(stderr, "rfm_solve: outline section, degree p = {}, die on {}: the zone's end "
                           "where the edge intensity K vanishes\n",
                   problem.rfm.degree, zones[0].part);
        // Each trial as it is solved: a ring die's search takes minutes (about 100 s a solve).
        rfm::OutlineContactOptions options;
        options.on_step = [clock = std::chrono::steady_clock::now()](const rfm::OutlineContactStep &step) mutable {
          const auto now = std::chrono::steady_clock::now();
          fmt::print(stderr,
                     "rfm_solve:   zone [{:.6g}, {:.6g}] m: K = {:.5g} Pa m^1/2, P = {:.6g} N, "
                     "delta = {:.6g} m ({}, {:.1f} s)\n",
                     step.zone[0], step.zone[1], fmt::join(step.edge_intensities, ", "), step.force,
                     step.indentation, step.phase, std::chrono::duration<double>(now - clock).count());
          clock = now;
        };
        search = rfm::solve_outline_contact(problem, problem.rfm, options);
        if (!search->success || !search->model)
          {
            nlohmann::json failed = {{"solver", "rfm"}, {"problem", problem.source},
                                     {"diagnostics", {{"status", "failed"}, {"message", search->message}}}};
            nlohmann::json history = nlohmann::json::array();
            for (const rfm::OutlineContactStep &step : search->history)
              history.push_back({{"half_width", step.half_width}, {"force", step.force},
                                 {"edge_intensity", step.edge_intensity}});
            failed["contact"] = {{"iterations", history}};
            write_failed_result(output_path, failed);
            fmt::print(stderr, "rfm_solve: numerical failure: {}\n", search->message);
            return 3;
          }
        zones = {search->zone};
        model = std::move(search->model);
      }
    else if (!zones.empty() && problem.contact.method != "fixed")
      {
        // iterate or max-force: conditions 1.2 and 1.3 on trial zones (outline_contact.h).
        fmt::print(stderr, "rfm_solve: outline section, degree p = {}, die on {}: contact.method "
                           "{} on conditions 1.2 and 1.3\n",
                   problem.rfm.degree, zones[0].part, problem.contact.method);
        checked = rfm::solve_outline_contact_by_conditions(
          problem, problem.rfm, {}, [](const rfm::ContactIterate &it) {
            fmt::print(stderr,
                       "rfm_solve:   c = {:.6g} m: P = {:.6g} N, delta = {:.6g} m, K = {:.5g} Pa "
                       "m^1/2, tension {}, penetration {} ({}, {:.1f} s)\n",
                       it.half_width, it.force, it.indentation, it.edge_intensity,
                       it.tension ? "yes" : "no", it.penetration ? "yes" : "no", it.phase,
                       it.assembly_s + it.solve_s);
          });
        if (!checked->success || !checked->model)
          {
            nlohmann::json failed = {{"solver", "rfm"}, {"problem", problem.source},
                                     {"diagnostics", {{"status", "failed"}, {"message", checked->message}}}};
            failed["contact"] = rfm::to_json(*checked, problem, 0);
            write_failed_result(output_path, failed);
            fmt::print(stderr, "rfm_solve: numerical failure: {}\n", checked->message);
            return 3;
          }
        model = std::move(checked->model);
        zones = {model->zones().at(0)};
      }
    else if (!zones.empty())
      {
        fmt::print(stderr, "rfm_solve: outline section, degree p = {}, die on {}: bilateral "
                           "zone [{:.6g}, {:.6g}] m along the part\n",
                   problem.rfm.degree, zones[0].part, zones[0].s_lo, zones[0].s_hi);
        search = rfm::solve_outline_zone(problem, problem.rfm, zones[0].s_lo, zones[0].s_hi);
        if (!search->success || !search->model)
          {
            fmt::print(stderr, "rfm_solve: numerical failure: {}\n", search->message);
            return 3;
          }
        zones = {search->zone};
        model = std::move(search->model);
      }
    else if (target_indicator)
      {
        fmt::print(stderr, "rfm_solve: outline section; p = 2, 4, ... until the indicator < "
                           "{:.1e} (up to p = {})\n",
                   *target_indicator, problem.rfm.max_degree);
        sequence = rfm::solve_outline_to_tolerance(problem, problem.rfm, *target_indicator);
        model = std::move(sequence->model);
        problem.rfm.degree = sequence->steps.empty() ? 2 : sequence->steps.back().degree;
        print_sequence(sequence->steps);
      }
    else
      {
        fmt::print(stderr, "rfm_solve: outline section, degree p = {}{}\n", problem.rfm.degree,
                   problem.rfm.degree_z() != problem.rfm.degree
                     ? fmt::format(" (p_z = {} along z)", problem.rfm.degree_z())
                     : std::string());
        model = std::make_unique<rfm::OutlineModel>(problem, problem.rfm);
      }
    const int p = problem.rfm.degree;
    // N per component: the global polynomials' (p + 1)(p_z + 1) and the local boxes' functions.
    const long n_basis = static_cast<long>(model->n_basis_functions());
    const long n_edge = static_cast<long>(model->n_edge_columns()) +
                        static_cast<long>(model->n_vertex_columns());
    nlohmann::json result;
    result["solver"] = "rfm";
    result["problem"] = problem.source;
    result["discretization"] = {
      {"degree", p},
      {"degree_z", model->degree_z()},
      {"N", n_basis},
      {"local_functions", model->n_local_functions()},
      {"local_boxes", model->local_basis().patches().size()},
      {"local_stress_functions", model->n_local_stress_columns()},
      {"edge_columns", static_cast<long>(model->n_edge_columns())},
      {"vertex_columns", static_cast<long>(model->n_vertex_columns())},
      {"jump_columns", static_cast<long>(model->n_jump_columns())},
      {"unknowns", 6 * n_basis + model->n_boundary_columns() + model->n_local_stress_columns() +
                     2 * n_edge},
      {"stress_unknowns",
       4 * n_basis + model->n_boundary_columns() + model->n_local_stress_columns() + n_edge},
      {"displacement_unknowns", 2 * n_basis + n_edge},
      {"boundary_columns", model->n_boundary_columns()},
      {"unknowns_after_orthonormalization",
       {model->n_kept_unknowns()[0], model->n_kept_unknowns()[1]}},
      {"dropped_directions", {model->n_dropped_directions()[0], model->n_dropped_directions()[1]}},
      {"quadrature_points", model->n_quadrature_points()},
      {"section", "the outline as given (no mirroring)"},
      {"axis_parity", model->axis_parity()},
      {"axis_coupling", model->axis_coupling()},
      {"degree_policy", target_indicator ? "tolerance" : "fixed"}};
    if (!model->axis_parity())
      result["discretization"]["axis_parity_obstacle"] = model->axis_parity_obstacle();
    if (model->n_vertex_columns() > 0) // the vertices' smooth local stress columns' degree at p
      result["discretization"]["vertex_local_degree"] = problem.rfm.vertex_local_stress_degree();
    if (sequence)
      record_sequence(result["discretization"], *target_indicator, sequence->steps);
    result["timing"] = {{"assembly_s", model->assembly_seconds()},
                        {"solve_s", model->solve_seconds()}};
    const rfm::SolveSummary &s = model->summary();
    const bool solved = model->ok() && (!sequence || sequence->reached);
    result["diagnostics"] = {{"status", solved ? "ok" : "failed"},
                             {"message", sequence ? sequence->message : s.message},
                             {"rcond_stress_block", s.rcond_stress},
                             {"rcond_schur_complement", s.rcond_schur},
                             {"inf_sup_indicator", s.inf_sup}};
    // Vertices where the field is singular (issue 24 item 2): without vertex modes the
    // stresses near them converge slowly and their values at the vertex are not limits,
    // whatever the indicator says (it measures energy); a tolerance may not be reached.
    const std::vector<rfm::SingularVertex> vertices =
      rfm::singular_vertices(*problem.body, problem.material.poisson_ratio);
    std::string vertex_warning;
    if (!vertices.empty())
      {
        nlohmann::json list = nlohmann::json::array();
        const rfm::SingularVertex *bare = nullptr; // the first vertex without columns
        std::size_t n_bare = 0;
        for (const rfm::SingularVertex &v : vertices)
          {
            nlohmann::json entry = vertex_entry(v);
            nlohmann::json &enrichment = entry["enrichment"];
            const double tol = 1e-9 * problem.body->outline.size();
            if (const rfm::VertexEnrichment *found = model->vertex_enrichment_at(v.at, tol))
              {
                const rfm::VertexEnrichment &e = *found;
                enrichment = {{"columns", e.n_columns()},
                              {"modes", e.modes().size()},
                              {"cutoff_radius", e.cutoff_radius()},
                              {"support", e.section_support() ? (e.has_section_rule() ? "section" : "blended") : "local"},
                              {"curved_faces", e.curved()},
                              {"hoop_shadow", e.hoop_shadow()}};
                enrichment["inner_disc"] =
                  e.inner_degree() < 0
                    ? nlohmann::json(nullptr)
                    : nlohmann::json{{"radius", rfm::VertexEnrichment::inner_disc_ratio * e.cutoff_radius()},
                                     {"degree", e.inner_degree()}};
                // The generalized stress intensities (vertex_intensity.h) over the support
                // (on an arc face the integral takes the arc's own sector and the duals'
                // traction on it).
                if (model->ok())
                  {
                    const std::vector<rfm::VertexIntensity> k = rfm::vertex_intensities(
                      [&](const Eigen::Ref<const Eigen::VectorXd> &r, const Eigen::Ref<const Eigen::VectorXd> &z) {
                        return model->evaluate(r, z);
                      },
                      e, problem, e.cutoff_radius());
                    for (const rfm::VertexIntensity &x : k)
                      fmt::print(stderr, "rfm_solve: vertex ({:.6g}, {:.6g}) m: K = {:.6e}{} Pa m^{:.4g} "
                                         "(lambda = {:.6g})\n",
                                 v.at.r, v.at.z, x.value.real(),
                                 x.value.imag() != 0.0 ? fmt::format(" {:+.6e} i", x.value.imag()) : "",
                                 1.0 - x.lambda.real(), x.lambda.real());
                    enrichment["intensities"] = rfm::to_json(k);
                    enrichment["intensity_units"] = "Pa m^(1 - lambda); K of the notch normalization "
                                                    "sqrt(2 pi) rho^(1 - lambda) sigma_thth(rho, 0) -> K";
                  }
              }
            if (enrichment.is_null())
              {
                bare = bare ? bare : &v;
                ++n_bare;
              }
            list.push_back(std::move(entry));
          }
        result["diagnostics"]["singular_vertices"] = list;
        // A vertex with its columns converges like the rest (the indicator sees it); one
        // without (on a clamped arc, on a die's part, or switched off) does not: say so.
        if (bare)
          vertex_warning = fmt::format(
            "the stress is singular at {} {} of the section without the vertex's columns (on a clamped "
            "arc or a die's part, or rfm.vertex_max_exponent = 0), the first at (r, z) = ({:.6g}, "
            "{:.6g}) m between parts {} and {} (interior angle {:.1f} degrees, lambda = {:.4g}{}): "
            "stresses near it converge slowly and values there are not limits "
            "(diagnostics.singular_vertices lists all)",
            n_bare, n_bare > 1 ? "vertices" : "vertex", bare->at.r, bare->at.z, bare->part_before,
            bare->part_after, bare->angle * 180.0 / 3.14159265358979323846, bare->modes.front().lambda.real(),
            bare->modes.front().lambda.imag() != 0.0 ? fmt::format(" {:+.4g} i", bare->modes.front().lambda.imag())
                                                     : "");
      }
    // Notch roots (wedge_modes.h: notch_roots): the local columns the model placed there.
    if (model)
      {
        nlohmann::json list = nlohmann::json::array();
        for (const axisym::NotchRoot &n : axisym::notch_roots(*problem.body))
          if (const rfm::VertexEnrichment *e = model->vertex_enrichment_at(n.at, 1e-9 * problem.body->outline.size());
              e && e->modes().empty())
            list.push_back({{"r", n.at.r},
                            {"z", n.at.z},
                            {"angle_degrees", n.angle * 180.0 / 3.14159265358979323846},
                            {"arc_radius", n.radius},
                            {"columns", e->n_columns()},
                            {"cutoff_radius", e->cutoff_radius()}});
        if (!list.empty())
          result["diagnostics"]["notch_roots"] = list;
      }
    // Rough vertices (wedge_modes.h: rough_vertices): the bounded non-smooth terms' exponents
    // and the columns the model placed there (none with rfm.rough_vertices false).
    if (model)
      {
        nlohmann::json list = nlohmann::json::array();
        for (const rfm::SingularVertex &v : rfm::rough_vertices(*problem.body, problem.material.poisson_ratio))
          {
            nlohmann::json entry = vertex_entry(v);
            if (const rfm::VertexEnrichment *e = model->vertex_enrichment_at(v.at, 1e-9 * problem.body->outline.size()))
              entry["enrichment"] = {{"columns", e->n_columns()},
                                     {"modes", e->modes().size()},
                                     {"cutoff_radius", e->cutoff_radius()},
                                     {"curved_faces", e->curved()},
                                     {"hoop_shadow", e->hoop_shadow()}};
            list.push_back(std::move(entry));
          }
        if (!list.empty())
          result["diagnostics"]["rough_vertices"] = list;
      }
    // Traction jumps (traction_jump.h, issue 24 item 4): the loaded wedge's stress added to the
    // particular solution at each.
    if (model && !model->traction_jumps().empty())
      {
        nlohmann::json list = nlohmann::json::array();
        for (std::size_t i = 0; i < model->traction_jumps().size(); ++i)
          {
            const rfm::TractionJump &j = model->traction_jumps()[i];
            const double degrees = j.angle() * 180.0 / 3.14159265358979323846;
            const bool section = model->traction_jump_on_section(i);
            const std::string where =
              section ? std::string("on the whole section") : fmt::format("within {:.4g} m", j.cutoff_radius());
            fmt::print(stderr,
                       "rfm_solve: traction jump at ({:.6g}, {:.6g}) m (interior angle {:.1f} degrees): "
                       "the loaded wedge's stress added {}{}\n",
                       j.vertex().r, j.vertex().z, degrees, where, j.has_hoop_shadow() ? ", with its hoop shadow" : "");
            // The hoop shadow (traction_jump.h): the powers of ln rho it takes and the
            // collocation's self-check; null where there is none (on the axis).
            nlohmann::json shadow = nullptr;
            if (j.has_hoop_shadow())
              shadow = {{"log_levels", j.hoop_shadow().levels()}, {"residual", j.hoop_shadow().residual()}};
            list.push_back({{"r", j.vertex().r},
                            {"z", j.vertex().z},
                            {"angle_degrees", degrees},
                            {"cutoff_radius", j.cutoff_radius()},
                            {"support", section ? "section" : "local"},
                            {"hoop_shadow", shadow}});
          }
        result["diagnostics"]["traction_jumps"] = list;
      }
    if (model && !model->resonant_vertices().empty())
      {
        nlohmann::json list = nlohmann::json::array();
        for (const rfm::ResonantVertex &v : model->resonant_vertices())
          {
            fmt::print(stderr,
                       "rfm_solve: resonant vertex at ({:.6g}, {:.6g}) m (a symmetry line meets a traction "
                       "part at a right angle, a temperature gradient crosses the line): {} log stress columns, {} with a "
                       "displacement, within {:.4g} m\n",
                       v.vertex().r, v.vertex().z, v.n_columns(), v.n_displacement_columns(), v.cutoff_radius());
            list.push_back({{"r", v.vertex().r},
                            {"z", v.vertex().z},
                            {"cutoff_radius", v.cutoff_radius()},
                            {"columns", v.n_columns()},
                            {"displacement_columns", v.n_displacement_columns()}});
          }
        result["diagnostics"]["resonant_vertices"] = list;
      }
    if (!solved)
      {
        if (!vertex_warning.empty())
          result["diagnostics"]["message"] =
            result["diagnostics"]["message"].get<std::string>() + "; " + vertex_warning;
        write_failed_result(output_path, result);
        fmt::print(stderr, "rfm_solve: numerical failure: {}\n",
                   result["diagnostics"]["message"].get<std::string>());
        return 3;
      }
    const rfm::Functionals phi = model->functionals();
    result["functionals"] = {{"lagrange", phi.lagrange},
                             {"castigliano", phi.castigliano},
                             {"reissner", phi.reissner},
                             {"indicator", phi.indicator()},
                             {"units", "J per radian"}};
    if (zones.empty() && problem.rfm.ritz_bound)
      add_ritz_bound(*model, phi, result);
    add_constitutive_error(*model, phi, result);
    // Phi_L - Phi_C = E + (the stress's equilibrium defect against u_h's fixed part), E >= 0
    // (OutlineModel::constitutive_error_map). Below zero the defect outweighs E and the
    // indicator, its absolute value, measures no error: it can even meet a tolerance so.
    // (Not with a die: there Phi_C carries the zone's prescribed displacement. Converged
    // solutions cross by rounding: the Lame cylinders by up to 5e-15 of |Phi_R|.)
    if (zones.empty() && phi.castigliano - phi.lagrange > indicator_rounding * std::abs(phi.reissner))
      add_warning(result, "indicator_crossed",
                  fmt::format("Phi_L is below Phi_C by {:.3g} of |Phi_R|: the indicator |Phi_L - Phi_C| / |Phi_R| "
                              "then measures no error (the stress's equilibrium defect against the fixed part of "
                              "u_h, a traction jump's particular displacement, outweighs the constitutive-relation "
                              "error E = {:.3g} of |Phi_R|, diagnostics.constitutive_error); read E instead",
                              (phi.castigliano - phi.lagrange) / std::abs(phi.reissner),
                              result["diagnostics"]["constitutive_error"]["relative"].get<double>()));
    result["samples"] = fields_to_json(problem, *model);
    check_axis_samples(problem, phi, target_indicator, result);
    check_vertex_samples(problem, result);
    check_resonant_amplitudes(*model, result);
    if (!zones.empty())
      check_contact_samples(problem, *model, zones, phi, target_indicator, result);
    if (zones.empty() && sequence && sequence->previous)
      check_tolerance_samples(problem, *sequence->previous, phi, p, *target_indicator, result);
    // A fixed degree is not a failure, but its doubt is said (issue 24 item 6): above 1e-5 the
    // indicator means about 0.3 % in stress (the Lame calibration of rfm.tolerance).
    if (!target_indicator && without_free_ends(problem, zones))
      check_fixed_degree(problem, *model, phi, p, result, zones);
    if (!vertex_warning.empty())
      add_warning(result, "vertex_without_columns", vertex_warning);
    if (!zones.empty())
      {
        result["contact"] = outline_die_to_json(problem, *model, zones[0], phi);
        if (search && problem.contact.method == "edge-intensity")
          {
            result["contact"]["method"] = "edge-intensity";
            nlohmann::json history = nlohmann::json::array();
            for (const rfm::OutlineContactStep &step : search->history)
              history.push_back({{"half_width", step.half_width},
                                 {"zone", step.zone},
                                 {"indentation", step.indentation},
                                 {"edge_intensities", step.edge_intensities},
                                 {"force", step.force},
                                 {"force_trace", step.force_trace},
                                 {"edge_intensity", step.edge_intensity},
                                 {"lagrange", step.lagrange},
                                 {"castigliano", step.castigliano},
                                 {"reissner", step.reissner},
                                 {"phase", step.phase}});
            result["contact"]["iterations"] = history;
            result["contact"]["message"] = search->message;
          }
        if (checked)
          {
            // The method's record as on the hollow cylinder (contact.h's to_json), over the
            // outline die's keys: its iterations with the conditions, its bracket of c.
            const nlohmann::json m = rfm::to_json(*checked, problem, 0);
            for (const char *key : {"method", "message", "iterations", "conditions", "half_width_range"})
              if (m.contains(key))
                result["contact"][key] = m[key];
          }
        if (several)
          {
            // Every die in the same form; `contact` is the first (DESIGN.md 7).
            result["contact"]["method"] = problem.contact.method;
            result["contact"]["message"] = several->message;
            result["dies"] = nlohmann::json::array({result["contact"]});
            for (std::size_t d = 1; d < zones.size(); ++d)
              {
                nlohmann::json die = outline_die_to_json(problem, *model, zones[d], phi);
                die["method"] = problem.contact.method;
                result["dies"].push_back(die);
              }
            nlohmann::json history = nlohmann::json::array();
            for (const rfm::OutlineDiesStep &step : several->history)
              {
                nlohmann::json z = nlohmann::json::array();
                for (std::size_t d = 0; d < step.zones.size(); ++d)
                  z.push_back({{"part", step.zones[d].part},
                               {"zone", {step.zones[d].s_lo, step.zones[d].s_hi}},
                               {"indentation", step.zones[d].indentation},
                               {"force", step.forces[d]}});
                history.push_back({{"dies", z}, {"edge_intensities", step.edge_intensities},
                                   {"phase", step.phase}});
              }
            result["contact"]["iterations"] = history;
            result["dies"][0] = result["contact"];
          }
        else
          result["dies"] = nlohmann::json::array({result["contact"]});
        // An indicator far above the die problems' usual 1e-3: the zone is small against the
        // section and the degree does not resolve it (measured: the rounded flat punch, a zone
        // 1/27 of its face, 14 at p = 8 with P 73 % off the FEM's).
        if (phi.indicator() > 1e-2)
          {
            // Which functional is off says which field is: at the defaults' local boxes the
            // rounded flat punch's Phi_L (the displacements') is 18 % from Phi_R and its
            // Phi_C (the stresses') 0.24 %, with P 1.7e-5 from the FEM's.
            const double off_l = std::abs(phi.lagrange / phi.reissner - 1),
                         off_c = std::abs(phi.castigliano / phi.reissner - 1);
            add_warning(result, "contact_zone_unresolved", fmt::format(
              "the indicator |Phi_L - Phi_C| / |Phi_R| is {:.3g} at p = {} (Phi_L {:.2g} and "
              "Phi_C {:.2g} from Phi_R): the {} near the contact zone is not resolved (a zone "
              "small against the section); raise rfm.degree or rfm.local_degree, or compare "
              "with fem_solve",
              phi.indicator(), problem.rfm.degree, off_l, off_c,
              off_l > 10 * off_c   ? "displacement field (Phi_L)"
              : off_c > 10 * off_l ? "stress field (Phi_C)"
                                   : "field"));
          }
        // A zone that ends inside its part without the edge modes (rfm.edge_modes = 0): the
        // edge's singular field is missing, so P(c) is in doubt.
        const auto free_zone = std::find_if(zones.begin(), zones.end(), [&](const rfm::DieZone &z) {
          return zone_has_free_end(problem, z);
        });
        if (model->n_zone_edges() == 0 && free_zone != zones.end())
          {
            add_warning(result, "zone_edge_without_modes",
                        "the zone ends inside part " + free_zone->part +
                          " and rfm.edge_modes = 0: the edge's singular field is missing and P(c) "
                          "is in doubt (the paper's die at c = 0.45a-0.6a: 0.2-0.7 % off at p = 8-16)");
          }
        for (const nlohmann::json &die : result["dies"])
          fmt::print(stderr, "rfm_solve: die on {}: c = {:.6g} m, P = {:.6g} N (trace {:.6g} N)\n",
                     die["part"].get<std::string>(), die["half_width"].get<double>(),
                     die["force"].get<double>(), die["force_trace"].get<double>());
      }
    if (!output_path.empty())
      axisym::write_json_atomically(output_path, result);
    if (!vtu_directory.empty())
      {
        const axisym::Outline &outline = problem.body->outline;
        const axisym::BoundingBox b = outline.bounding_box();
        rfm::VtuGrid grid;
        grid.r_min = b.r_min, grid.r_max = b.r_max, grid.z_min = b.z_min, grid.z_max = b.z_max;
        const std::string path = vtu_directory + "/rfm_solution.vtu";
        axisym::write_text_atomically(
          path, rfm::fields_vtu(
                  [&](const Eigen::Ref<const Eigen::VectorXd> &r,
                      const Eigen::Ref<const Eigen::VectorXd> &z) { return model->evaluate(r, z); },
                  grid,
                  [&](double r, double z) { return outline.contains({r, z}, 1e-9 * outline.size()); },
                  [&](const Eigen::Ref<const Eigen::VectorXd> &r, const Eigen::Ref<const Eigen::VectorXd> &z,
                      const rfm::FieldValues &f) { return model->constitutive_error_density(r, z, f); }));
        fmt::print(stderr, "rfm_solve: wrote {}\n", path);
      }
    fmt::print(stderr, "rfm_solve: Phi_L = {:.6e}, Phi_C = {:.6e}, Phi_R = {:.6e} J/rad; "
                       "assembly {:.3f} s, solve {:.3f} s\n",
               phi.lagrange, phi.castigliano, phi.reissner, model->assembly_seconds(),
               model->solve_seconds());
    if (output_path.empty())
      std::cout << result.dump(2) << '\n';
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      rfm::keep_freed_matrices_in_heap();
      // 1. Command line.
      CLI::App app{"R-function method with Reissner's mixed principle (axisymmetric elasticity)"};
      std::string problem_path, output_path, vtu_directory;
      int degree = -1;
      double tolerance = -1.0;
      app.add_option("problem", problem_path, "problem file (JSON, SI units)")->required();
      app.add_option("--degree", degree, "polynomial degree p per variable (r^2 and z with the axis parity): N = (p+1)^2; "
                     "along z round(rfm.z_degree_ratio p) where that is given")
        ->check(CLI::Range(axisym::ranges::rfm_degree.lo, axisym::ranges::rfm_degree.hi));
      app.add_option("--tolerance", tolerance,
                     "raise p (2, 4, ...) until |Phi_L - Phi_C| / |Phi_R| < this; without "
                     "--degree, rfm.degree or rfm.tolerance: 1e-8 (a die problem: p = 8)")
        ->check(CLI::Range(axisym::RfmSettings::min_tolerance, 0.1));
      app.add_option("--output", output_path,
                     "write the result JSON to this file (atomically; after a numerical failure "
                     "with the history so far); without it the result JSON goes to stdout");
      bool ritz_bound = false;
      app.add_flag("--ritz-bound", ritz_bound,
                   "also the displacement space's own upper bound of Phi (a Ritz solve after the "
                   "mixed one; rfm.ritz_bound): functionals.lagrange_ritz and indicator_ritz, and "
                   "diagnostics.stress_space_gap (the stress space's best stress for that displacement)");
      app.add_option("--vtu", vtu_directory,
                     "write DIR/rfm_solution.vtu: the fields on a 101 x 201 grid of the section, "
                     "named as in fem_solve's VTU, and the constitutive-relation error density "
                     "constitutive_error [J/m^3] of an outline section (DIR is created when missing)");
      try
        {
          app.parse(argc, argv);
        }
      catch (const CLI::ParseError &e)
        {
          const int status = app.exit(e);
          return status == 0 ? 0 : 2;
        }

      // 2. Input: everything is checked before any work or output.
      axisym::Problem problem = axisym::read_problem_file(problem_path);
      // How p is chosen: --degree, --tolerance, rfm.degree, rfm.tolerance, then the default
      // (a tolerance of 1e-8; p = rfm.degree's default for a die problem).
      if (ritz_bound)
        problem.rfm.ritz_bound = true;
      if (degree >= 0)
        problem.rfm.degree = degree, problem.rfm.degree_given = true;
      else if (tolerance > 0)
        {
          if (problem.die)
            throw axisym::InputError("--tolerance: not for a die problem (the indicator does not "
                                     "see the contact-edge error; give --degree)");
          problem.rfm.tolerance = tolerance, problem.rfm.degree_given = false;
        }
      const bool has_die = problem.die || !problem.body->die_parts().empty();
      if (tolerance > 0 && has_die && !problem.die)
        throw axisym::InputError("--tolerance: not for a die problem (the indicator does not "
                                 "see the contact-edge error; give --degree)");
      std::optional<double> target_indicator;
      if (!problem.rfm.degree_given && !has_die)
        target_indicator = problem.rfm.tolerance.value_or(axisym::RfmSettings::default_tolerance);
      if (target_indicator)
        problem.rfm.degree = problem.rfm.max_degree; // for the memory estimate below
      if (!output_path.empty())
        axisym::check_output_path("--output", output_path);
      if (!vtu_directory.empty())
        axisym::ensure_output_directory("--vtu", vtu_directory);
      problem.rfm.validate(); // the settings with the command line's, before any work
      {
        // Memory: estimated before any allocation, against the machine's physical memory.
        const double bytes = rfm::estimate_memory_bytes(problem, problem.rfm);
        const double available = static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
                                 static_cast<double>(sysconf(_SC_PAGE_SIZE));
        if (bytes > 0.75 * available)
          throw axisym::InputError(fmt::format(
            "rfm.degree = {} (with extra_gauss_points = {}, n_graded_layers = {}, n_cells = {} x {}): "
            "a solve needs about {:.1f} GiB, more than 75 % of this machine's {:.1f} GiB: lower the "
            "degree or the quadrature",
            problem.rfm.degree, problem.rfm.extra_gauss_points, problem.rfm.n_graded_layers,
            problem.rfm.n_cells_r, problem.rfm.n_cells_z, bytes / (1 << 30), available / (1 << 30)));
      }
      if (!problem.legacy_cylinder)
        return solve_outline(problem, target_indicator, output_path, vtu_directory);

      // 3. Solve: one linear solve, a degree sequence to a tolerance, or the contact search
      //    for a die problem.
      std::unique_ptr<rfm::OutlineModel> model_ptr;
      rfm::ContactResult contact;
      nlohmann::json result;
      result["solver"] = "rfm";
      result["problem"] = problem.source;
      std::optional<rfm::DegreeSequence<rfm::OutlineModel>> to_tolerance;
      if (target_indicator)
        {
          fmt::print(stderr, "rfm_solve: p = 2, 4, ... until the indicator < {:.1e} (up to p = {})\n",
                     *target_indicator, problem.rfm.max_degree);
          to_tolerance = rfm::solve_outline_to_tolerance(problem, problem.rfm, *target_indicator);
          model_ptr = std::move(to_tolerance->model);
          problem.rfm.degree = to_tolerance->steps.empty() ? 2 : to_tolerance->steps.back().degree;
          print_sequence(to_tolerance->steps);
        }
      const int p = problem.rfm.degree;
      if (!target_indicator)
        fmt::print(stderr, "rfm_solve: degree p = {}, N = {} per component\n", p,
                   (p + 1) * (problem.rfm.degree_z() + 1));
      if (target_indicator)
        ; // solved above
      else if (problem.die)
        {
          contact = rfm::solve_contact(problem, problem.rfm, rfm::ContactOptions{});
          result["contact"] = rfm::to_json(contact, problem, 101);
          model_ptr = std::move(contact.model);
        }
      else
        model_ptr = std::make_unique<rfm::OutlineModel>(problem, problem.rfm);

      const auto n_basis = static_cast<long>((p + 1) * (problem.rfm.degree_z() + 1));
      const long n_edge = model_ptr ? static_cast<long>(model_ptr->n_edge_columns()) : 0;
      result["discretization"] = {
        {"degree", p},
        {"degree_z", problem.rfm.degree_z()},
        {"N", n_basis},
        {"unknowns", 6 * n_basis + 2 * n_edge},
        {"stress_unknowns", 4 * n_basis + n_edge},
        {"displacement_unknowns", 2 * n_basis + n_edge},
        {"edge_modes", n_edge},
        {"edge_cutoff_radius", n_edge > 0 ? nlohmann::json(model_ptr->zone_edge_enrichment(0).cutoff_radius())
                                          : nlohmann::json(nullptr)},
        {"gauss_points_per_cell", p + problem.rfm.extra_gauss_points},
        {"n_graded_layers", problem.rfm.n_graded_layers},
        {"grading_ratio", problem.rfm.grading_ratio},
        {"section", "upper half z in [0, length/2], symmetry plane z = 0"},
        {"degree_policy", target_indicator ? "tolerance" : "fixed"}};
      if (to_tolerance)
        record_sequence(result["discretization"], *target_indicator, to_tolerance->steps);
      double assembly_s = 0.0, solve_s = 0.0;
      if (problem.die)
        for (const auto &it : contact.history)
          assembly_s += it.assembly_s, solve_s += it.solve_s;
      else if (model_ptr)
        assembly_s = model_ptr->assembly_seconds(), solve_s = model_ptr->solve_seconds();
      result["timing"] = {{"assembly_s", assembly_s}, {"solve_s", solve_s}};

      const bool solved = model_ptr && model_ptr->ok() && (!problem.die || contact.success) &&
                          (!to_tolerance || to_tolerance->reached);
      if (model_ptr)
        {
          const rfm::SolveSummary &s = model_ptr->summary();
          result["discretization"]["quadrature_points"] = model_ptr->n_quadrature_points();
          result["diagnostics"] = {{"status", solved ? "ok" : "failed"},
                                   {"message", problem.die ? contact.message : s.message},
                                   {"rcond_stress_block", s.rcond_stress},
                                   {"rcond_schur_complement", s.rcond_schur},
                                   {"cond_stress_block", s.cond_stress},
                                   {"cond_schur_complement", s.cond_schur},
                                   {"inf_sup_indicator", s.inf_sup}};
        }
      if (!solved)
        {
          const std::string msg = problem.die      ? contact.message
                                  : to_tolerance ? to_tolerance->message
                                                 : model_ptr->summary().message;
          result["diagnostics"]["status"] = "failed";
          result["diagnostics"]["message"] = msg;
          write_failed_result(output_path, result);
          fmt::print(stderr, "rfm_solve: numerical failure: {}\n", msg);
          return 3;
        }
      const rfm::OutlineModel &model = *model_ptr;

      // 4. Post-processing.
      const rfm::Functionals phi = model.functionals();
      result["functionals"] = {{"lagrange", phi.lagrange},
                               {"castigliano", phi.castigliano},
                               {"reissner", phi.reissner},
                               {"indicator", phi.indicator()},
                               {"units", "J per radian"}};
      if (!problem.die && problem.rfm.ritz_bound)
        add_ritz_bound(model, phi, result);
      if (problem.die && problem.contact.curve_points > 0)
        result["contact"]["curve"] = force_curve(problem);
      result["samples"] = fields_to_json(problem, model);
      if (problem.die)
        check_contact_samples(problem, model, model.zones(), phi, target_indicator, result);
      if (!target_indicator && without_free_ends(problem, model.zones()))
        check_fixed_degree(problem, model, phi, p, result, model.zones());
      if (!problem.die && to_tolerance && to_tolerance->previous)
        check_tolerance_samples(problem, *to_tolerance->previous, phi, p, *target_indicator, result);

      const bool finite = std::isfinite(phi.lagrange) && std::isfinite(phi.castigliano) &&
                          std::isfinite(phi.reissner);
      if (!finite)
        {
          result["diagnostics"]["status"] = "failed";
          result["diagnostics"]["message"] = "non-finite functional";
        }
      if (!output_path.empty())
        axisym::write_json_atomically(output_path, result);
      if (!vtu_directory.empty() && finite)
        {
          // The solver's section: the half z in [0, a] (as fem_solve writes it).
          rfm::VtuGrid grid;
          grid.r_min = problem.geometry.inner_radius, grid.r_max = problem.geometry.outer_radius;
          grid.z_min = 0.0, grid.z_max = problem.geometry.half_length();
          const std::string path = vtu_directory + "/rfm_solution.vtu";
          axisym::write_text_atomically(
            path, rfm::fields_vtu([&](const Eigen::Ref<const Eigen::VectorXd> &r,
                                      const Eigen::Ref<const Eigen::VectorXd> &z) { return model.evaluate(r, z); },
                                  grid));
          fmt::print(stderr, "rfm_solve: wrote {}\n", path);
        }
      fmt::print(stderr, "rfm_solve: Phi_L = {:.6e}, Phi_C = {:.6e}, Phi_R = {:.6e} J/rad; "
                         "assembly {:.3f} s, solve {:.3f} s\n",
                 phi.lagrange, phi.castigliano, phi.reissner, assembly_s, solve_s);
      if (problem.die)
        fmt::print(stderr, "rfm_solve: contact ({}): c = {:.6g} m = {:.5f} a, P = {:.6g} N "
                           "(trace {:.6g} N), {} solves: {}\n",
                   problem.contact.method, contact.final.half_width,
                   contact.final.half_width / problem.geometry.half_length(), contact.final.force,
                   contact.final.force_trace, contact.history.size(), contact.message);
      if (!finite)
        {
          fmt::print(stderr, "rfm_solve: numerical failure: non-finite functional\n");
          if (output_path.empty()) // written to --output above
            std::cout << result.dump(2) << '\n';
          return 3;
        }
      if (output_path.empty())
        std::cout << result.dump(2) << '\n';
      return 0;
    }
  catch (const axisym::InputError &e)
    {
      std::cerr << "rfm_solve: error: " << e.what() << '\n';
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "rfm_solve: error: " << e.what() << '\n';
      return 3;
    }
}
