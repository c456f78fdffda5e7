// From a problem file to a solved RFM model: the section of DESIGN.md section 4 with its
// boundary parts, the discrete space, assembly, solve, and the derived quantities.
//
// The body and every load of the problem file are symmetric about z = 0, so the solver
// works on the upper half z in [0, a] (a = length/2) with a symmetry plane at z = 0
// (u_z = 0, sigma_rz = 0): this removes the rigid translation in z and spends every
// coordinate function on the symmetric part of the solution. Reported energies and
// forces are for the whole body; fields at z < 0 follow by mirroring.
#pragma once

#include "rfm/assembly.h"
#include "rfm/degree_sequence.h"
#include "problem/problem.h"
#include "rfm/saddle_point_solver.h"
#include "rfm/solution.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rfm
{
  /// Half section with its parts: inner and top traction (pressure, free end), bottom
  /// symmetry, outer traction or, with a die, contact on z in [0, c] and traction beyond.
  /// Precondition: problem validated; 0 < half_width <= a when the problem has a die.
  Section build_section(const axisym::Problem &problem, std::optional<double> half_width);

  /// Peak memory of one solve [bytes], estimated before any allocation: quadrature
  /// points times basis size for the ~14 dense point-by-function matrices of assembly,
  /// plus the saddle-point matrices (R11, R12, their factors and the Schur complement).
  double estimate_memory_bytes(const axisym::Problem &problem, const DiscretizationOptions &options,
                               std::optional<double> half_width);

  struct ContactForce
  {
    double domain = 0.0; ///< P = -2 pi int s . e(v) r dr dz, v = ((r - R1)/(R2 - R1), 0) [N]
    double trace = 0.0;  ///< P = -2 pi R2 int_{-a}^{a} sigma_rr(R2, z) dz (eq. 4.6) [N]
  };

  /// A solved model. Keeps the discrete space alive for post-processing.
  class RfmModel
  {
  public:
    RfmModel(const axisym::Problem &problem, const DiscretizationOptions &options,
             std::optional<double> half_width, const SolverOptions &solver_options = {});

    const SolveSummary &summary() const { return summary_; }
    bool ok() const { return summary_.success; }
    const RfmSolution &solution() const { return *solution_; } ///< precondition: ok()
    const DiscreteSpace &space() const { return *space_; }
    std::optional<double> half_width() const { return half_width_; }
    double assembly_seconds() const { return assembly_s_; }
    double solve_seconds() const { return solve_s_; }

    /// Fields at points anywhere in the full section (z < 0 by mirroring).
    FieldValues evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                         const Eigen::Ref<const Eigen::VectorXd> &z) const;
    ContactForce contact_force() const;
    /// Edge intensity K = sqrt(2 pi) a_1 [Pa m^1/2] from the coefficient a_1 of the n = 1
    /// stress column at the contact edge (edge_modes.h: K < 0 zone too short, K > 0 too
    /// long); NaN without that column. Precondition: ok().
    double edge_intensity() const;

  private:
    std::optional<double> half_width_;
    std::unique_ptr<DiscreteSpace> space_;
    SolveSummary summary_;
    std::unique_ptr<RfmSolution> solution_;
    double assembly_s_ = 0.0, solve_s_ = 0.0;
  };

  using ToleranceSolve = DegreeSequence<RfmModel>;

  /// rfm.tolerance: solves at p = 2, 4, 6, ... up to options.max_degree until the indicator
  /// falls below `tolerance`. Not reached (reached = false, with the reason) when max_degree
  /// is passed, when the indicator has not decreased over two steps (its rounding floor), or
  /// when a solve fails. Precondition: a problem without a die.
  ToleranceSolve solve_to_tolerance(const axisym::Problem &problem,
                                    const DiscretizationOptions &options, double tolerance);
} // namespace rfm
