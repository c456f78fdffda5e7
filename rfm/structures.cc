#include "rfm/structures.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rfm
{
  namespace
  {
    bool is_radial(const Side s) { return s == Side::inner || s == Side::outer; }
  } // namespace

  Structures::Structures(const Section &section) : section_(section)
  {
    section_.validate();
    bool fixes_u_z = false;
    for (const auto &p : section_.parts())
      fixes_u_z |= p.condition == Condition::symmetry || p.condition == Condition::displacement;
    if (!fixes_u_z)
      throw std::invalid_argument(
        "Structures: no part fixes u_z (symmetry plane or displacement): the rigid "
        "translation in z would make the system singular");
  }

  template <typename Predicate>
  RValue Structures::omega_of(const double r, const double z, Predicate take) const
  {
    // Adjacent selected parts of one side are merged first: a product of two functions
    // that both vanish on the same line would vanish to second order there and forbid
    // the field a non-zero normal derivative on the side.
    RValue w{1.0, 0.0, 0.0};
    for (const Side side : {Side::inner, Side::outer, Side::bottom, Side::top})
      {
        std::vector<std::pair<double, double>> intervals;
        for (const auto &p : section_.parts())
          if (p.side == side && take(p))
            intervals.emplace_back(p.begin, p.end);
        std::sort(intervals.begin(), intervals.end());
        std::vector<std::pair<double, double>> merged;
        for (const auto &iv : intervals)
          if (!merged.empty() && iv.first <= merged.back().second)
            merged.back().second = std::max(merged.back().second, iv.second);
          else
            merged.push_back(iv);
        for (const auto &iv : merged)
          w = product(w, section_.interval_omega(side, iv.first, iv.second, r, z));
      }
    return w;
  }

  double Structures::side_normal_stress(const Side side) const
  {
    for (const auto &p : section_.parts())
      if (p.side == side && p.condition == Condition::traction)
        return p.normal_stress;
    return 0.0;
  }

  double Structures::side_u_r(const Side side, const double z, double &du_r_dz) const
  {
    // u_r = +u_n on the outer side, -u_n on the inner side.
    const double sign = side == Side::outer ? 1.0 : -1.0;
    du_r_dz = 0.0;
    for (const auto &p : section_.parts())
      if (p.side == side &&
          (p.condition == Condition::displacement || p.condition == Condition::contact) &&
          p.normal_displacement)
        {
          // The prescribed function is used on the whole side; it matters only on the part.
          du_r_dz = sign * p.normal_displacement_derivative(z);
          return sign * p.normal_displacement(z);
        }
    return 0.0;
  }

  StressStructureValues Structures::stress(const Eigen::Ref<const Eigen::VectorXd> &r,
                                           const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    const Eigen::Index n = r.size();
    StressStructureValues v;
    v.omega.resize(n, n_stress_components);
    v.s0.setZero(n, n_stress_components);
    const double r0 = section_.r_min(), r1 = section_.r_max();
    const double z0 = section_.z_min(), z1 = section_.z_max();
    const double s_in = side_normal_stress(Side::inner), s_out = side_normal_stress(Side::outer);
    const double s_bot = side_normal_stress(Side::bottom), s_top = side_normal_stress(Side::top);
    for (Eigen::Index k = 0; k < n; ++k)
      {
        const double rk = r[k], zk = z[k];
        v.omega(k, rr) = omega_of(rk, zk, [](const BoundaryPart &p) {
                           return is_radial(p.side) && p.condition == Condition::traction;
                         }).value;
        v.omega(k, zz) = omega_of(rk, zk, [](const BoundaryPart &p) {
                           return !is_radial(p.side) && p.condition == Condition::traction;
                         }).value;
        v.omega(k, tt) = 1.0;
        v.omega(k, rz) = omega_of(rk, zk, [](const BoundaryPart &p) {
                           return p.condition != Condition::displacement;
                         }).value;
        v.s0(k, rr) = (s_in * (r1 - rk) + s_out * (rk - r0)) / (r1 - r0);
        v.s0(k, zz) = (s_bot * (z1 - zk) + s_top * (zk - z0)) / (z1 - z0);
      }
    return v;
  }

  DisplacementStructureValues
  Structures::displacement(const Eigen::Ref<const Eigen::VectorXd> &r,
                           const Eigen::Ref<const Eigen::VectorXd> &z) const
  {
    const Eigen::Index n = r.size();
    DisplacementStructureValues v;
    v.omega.resize(n, 2);
    v.omega_r.resize(n, 2);
    v.omega_z.resize(n, 2);
    v.u0.setZero(n, 2);
    v.u0_r.setZero(n, 2);
    v.u0_z.setZero(n, 2);
    const double r0 = section_.r_min(), r1 = section_.r_max(), h = r1 - r0;
    for (Eigen::Index k = 0; k < n; ++k)
      {
        const double rk = r[k], zk = z[k];
        const RValue w_r = omega_of(rk, zk, [](const BoundaryPart &p) {
          return p.condition == Condition::displacement || p.condition == Condition::contact;
        });
        const RValue w_z = omega_of(rk, zk, [](const BoundaryPart &p) {
          return p.condition == Condition::displacement || p.condition == Condition::symmetry;
        });
        v.omega(k, 0) = w_r.value, v.omega_r(k, 0) = w_r.d_r, v.omega_z(k, 0) = w_r.d_z;
        v.omega(k, 1) = w_z.value, v.omega_r(k, 1) = w_z.d_r, v.omega_z(k, 1) = w_z.d_z;

        double dg_in = 0.0, dg_out = 0.0;
        const double g_in = side_u_r(Side::inner, zk, dg_in);
        const double g_out = side_u_r(Side::outer, zk, dg_out);
        v.u0(k, 0) = (g_in * (r1 - rk) + g_out * (rk - r0)) / h;
        v.u0_r(k, 0) = (g_out - g_in) / h;
        v.u0_z(k, 0) = (dg_in * (r1 - rk) + dg_out * (rk - r0)) / h;
      }
    return v;
  }
} // namespace rfm
