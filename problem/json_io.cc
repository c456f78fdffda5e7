#include "problem/json_io.h"

#include "problem/input_error.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace axisym
{
  void write_json_atomically(const std::string &path, const nlohmann::json &j)
  {
    write_text_atomically(path, j.dump(2) + '\n');
  }

  void write_text_atomically(const std::string &path, const std::string &text)
  {
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    {
      std::ofstream out(tmp);
      if (!out)
        throw std::runtime_error("cannot write " + tmp);
      out << text;
      out.flush();
      if (!out)
        {
          std::remove(tmp.c_str());
          throw std::runtime_error("cannot write " + tmp);
        }
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
      {
        std::remove(tmp.c_str());
        throw std::runtime_error("cannot rename " + tmp + " to " + path);
      }
  }

  void ensure_output_directory(const std::string &option, const std::string &dir)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
      throw InputError(option + " = " + dir + ": exists and is not a directory");
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir) || ::access(dir.c_str(), W_OK) != 0)
      throw InputError(option + " = " + dir + ": cannot create a writable directory there" +
                       (ec ? " (" + ec.message() + ")" : std::string()));
  }

  void check_output_path(const std::string &option, const std::string &path)
  {
    namespace fs = std::filesystem;
    const fs::path p(path);
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
      throw InputError(option + " = " + path + ": directory " + dir.string() +
                       " does not exist");
    if (fs::is_directory(p, ec))
      throw InputError(option + " = " + path + ": is a directory, not a file path");
    if (::access(dir.c_str(), W_OK) != 0)
      throw InputError(option + " = " + path + ": directory " + dir.string() +
                       " is not writable");
  }
} // namespace axisym
