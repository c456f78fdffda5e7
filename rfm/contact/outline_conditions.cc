// contact.method iterate and max-force on an outline part (outline_contact.h): the hollow
// cylinder's methods (contact_methods.h) on the outline's trial zones.
#include "rfm/contact/outline_contact.h"

#include "rfm/contact/contact_methods.h"
#include "rfm/contact/outline_trials.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rfm
{
  using namespace outline_trials;

  ContactResult solve_outline_contact_by_conditions(const axisym::Problem &problem,
                                                    const DiscretizationOptions &discretization,
                                                    const ContactOptions &options,
                                                    const std::function<void(const ContactIterate &)> &on_step)
  {
    const std::string part = problem.body->die_parts().at(0);
    const axisym::DieFrame f = axisym::die_frame(*problem.body, part);
    const axisym::DieCondition &die = problem.body->conditions.at(part).die;
    const bool up = f.runs_up(), down = f.runs_down();
    const std::string field = "contact.method";
    if (up && down)
      throw axisym::InputError(
        field + " = \"" + problem.contact.method + "\": it searches a zone with one free end, and " +
        "the die on part " + part + " has two (its centre is inside the part, not on the axis or a " +
        "symmetry edge); use \"edge-intensity\" (the default) or \"fixed\"");
    if (die.profile.sharp_edge())
      throw axisym::InputError(field + " = \"" + problem.contact.method +
                               "\": a flat punch with a sharp edge (boundary." + part +
                               ".die.profile.shape = \"flat\") has its face as the zone; use "
                               "\"edge-intensity\" (the default) or \"fixed\"");
    const double extent = up ? f.s_max : -f.s_min;
    ContactResult result;
    result.method = problem.contact.method;
    contact_methods::ZoneTrials trials{
      problem, discretization, options, result, extent,
      [&](const double c) {
        OutlineContactResult r =
          up ? solve_outline_zone(problem, discretization, 0.0, c)
             : solve_outline_zone(problem, discretization, -c, 0.0);
        if (!r.success || !r.model)
          throw std::runtime_error(r.message);
        return std::move(r.model);
      },
      [&](const OutlineModel &model) {
        ContactIterate it;
        const DieZone &zone = model.zones().at(0);
        it.half_width = up ? zone.s_hi : -zone.s_lo;
        const OutlineModel::DieForce force = model.die_force(part);
        it.force = force.domain, it.force_trace = force.trace;
        const Functionals phi = model.functionals();
        it.lagrange = phi.lagrange, it.castigliano = phi.castigliano, it.reissner = phi.reissner;
        it.assembly_s = model.assembly_seconds(), it.solve_s = model.solve_seconds();
        it.edge_intensity = it.edge_intensity_coefficient = nan;
        it.edge_intensity_reciprocal_work = nan;
        if (model.n_zone_edges() > 0)
          {
            it.edge_intensity = model.edge_intensity(0);
            const EdgeEnrichment &e = model.zone_edge_enrichment(0);
            if (e.singular_column() >= 0)
              it.edge_intensity_coefficient =
                std::sqrt(2.0 * M_PI) * model.edge_column_coefficients(0, e.singular_column())[0];
          }
        check_die_conditions(model, *problem.body, it.edge_intensity, options, it);
        return it;
      },
      !die.indentation.has_value(), true, 1e-3 * extent};
    trials.on_step = on_step;
    if (problem.contact.method == "iterate")
      contact_methods::iterate(trials);
    else if (problem.contact.method == "max-force")
      contact_methods::max_force(trials);
    else
      throw std::invalid_argument("solve_outline_contact_by_conditions: contact.method " +
                                  problem.contact.method);
    return result;
  }

} // namespace rfm
