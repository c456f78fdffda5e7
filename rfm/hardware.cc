#include "rfm/hardware.h"

#include <Eigen/Core>

#include <unistd.h>

#include <fstream>
#include <stdexcept>
#include <string>

namespace rfm
{
  int n_threads() { return Eigen::nbThreads(); }

  void set_n_threads(int n)
  {
    if (n < 1)
      throw std::invalid_argument("thread count: " + std::to_string(n) + " (must be >= 1)");
    Eigen::setNbThreads(n);
  }

  const char *threading_backend() { return "none"; }

  namespace
  {
    long l2_from_sysfs()
    {
      for (int index = 0; index < 8; ++index)
        {
          const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index);
          std::ifstream level_file(dir + "/level"), size_file(dir + "/size");
          int level = 0;
          long size = 0;
          char unit = 0;
          if (!(level_file >> level))
            return 0;
          if (level != 2 || !(size_file >> size))
            continue;
          size_file >> unit;
          return unit == 'M' ? size << 20 : unit == 'K' ? size << 10 : size;
        }
      return 0;
    }
  } // namespace

  long l2_cache_bytes()
  {
    static const long bytes = [] {
#if defined(_SC_LEVEL2_CACHE_SIZE)
      const long s = sysconf(_SC_LEVEL2_CACHE_SIZE);
      if (s > 0)
        return s;
#endif
      const long f = l2_from_sysfs();
      return f > 0 ? f : default_l2_bytes;
    }();
    return bytes;
  }
} // namespace rfm
