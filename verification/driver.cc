#include "verification/driver.h"

#include "problem/input_error.h"
#include "problem/json_io.h"
#include "rfm/allocator.h"
#include "rfm/hardware.h"
#include "verification/tolerances.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <filesystem>
#include <iostream>

namespace verification
{
  std::string DriverContext::problem_path(const std::string &file) const
  {
    return source_dir + "/verification/problems/" + file;
  }

  int run_driver(int argc, char **argv, const std::string &name, const std::string &description,
                 const std::function<nlohmann::json(const DriverContext &)> &body)
  {
    try
      {
        rfm::keep_freed_matrices_in_heap();
        // 1. Options.
        CLI::App app{description};
        DriverContext context;
        context.output_dir = "verification-output";
        context.source_dir = RFM_SOURCE_DIR;
        std::string tolerances;
        app.add_option("--mode", context.mode, "quick (CI) or full (report)")
          ->check(CLI::IsMember({"quick", "full"}));
        app.add_option("--output-dir", context.output_dir,
                       "where " + name + ".json is written (created if missing)");
        app.add_option("--source-dir", context.source_dir, "project source (problem files)");
        app.add_option("--tolerances", tolerances, "tolerance file to check (default: none)")
          ->check(CLI::ExistingFile);
        try
          {
            app.parse(argc, argv);
          }
        catch (const CLI::ParseError &e)
          {
            return app.exit(e) == 0 ? 0 : 2;
          }
        std::filesystem::create_directories(context.output_dir);

        // 2. The driver's own work.
        nlohmann::json results = body(context);
        // The thread count of the RFM's dense kernels and assembly (rfm/hardware.h): the
        // report states it beside the wall times.
        results["threads"] = rfm::n_threads();

        // 3. Write, then gate.
        const std::string out_file = context.output_dir + "/" + name + ".json";
        axisym::write_json_atomically(out_file, results);
        fmt::print("\nwrote {}\n", out_file);
        if (tolerances.empty())
          return 0;
        const ToleranceReport report = check_tolerances(tolerances, name, results, std::cout);
        fmt::print("{} passed, {} failed, {} skipped (another mode)\n", report.n_passed,
                   report.n_failed, report.n_skipped);
        return report.n_failed == 0 ? 0 : 1;
      }
    catch (const axisym::InputError &e)
      {
        std::cerr << name << ": bad input: " << e.what() << '\n';
        return 2;
      }
    catch (const std::exception &e)
      {
        std::cerr << name << ": numerical failure: " << e.what() << '\n';
        return 3;
      }
  }
} // namespace verification
