// Tolerance gates of the verification suite. verification/tolerances.json holds, per
// driver, a list of entries
//   {"quantity": "/json/pointer/into/the/driver/results", "max" | "min": limit,
//    "why": "where the limit comes from", "mode": "full" (optional: checked in that mode
//    only; the driver's results name their mode)}
// and check_tolerances() compares the driver's results against every entry of its own
// driver, printing one line per entry and a readable failure naming the quantity, the
// measured value and the limit.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace verification
{
  struct ToleranceReport
  {
    int n_passed = 0, n_failed = 0, n_skipped = 0;
  };

  /// Checks every entry listed under `driver` in the tolerance file; writes a line per
  /// entry to `out`. Throws std::runtime_error if the file or an entry is malformed, or
  /// if a quantity is missing from the results (a missing number never passes).
  ToleranceReport check_tolerances(const std::string &tolerance_file, const std::string &driver,
                                   const nlohmann::json &results, std::ostream &out);
} // namespace verification
