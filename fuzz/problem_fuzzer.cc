// libFuzzer target for the problem-file parser (problem/problem.h). Any input must either
// parse into a valid Problem or be rejected with axisym::InputError; every other exception,
// crash or sanitizer report is a bug. Build and run: scripts/fuzz.sh [SECONDS].
#include "problem/problem.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstdio>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  // Same path as read_problem_file: JSON errors are bad input.
  nlohmann::json j;
  try
    {
      j = nlohmann::json::parse(data, data + size);
    }
  catch (const nlohmann::json::exception &)
    {
      return 0;
    }
  try
    {
      const axisym::Problem p = axisym::parse_problem(j);
      // A parsed problem is physically valid.
      if (!(p.geometry.outer_radius > p.geometry.inner_radius && p.geometry.inner_radius > 0 &&
            p.material.poisson_ratio < 0.5 && p.material.poisson_ratio > -1))
        std::abort();
      // Both forms give a section outline with a condition on every part.
      if (!p.body || p.body->outline.signed_area() <= 0 ||
          p.body->conditions.size() != p.body->outline.parts().size())
        std::abort();
    }
  catch (const axisym::InputError &)
    {
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "unexpected exception: %s\n", e.what());
      std::abort();
    }
  return 0;
}
