// The one main of every verification driver (DESIGN.md section 8): the options, the
// driver's body, the atomic write of OUTPUT_DIR/NAME.json and the tolerance gate.
//
// Options: --mode quick|full, --output-dir DIR (created if missing), --source-dir DIR (the
// project source: problem files), --tolerances FILE (gate; default none).
// Exit status: 0 success; 1 a tolerance violated (the results are written first); 2 bad input
// (an option, or a problem file: axisym::InputError); 3 numerical failure (NumericalFailure,
// or any other exception from the solvers): a message, and nothing written.
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <stdexcept>
#include <string>

namespace verification
{
  /// A solve that failed numerically inside a driver (singular system, contact not
  /// converging): exit status 3.
  class NumericalFailure : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  struct DriverContext
  {
    std::string mode = "quick"; ///< "quick" (CI) or "full" (report)
    std::string output_dir;
    std::string source_dir;

    bool full() const { return mode == "full"; }
    /// source_dir/verification/problems/FILE
    std::string problem_path(const std::string &file) const;
  };

  /// Parses the options, runs `body`, writes its result to OUTPUT_DIR/NAME.json and gates it
  /// against the tolerance file's section NAME. Returns the exit status.
  int run_driver(int argc, char **argv, const std::string &name, const std::string &description,
                 const std::function<nlohmann::json(const DriverContext &)> &body);
} // namespace verification
