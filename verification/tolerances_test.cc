#include "verification/tolerances.h"

#include "problem/input_error.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace verification
{
  namespace
  {
    std::string write_file(const std::string &name, const std::string &text)
    {
      const std::string path = std::string(TOLERANCE_TEST_DIR) + "/" + name;
      std::ofstream(path) << text;
      return path;
    }
    const nlohmann::json results = {{"cases", {{"paper", {{"p7", {{"err", 3.2e-5}}}}}}}};
  } // namespace

  TEST(Tolerances, PassesWithinLimitsAndFailsWhenTightened)
  {
    const std::string ok = write_file("tol_ok.json", R"({"d": [
      {"quantity": "/cases/paper/p7/err", "max": 1e-4, "why": "issue 3"},
      {"quantity": "/cases/paper/p7/err", "min": 0.0, "why": "non-negative"}]})");
    std::ostringstream out;
    ToleranceReport r = check_tolerances(ok, "d", results, out);
    EXPECT_EQ(r.n_passed, 2);
    EXPECT_EQ(r.n_failed, 0);

    const std::string tight = write_file("tol_tight.json", R"({"d": [
      {"quantity": "/cases/paper/p7/err", "max": 1e-6, "why": "deliberately tightened"}]})");
    std::ostringstream out2;
    r = check_tolerances(tight, "d", results, out2);
    EXPECT_EQ(r.n_failed, 1);
    const std::string msg = out2.str();
    EXPECT_NE(msg.find("FAIL /cases/paper/p7/err"), std::string::npos) << msg;
    EXPECT_NE(msg.find("3.2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("1.0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("deliberately tightened"), std::string::npos) << msg;
  }

  // An entry for the full mode is checked there (and can fail) and skipped in quick mode,
  // where its quantity is not computed; a mode that is neither is an error.
  TEST(Tolerances, FullModeEntriesAreSkippedInQuickMode)
  {
    const std::string file = write_file("tol_mode.json", R"({"d": [
      {"quantity": "/long/err", "max": 1e-3, "why": "full run only", "mode": "full"}]})");
    std::ostringstream out;
    ToleranceReport r = check_tolerances(file, "d", {{"mode", "quick"}}, out);
    EXPECT_EQ(r.n_skipped, 1);
    EXPECT_EQ(r.n_passed + r.n_failed, 0);
    EXPECT_NE(out.str().find("SKIP /long/err"), std::string::npos) << out.str();
    r = check_tolerances(file, "d", {{"mode", "full"}, {"long", {{"err", 2e-3}}}}, out);
    EXPECT_EQ(r.n_failed, 1);
    EXPECT_THROW(check_tolerances(file, "d", {{"mode", "full"}}, out), axisym::InputError);
    const std::string bad = write_file("tol_bad_mode.json", R"({"d": [
      {"quantity": "/long/err", "max": 1e-3, "mode": "fast"}]})");
    EXPECT_THROW(check_tolerances(bad, "d", {{"mode", "full"}}, out), axisym::InputError);
  }

  TEST(Tolerances, MissingQuantityIsAnError)
  {
    const std::string f = write_file("tol_missing.json",
                                     R"({"d": [{"quantity": "/cases/x", "max": 1}]})");
    std::ostringstream out;
    EXPECT_THROW(check_tolerances(f, "d", results, out), std::runtime_error);
  }
} // namespace verification
