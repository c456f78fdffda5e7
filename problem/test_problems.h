// Test support shared by the unit tests of problem/, rfm/ and fem_reference/ (header only,
// never linked into a solver): the thick sphere of DESIGN.md 7.1 and its 60-degree sector as
// problem files, and a
// command-line runner for the solvers' CLI tests.
#pragma once

#include "problem/outline.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace axisym::testing
{
  /// One outline edge built directly (no parsing): the line from a to b, and the arc from a
  /// to b about c.
  inline OutlineEdge line(const Point a, const Point b, const char *part = "")
  {
    OutlineEdge e;
    e.kind = OutlineEdge::Kind::line;
    e.start = a, e.end = b;
    e.part = part;
    return e;
  }
  inline OutlineEdge arc(const Point a, const Point b, const Point c)
  {
    OutlineEdge e = line(a, b);
    e.kind = OutlineEdge::Kind::arc;
    e.center = c;
    return e;
  }

  /// The thick spherical shell a = 0.1 m, b = 0.2 m of DESIGN.md 7.1: a quarter annulus with
  /// the equator (symmetry) and the axis, inner pressure 10 MPa, steel. Tests add samples,
  /// solver settings or other conditions to it.
  inline nlohmann::json thick_sphere()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.1, 0.0]},
        {"line_to": [0.2, 0.0], "part": "equator"},
        {"arc_to": [0.0, 0.2], "center": [0.0, 0.0], "part": "outer"},
        {"line_to": [0.0, 0.1], "part": "axis"},
        {"arc_to": [0.1, 0.0], "center": [0.0, 0.0], "part": "inner"}]},
      "boundary": {"equator": {"symmetry": true}, "inner": {"pressure": 1.0e7}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
  }

  // A ring section with a rectangular step inward (the L-shaped section of issue 24): one
  // free-free vertex of 270 degrees at (0.15, 0.1), pressure inside, symmetry at z = 0.
  inline nlohmann::json stepped_ring()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.1, 0.0]}, {"line_to": [0.2, 0.0], "part": "bottom"},
        {"line_to": [0.2, 0.2], "part": "outer"}, {"line_to": [0.15, 0.2], "part": "top"},
        {"line_to": [0.15, 0.1], "part": "step_side"}, {"line_to": [0.1, 0.1], "part": "step"},
        {"line_to": [0.1, 0.0], "part": "inner"}]},
      "boundary": {"inner": {"pressure": 1.0e7}, "bottom": {"symmetry": true}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
  }

  // A ring section whose bore carries a pressure on its lower half only (issue 24 item 4): the
  // traction jumps at (0.5, 0.25), where the loaded and the free half of the bore meet (a
  // straight angle). Symmetry at z = 0.
  inline nlohmann::json pressure_band()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.5, 0.0]}, {"line_to": [1.0, 0.0], "part": "mid"},
        {"line_to": [1.0, 0.5], "part": "outer"}, {"line_to": [0.5, 0.5], "part": "top"},
        {"line_to": [0.5, 0.25], "part": "bore_free"}, {"line_to": [0.5, 0.0], "part": "bore_loaded"}]},
      "boundary": {"mid": {"symmetry": true}, "bore_loaded": {"pressure": 1.0e7}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
  }

  // Issue 24's tapered hub: a pressure on the inner arc ends at the straight bore (133.4
  // degrees, a traction jump on an arc), a re-entrant vertex where the taper meets the neck,
  // and a 186-degree vertex on the outer arc; symmetry on mid and top.
  inline nlohmann::json tapered_hub()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [{"start": [0.8, 0.0]}, {"line_to": [1.2, 0.0], "part": "mid"},
        {"arc_to": [1.0875693444439798, 0.5071419140888394], "center": [0.0, 0.0], "part": "outer_arc"},
        {"line_to": [0.85, 1.2], "part": "taper"}, {"line_to": [0.85, 1.6], "part": "neck"},
        {"line_to": [0.55, 1.6], "part": "top"}, {"line_to": [0.55, 0.5809475019311126], "part": "bore"},
        {"arc_to": [0.8, 0.0], "center": [0.0, 0.0], "part": "inner_arc"}]},
      "boundary": {"mid": {"symmetry": true}, "top": {"symmetry": true}, "inner_arc": {"pressure": 1.0e7}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
  }

  /// The ring [0.8, 1.2] x [0, 0.4] m on its symmetry plane z = 0 under T = 100 z K, steel
  /// (verification/problems/heated_ring_axial_gradient.json without its samples): two
  /// resonant vertices, (0.8, 0) and (1.2, 0). Parts: mid, outer, top, bore.
  inline nlohmann::json heated_ring_axial_gradient()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [{"start": [0.8, 0.0]}, {"line_to": [1.2, 0.0], "part": "mid"},
        {"line_to": [1.2, 0.4], "part": "outer"}, {"line_to": [0.8, 0.4], "part": "top"},
        {"line_to": [0.8, 0.0], "part": "bore"}]},
      "boundary": {"mid": {"symmetry": true}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3, "thermal_expansion": 1.2e-5},
      "loading": {"temperature": {"field": [0.0, 0.0, 100.0]}}})");
  }

  /// A solid shaft, radius 0.05 m, half-length 0.15 m (mid-plane symmetry), with a
  /// quarter-circle groove of radius 0.01 m at the mid-plane meeting the surface at 90
  /// degrees (a sharp lip), pulled by 10 MPa on its end (verification/problems/
  /// grooved_shaft_tension.json). Parts: mid_plane, groove, surface, end, axis.
  inline nlohmann::json grooved_shaft()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [{"start": [0.0, 0.0]}, {"line_to": [0.04, 0.0], "part": "mid_plane"},
        {"arc_to": [0.05, 0.01], "center": [0.05, 0.0], "part": "groove"},
        {"line_to": [0.05, 0.15], "part": "surface"}, {"line_to": [0.0, 0.15], "part": "end"},
        {"line_to": [0.0, 0.0], "part": "axis"}]},
      "boundary": {"mid_plane": {"symmetry": true}, "end": {"traction": [0.0, 1.0e7]}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
  }

  /// The sector 0 <= polar angle from the equator <= 60 degrees of the same shell: the cone
  /// phi = 60 degrees is an inclined symmetry edge (u.n = 0 with n = (-sin 60, cos 60)),
  /// which a spherically symmetric solution satisfies; inner pressure 10 MPa, steel.
  inline nlohmann::json thick_sphere_sector()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.1, 0.0]},
        {"line_to": [0.2, 0.0], "part": "equator"},
        {"arc_to": [0.1, 0.17320508075688773], "center": [0.0, 0.0], "part": "outer"},
        {"line_to": [0.05, 0.08660254037844387], "part": "cone"},
        {"arc_to": [0.1, 0.0], "center": [0.0, 0.0], "part": "inner"}]},
      "boundary": {"equator": {"symmetry": true}, "cone": {"symmetry": true},
                   "inner": {"pressure": 1.0e7}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
  }

  /// A solid steel cylinder, radius 0.02 m and height 0.02 m, on a frictionless support
  /// (symmetry on the bottom z = 0), pressed on its top face by a rigid paraboloid of radius
  /// 0.1 m with 2 kN (the Hertz case; a = (3 P R / 4 E*)^(1/3) = 0.87 mm). Parts: bottom,
  /// side, top, axis.
  inline nlohmann::json punched_cylinder()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.0, 0.0]},
        {"line_to": [0.02, 0.0], "part": "bottom"},
        {"line_to": [0.02, 0.02], "part": "side"},
        {"line_to": [0.0, 0.02], "part": "top"},
        {"line_to": [0.0, 0.0], "part": "axis"}]},
      "boundary": {"bottom": {"symmetry": true},
                   "top": {"die": {"force": 2000.0,
                                   "profile": {"shape": "paraboloid", "radius": 0.1}}}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3}})");
  }

  /// The paper's die (DESIGN.md 4) written as an outline: the half section z >= 0 of the
  /// hollow cylinder (not mirrored), the die on part `outer` centred on the mid-plane, the
  /// paraboloid R = a^2 / (4 delta) = 10 km of the paper's u_r* at delta = 1 um, p = 8.
  inline nlohmann::json paper_die_outline()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [{"start": [0.1, 0.0]}, {"line_to": [0.2, 0.0], "part": "mid_plane"},
        {"line_to": [0.2, 0.2], "part": "outer"}, {"line_to": [0.1, 0.2], "part": "end"},
        {"line_to": [0.1, 0.0], "part": "inner"}]},
      "boundary": {"mid_plane": {"symmetry": true},
                   "outer": {"die": {"indentation": 1e-6,
                                     "profile": {"shape": "paraboloid", "radius": 10000.0}}}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
      "rfm": {"degree": 8}})");
  }

  /// A solid steel cylinder (radius 20 mm, length 40 mm, no symmetry plane) pressed at both
  /// end faces by paraboloids R = 0.1 m, each by 0.25 mm: zones of about 5.3 mm (fem_solve at
  /// its defaults, Q2: 5.28441 mm and P = 456347 N each; its half model with a symmetry plane
  /// 5.28509 mm). verification/problems/cylinder_between_two_dies.json.
  inline nlohmann::json cylinder_between_two_dies()
  {
    return nlohmann::json::parse(R"({
      "geometry": {"outline": [
        {"start": [0.0, -0.02]},
        {"line_to": [0.02, -0.02], "part": "bottom"},
        {"line_to": [0.02, 0.02], "part": "side"},
        {"line_to": [0.0, 0.02], "part": "top"},
        {"line_to": [0.0, -0.02], "part": "axis"}]},
      "boundary": {"top": {"die": {"indentation": 2.5e-4,
                                   "profile": {"shape": "paraboloid", "radius": 0.1}}},
                   "bottom": {"die": {"indentation": 2.5e-4,
                                      "profile": {"shape": "paraboloid", "radius": 0.1}}}},
      "material": {"youngs_modulus": 2.1e11, "poisson_ratio": 0.3},
      "rfm": {"degree": 8}})");
  }

  struct CommandOutcome
  {
    int status;      ///< exit status (-1 if the command did not exit normally)
    std::string err; ///< what it wrote on stderr (stdout is discarded)
  };

  /// Runs a shell command line and collects its exit status and stderr.
  inline CommandOutcome run_command(const std::string &command)
  {
    const std::string cmd = command + " 2>&1 >/dev/null";
    std::unique_ptr<FILE, int (*)(FILE *)> pipe(popen(cmd.c_str(), "r"), pclose);
    std::string out;
    std::array<char, 512> buf{};
    while (fgets(buf.data(), buf.size(), pipe.get()))
      out += buf.data();
    const int raw = pclose(pipe.release());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
  }

  /// A fresh, empty scratch directory `prefix name _ pid` under the system's temporary
  /// directory (the pid keeps concurrent test processes apart).
  inline std::filesystem::path scratch_directory(const std::string &prefix, const std::string &name)
  {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      (prefix + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
  }
} // namespace axisym::testing
