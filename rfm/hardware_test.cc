#include "rfm/hardware.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

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

  // All parts run at the same time (each waits for all three at a barrier, which would
  // hang if the pool ran them one after the other), on distinct threads, call after call.
  TEST(Hardware, RunOnThreadsRunsThePartsSideBySide)
  {
    for (int call = 0; call < 20; ++call)
      {
        std::atomic<int> arrived{0};
        std::vector<std::thread::id> ids(3);
        std::vector<int> ran(3, 0);
        run_on_threads(3, [&](int t) {
          ran[t] += 1;
          ids[t] = std::this_thread::get_id();
          arrived.fetch_add(1);
          while (arrived.load() < 3)
            std::this_thread::yield();
        });
        EXPECT_EQ(ran, std::vector<int>({1, 1, 1})) << call;
        EXPECT_EQ(ids[0], std::this_thread::get_id()); // part 0 on the caller
        EXPECT_NE(ids[1], ids[0]);
        EXPECT_NE(ids[2], ids[1]);
        EXPECT_NE(ids[2], ids[0]);
      }
  }

  TEST(Hardware, RunOnThreadsRethrowsAndStaysUsable)
  {
    EXPECT_THROW(run_on_threads(2, [](int t) {
                   if (t == 1)
                     throw std::runtime_error("part 1");
                 }),
                 std::runtime_error);
    // A nested call (the pool is busy) gets threads of its own.
    std::atomic<int> inner{0};
    run_on_threads(2, [&](int t) {
      if (t == 0)
        run_on_threads(2, [&](int) { inner.fetch_add(1); });
    });
    EXPECT_EQ(inner.load(), 2);
    std::atomic<int> after{0};
    run_on_threads(2, [&](int) { after.fetch_add(1); });
    EXPECT_EQ(after.load(), 2);
  }
} // namespace rfm
