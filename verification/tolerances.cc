#include "verification/tolerances.h"

#include "problem/input_error.h"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace verification
{
  ToleranceReport check_tolerances(const std::string &tolerance_file, const std::string &driver,
                                   const nlohmann::json &results, std::ostream &out)
  {
    std::ifstream in(tolerance_file);
    if (!in)
      throw axisym::InputError("cannot read tolerance file " + tolerance_file);
    const nlohmann::json all = nlohmann::json::parse(in);
    if (!all.contains(driver) || !all.at(driver).is_array())
      throw axisym::InputError(tolerance_file + ": no list of entries for driver '" + driver + "'");

    ToleranceReport report;
    for (const auto &entry : all.at(driver))
      {
        const std::string quantity = entry.at("quantity").get<std::string>();
        const std::string why = entry.value("why", "");
        // An entry for one mode only (the full mode's longer runs) is skipped in the others.
        if (entry.contains("mode"))
          {
            const std::string mode = entry.at("mode").get<std::string>();
            if (mode != "quick" && mode != "full")
              throw axisym::InputError("tolerance entry " + quantity + ": mode '" + mode +
                                       "' is neither quick nor full");
            if (results.value("mode", "") != mode)
              {
                out << fmt::format("SKIP {}: {} mode only\n", quantity, mode);
                ++report.n_skipped;
                continue;
              }
          }
        const nlohmann::json::json_pointer ptr(quantity);
        if (!results.contains(ptr) || !results.at(ptr).is_number())
          throw axisym::InputError("tolerance entry " + quantity + ": no such number in the " +
                                   driver + " results");
        const double measured = results.at(ptr).get<double>();
        const bool is_max = entry.contains("max");
        if (is_max == entry.contains("min"))
          throw axisym::InputError("tolerance entry " + quantity + ": needs exactly one of max, min");
        const double limit = entry.at(is_max ? "max" : "min").get<double>();
        const bool ok = std::isfinite(measured) && (is_max ? measured <= limit : measured >= limit);
        out << fmt::format("{} {}: measured {:.6e}, {} {:.6e}{}\n", ok ? "PASS" : "FAIL", quantity,
                           measured, is_max ? "limit (max)" : "limit (min)", limit,
                           ok ? "" : "  <-- tolerance violated (" + why + ")");
        ++(ok ? report.n_passed : report.n_failed);
      }
    return report;
  }
} // namespace verification
