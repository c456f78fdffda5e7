#include "benchmarks/dense_reference.h"

#include <fstream>

namespace benchmarks
{
  namespace
  {
    // "48K", "1024K", "32M" -> bytes; 0 when unreadable.
    long sysfs_size(const std::string &dir)
    {
      std::ifstream in(dir + "/size");
      long value = 0;
      char unit = 0;
      if (!(in >> value))
        return 0;
      in >> unit;
      return unit == 'M' ? value << 20 : unit == 'K' ? value << 10 : value;
    }
    std::string sysfs_string(const std::string &file)
    {
      std::ifstream in(file);
      std::string s;
      in >> s;
      return s;
    }
  } // namespace

  std::vector<CacheLevel> host_caches()
  {
    std::vector<CacheLevel> out;
#if defined(_SC_LEVEL1_DCACHE_SIZE)
    const long l1 = sysconf(_SC_LEVEL1_DCACHE_SIZE), l2 = sysconf(_SC_LEVEL2_CACHE_SIZE),
               l3 = sysconf(_SC_LEVEL3_CACHE_SIZE);
    if (l1 > 0)
      out.push_back({"L1d", l1});
    if (l2 > 0)
      out.push_back({"L2", l2});
    if (l3 > 0)
      out.push_back({"L3", l3});
    if (!out.empty())
      return out;
#endif
    for (int index = 0; index < 8; ++index)
      {
        const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index);
        const std::string type = sysfs_string(dir + "/type");
        if (type.empty())
          break;
        if (type == "Instruction")
          continue;
        const long bytes = sysfs_size(dir);
        if (bytes > 0)
          out.push_back({"L" + sysfs_string(dir + "/level") + (type == "Data" ? "d" : ""), bytes});
      }
    return out;
  }
} // namespace benchmarks
