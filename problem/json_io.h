// Result files (DESIGN.md section 7) and their atomic writing, for both solvers.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace axisym
{
  /// Writes `j` (2-space indented) to `path` through a temporary file in the same
  /// directory and a rename, so that readers never see a half-written file. Throws
  /// std::runtime_error naming the path when it cannot be written.
  void write_json_atomically(const std::string &path, const nlohmann::json &j);
  /// The same for any text (VTU files).
  void write_text_atomically(const std::string &path, const std::string &text);

  /// Creates the directory `dir` (and its parents) for an option such as --vtu when it is
  /// missing; throws InputError naming the option if it is a file or cannot be created.
  void ensure_output_directory(const std::string &option, const std::string &dir);

  /// Checks before any work that `path` can be written (directory exists and is
  /// writable); throws InputError naming the option and the path.
  void check_output_path(const std::string &option, const std::string &path);
} // namespace axisym
