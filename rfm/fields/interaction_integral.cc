#include "rfm/fields/interaction_integral.h"

#include <cmath>
#include <utility>

namespace rfm
{
  Quadrature2D interaction_quadrature(const EdgeFrame &frame, const double rho_1)
  {
    // The rule about (0, 0) in the legacy orientation (r = -y, z = -x), placed in the frame.
    Quadrature2D q = half_disc_gauss(0.0, 0.0, rho_1, 16, 24);
    for (Eigen::Index k = 0; k < q.weights.size(); ++k)
      {
        const auto p = frame.point(-q.z[k], -q.r[k]);
        q.r[k] = p[0], q.z[k] = p[1];
      }
    return q;
  }

  double edge_intensity_interaction(const FieldEvaluator &field, const EdgeFrame &frame,
                                    const Material &m, const double rho_1,
                                    const std::function<double(double)> &contact_u,
                                    const double free_pressure)
  {
    // The weight interaction_weight (measured at p = 8: the root of K sits +0.08 % from the
    // FEM's c with it, +0.21 % with q = 1 - t, +0.34 % with (1 - t)^2).
    auto weight = [rho_1](double rho) { return interaction_weight(rho, rho_1); };
    const double n_out_r = -frame.n[0], n_out_z = -frame.n[1]; // the part's outward normal

    // 1. The normalization C: the plane-strain contour integral of mode 1 against mode -1,
    //    int_0^pi (s1 e_rho . u* - s* e_rho . u1) rho dtheta (independent of rho; at rho = 1).
    const GaussRule1D gt = gauss_on_cells({0.0, 0.5 * M_PI, M_PI}, 16);
    double norm = 0.0;
    for (Eigen::Index k = 0; k < gt.nodes.size(); ++k)
      {
        const double t = gt.nodes[k];
        const auto x = frame.point(std::cos(t), std::sin(t));
        const double n_r = x[0] - frame.r, n_z = x[1] - frame.z; // e_rho
        const EdgeModeValue v = edge_mode(1, x[0], x[1], frame, m),
                            a = edge_mode(-1, x[0], x[1], frame, m);
        norm += gt.weights[k] *
                ((v.sigma[rr] * n_r + v.sigma[rz] * n_z) * a.u_r +
                 (v.sigma[rz] * n_r + v.sigma[zz] * n_z) * a.u_z -
                 (a.sigma[rr] * n_r + a.sigma[rz] * n_z) * v.u_r -
                 (a.sigma[rz] * n_r + a.sigma[zz] * n_z) * v.u_z);
      }

    // 2. The domain part, -int_A (q div W + W . grad q) dr dz on the half disc rho < rho_1,
    //    W = r (s_h u* - s* u~), u~ = u_h - u_bar: u_bar's normal component the prescribed
    //    one at the edge, its tangential one the field's there.
    const Quadrature2D qd = interaction_quadrature(frame, rho_1);
    const FieldValues f = field(qd.r, qd.z);
    const FieldValues fe =
      field(Eigen::VectorXd::Constant(1, frame.r), Eigen::VectorXd::Constant(1, frame.z));
    const double u_t = fe.u(0, 0) * frame.t[0] + fe.u(0, 1) * frame.t[1];
    const double u_bar_r = contact_u(0.0) * n_out_r + u_t * frame.t[0];
    const double u_bar_z = contact_u(0.0) * n_out_z + u_t * frame.t[1];
    double domain = 0.0;
    for (Eigen::Index k = 0; k < qd.weights.size(); ++k)
      {
        const double r = qd.r[k], z = qd.z[k];
        const double rho = std::hypot(r - frame.r, z - frame.z);
        const double e_r = (r - frame.r) / rho, e_z = (z - frame.z) / rho;
        const EdgeModeValue a = edge_mode(-1, r, z, frame, m);
        const double u_r = f.u(k, 0), ut_r = u_r - u_bar_r, ut_z = f.u(k, 1) - u_bar_z;
        const double w_r = r * (f.sigma(k, rr) * a.u_r + f.sigma(k, rz) * a.u_z -
                                a.sigma[rr] * ut_r - a.sigma[rz] * ut_z);
        const double w_z = r * (f.sigma(k, rz) * a.u_r + f.sigma(k, zz) * a.u_z -
                                a.sigma[rz] * ut_r - a.sigma[zz] * ut_z);
        const double div_w = f.sigma(k, tt) * a.u_r + a.sigma[tt] * u_r - a.sigma[rr] * ut_r -
                             a.sigma[rz] * ut_z;
        const auto [q, dq] = weight(rho);
        domain -= qd.weights[k] * (q * div_w + (w_r * e_r + w_z * e_z) * dq);
      }

    // 3. The faces on the part's line (outward normal n_out), x in (0, rho_1) from the edge:
    //    on the contact face W . n_out = -r s*_nn u~_n with u~_n prescribed; on the free face
    //    W . n_out = -r p u*_n.
    const GaussRule1D gx = gauss_on_cells({0.0, rho_1}, 24, {0.0});
    double faces = 0.0;
    for (Eigen::Index k = 0; k < gx.nodes.size(); ++k)
      {
        const double x = gx.nodes[k], q = weight(x).first;
        const auto pin = frame.point(x, 0.0);
        const EdgeModeValue in = edge_mode(-1, pin[0], pin[1], frame, m);
        const double s_nn = in.sigma[rr] * n_out_r * n_out_r + 2 * in.sigma[rz] * n_out_r * n_out_z +
                            in.sigma[zz] * n_out_z * n_out_z;
        faces -= gx.weights[k] * q * pin[0] * s_nn * (contact_u(x) - contact_u(0.0));
        if (free_pressure != 0.0)
          {
            const auto pout = frame.point(-x, 0.0);
            const EdgeModeValue out = edge_mode(-1, pout[0], pout[1], frame, m);
            faces -= gx.weights[k] * q * pout[0] * free_pressure *
                     (out.u_r * n_out_r + out.u_z * n_out_z);
          }
      }
    return std::sqrt(2.0 * M_PI) * (faces + domain) / (frame.r * norm);
  }
} // namespace rfm
