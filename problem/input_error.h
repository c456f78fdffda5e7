// Bad input from a user's file or flag: the message names the field, the value and the
// rule. Drivers map it to exit status 2 (DESIGN.md section 7).
#pragma once

#include <stdexcept>

namespace axisym
{
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace axisym
