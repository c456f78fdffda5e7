#include "verification/tolerances.h"

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

  TEST(Tolerances, MissingQuantityIsAnError)
  {
    const std::string f = write_file("tol_missing.json",
                                     R"({"d": [{"quantity": "/cases/x", "max": 1}]})");
    std::ostringstream out;
    EXPECT_THROW(check_tolerances(f, "d", results, out), std::runtime_error);
  }
} // namespace verification
