#include "rfm/hardware.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace rfm
{
  TEST(Hardware, ThreadCountIsSetAndChecked)
  {
    const int before = n_threads();
    EXPECT_GE(before, 1);
    set_n_threads(2);
    EXPECT_EQ(n_threads(), 2);
    {
      const BlasThreadsOff off;
      EXPECT_EQ(n_threads(), 2); // ours unchanged, only OpenBLAS's
    }
    set_n_threads(before);
    try
      {
        set_n_threads(0);
        FAIL() << "no exception";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("must be >= 1"), std::string::npos);
      }
  }

  TEST(Hardware, L2SizeIsPlausible)
  {
    EXPECT_GE(l2_cache_bytes(), 64 * 1024);
    EXPECT_LE(l2_cache_bytes(), 1L << 30);
  }
} // namespace rfm
