#include "rfm/assembly/assembly.h"

#include "rfm/hardware.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>
#include <vector>

namespace rfm
{
  DisplacementBasisValues displacement_basis(const BasisValues &b,
                                             const DisplacementStructureValues &d)
  {
    DisplacementBasisValues v;
    for (int m = 0; m < 2; ++m)
      {
        v.value[m] = d.omega.col(m).asDiagonal() * b.value;
        v.d_r[m] = d.omega_r.col(m).asDiagonal() * b.value;
        v.d_r[m].noalias() += d.omega.col(m).asDiagonal() * b.d_r;
        v.d_z[m] = d.omega_z.col(m).asDiagonal() * b.value;
        v.d_z[m].noalias() += d.omega.col(m).asDiagonal() * b.d_z;
      }
    return v;
  }

  Eigen::Matrix4d block_compliance(const Eigen::Matrix4d &c, const bool hoop_coupled)
  {
    if (!hoop_coupled)
      return c;
    Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
    t(tt, rr) = 1.0;
    return t.transpose() * c * t;
  }

  // The products with the enrichment columns, on the near-edge rule: the borders of R11 and
  // R12 and the enrichment rows of p_s and p_u (but the traction term). The polynomial and
  // boundary-column blocks are not touched. The polynomial stress column (c, j) is
  // omega_c phi_j e_c and the polynomial strains expand into B, B_r and B_z, so every border
  // is B^T, B_r^T or B_z^T times a pointwise-weighted copy of the n_e enrichment columns.
  void add_enrichment_blocks(const Eigen::Ref<const Eigen::VectorXd> &mu,
                             const Eigen::Ref<const Eigen::VectorXd> &r, const BasisValues &b,
                             const StressStructureValues &s, const DisplacementStructureValues &d,
                             const EdgeColumns &e, const std::array<Eigen::MatrixXd, 4> *boundary,
                             const Eigen::VectorXd *thermal_strain, const Eigen::MatrixXd *body_force,
                             const Eigen::Matrix4d &c, ReissnerSystem &sys,
                             const std::vector<Eigen::Index> *columns)
  {
    const Eigen::Index n = b.value.cols(), n_e = e.stress[0].cols(), n_p = r.size();
    const Eigen::Index n_b = boundary ? (*boundary)[0].cols() : 0;
    const Eigen::Index s_e = 4 * n + n_b, u_e = 2 * n; // the enrichment's first unknowns
    // Where e's columns go among the enrichment's unknowns (all of them, in order, without
    // `columns`).
    std::vector<Eigen::Index> at_s(static_cast<std::size_t>(n_e)), at_u(static_cast<std::size_t>(n_e));
    for (Eigen::Index j = 0; j < n_e; ++j)
      {
        const Eigen::Index col = columns ? (*columns)[static_cast<std::size_t>(j)] : j;
        at_s[static_cast<std::size_t>(j)] = s_e + col;
        at_u[static_cast<std::size_t>(j)] = u_e + col;
      }
    const auto to_s = Eigen::seqN(0, s_e), to_poly = Eigen::seqN(0, n);
    // The columns with displacements and strains (all but the stress-only ones): the products
    // with e.u and e.strain are taken over these n_w alone. On issue 24's stepped ring at
    // p = 12, 2/3 of the vertex columns are stresses alone.
    const std::vector<Eigen::Index> with_u = e.displacement_columns();
    const Eigen::Index n_w = static_cast<Eigen::Index>(with_u.size());
    std::vector<Eigen::Index> at_w(with_u.size());
    Eigen::MatrixXd strain_w[n_stress_components], u_w[2];
    for (std::size_t j = 0; j < with_u.size(); ++j)
      at_w[j] = at_u[static_cast<std::size_t>(with_u[j])];
    for (int k = 0; k < n_stress_components; ++k)
      strain_w[k] = e.strain[k](Eigen::all, with_u);
    for (int m = 0; m < 2; ++m)
      u_w[m] = e.u[m](Eigen::all, with_u);

    // Per component k: weighted enrichment stresses mu X_e,k and mu C X_e (row k).
    Eigen::MatrixXd wx[n_stress_components], cx[n_stress_components];
    for (int k = 0; k < n_stress_components; ++k)
      wx[k] = mu.asDiagonal() * e.stress[k];
    for (int k = 0; k < n_stress_components; ++k)
      {
        cx[k].setZero(n_p, n_e);
        for (int l = 0; l < n_stress_components; ++l)
          if (c(k, l) != 0.0)
            cx[k] += c(k, l) * wx[l];
      }

    // Right factors of B^T: R11 border (4 n_e), R12 row border for u_r and u_z (2 n_e), R12
    // column border (4 n_w); of B_r^T and B_z^T: the R12 row border (2 n_e each).
    const Eigen::Index strains_at = 6 * n_e;
    Eigen::MatrixXd g(n_p, 6 * n_e + 4 * n_w), g_r(n_p, 2 * n_e), g_z(n_p, 2 * n_e);
    for (int k = 0; k < n_stress_components; ++k)
      {
        // With the hoop coupling the rr block's columns carry sigma_tt too.
        const bool both = s.hoop_coupled && k == rr;
        g.middleCols(k * n_e, n_e) = -(s.omega.col(k).asDiagonal() * (both ? Eigen::MatrixXd(cx[rr] + cx[tt]) : cx[k]));
        g.middleCols(strains_at + k * n_w, n_w) =
          (mu.cwiseProduct(s.omega.col(k))).asDiagonal() * (both ? Eigen::MatrixXd(strain_w[rr] + strain_w[tt]) : strain_w[k]);
      }
    const Eigen::VectorXd omega_r_over_r = d.omega.col(0).cwiseQuotient(r);
    g.middleCols(4 * n_e, n_e) = d.omega_r.col(0).asDiagonal() * wx[rr] +
                                 omega_r_over_r.asDiagonal() * wx[tt] +
                                 d.omega_z.col(0).asDiagonal() * wx[rz];
    g.middleCols(5 * n_e, n_e) =
      d.omega_z.col(1).asDiagonal() * wx[zz] + d.omega_r.col(1).asDiagonal() * wx[rz];
    g_r.leftCols(n_e) = d.omega.col(0).asDiagonal() * wx[rr];
    g_r.rightCols(n_e) = d.omega.col(1).asDiagonal() * wx[rz];
    g_z.leftCols(n_e) = d.omega.col(0).asDiagonal() * wx[rz];
    g_z.rightCols(n_e) = d.omega.col(1).asDiagonal() * wx[zz];
    Eigen::MatrixXd bg(n, g.cols()), bg_r(n, 2 * n_e), bg_z(n, 2 * n_e);
    bg.noalias() = b.value.transpose() * g;
    bg_r.noalias() = b.d_r.transpose() * g_r;
    bg_z.noalias() = b.d_z.transpose() * g_z;

    // 1. R11 border: - int X_all . C X_e, mirrored.
    Eigen::MatrixXd corner = Eigen::MatrixXd::Zero(n_e, n_e);
    Eigen::MatrixXd top(s_e, n_e);
    for (int k = 0; k < n_stress_components; ++k)
      {
        top.middleRows(k * n, n) = bg.middleCols(k * n_e, n_e);
        corner.noalias() -= e.stress[k].transpose() * cx[k];
      }
    if (n_b > 0)
      {
        Eigen::MatrixXd border = Eigen::MatrixXd::Zero(n_b, n_e);
        for (int k = 0; k < n_stress_components; ++k)
          border.noalias() -= (*boundary)[k].transpose() * cx[k];
        top.bottomRows(n_b) = border;
      }
    sys.r11(to_s, at_s) += top;
    sys.r11(at_s, to_s) += top.transpose();
    sys.r11(at_s, at_s) += corner;

    // 2. R12 borders: int X_all . e(Phi_e) and int X_e . e(Phi_poly).
    corner.setZero(n_e, n_w);
    for (int k = 0; k < n_stress_components; ++k)
      {
        sys.r12(Eigen::seqN(k * n, n), at_w) += bg.middleCols(strains_at + k * n_w, n_w);
        corner.noalias() += wx[k].transpose() * strain_w[k];
      }
    if (n_b > 0)
      {
        Eigen::MatrixXd border = Eigen::MatrixXd::Zero(n_b, n_w);
        for (int k = 0; k < n_stress_components; ++k)
          border.noalias() += (mu.asDiagonal() * (*boundary)[k]).transpose() * strain_w[k];
        sys.r12(Eigen::seqN(4 * n, n_b), at_w) += border;
      }
    sys.r12(at_s, at_w) += corner;
    sys.r12(at_s, to_poly) +=
      (bg.middleCols(4 * n_e, n_e) + bg_r.leftCols(n_e) + bg_z.leftCols(n_e)).transpose();
    sys.r12(at_s, Eigen::seqN(n, n)) +=
      (bg.middleCols(5 * n_e, n_e) + bg_r.rightCols(n_e) + bg_z.rightCols(n_e)).transpose();

    // 3. p_s rows: int X_e . (e(u0) - C s0 - e_th).
    Eigen::MatrixXd residual = initial_strain_residual(s, d, r, c);
    if (thermal_strain)
      for (const int k : {rr, zz, tt})
        residual.col(k) -= *thermal_strain;
    Eigen::VectorXd rows = Eigen::VectorXd::Zero(n_e);
    for (int k = 0; k < n_stress_components; ++k)
      rows.noalias() += wx[k].transpose() * residual.col(k);
    sys.p_s(at_s) += rows;

    // 4. p_u rows: int s0 . e(Phi_e) - int f . Phi_e (the traction term is the caller's).
    rows.setZero(n_w);
    for (int k = 0; k < n_stress_components; ++k)
      rows.noalias() += strain_w[k].transpose() * mu.cwiseProduct(s.s0.col(k));
    if (body_force)
      for (int m = 0; m < 2; ++m)
        rows.noalias() -= u_w[m].transpose() * mu.cwiseProduct(body_force->col(m));
    sys.p_u(at_w) += rows;
  }

  Eigen::Index assembly_chunk_points(Eigen::Index n_basis_functions, long l2_bytes)
  {
    const Eigen::Index bytes_per_point = 4 * n_basis_functions * static_cast<Eigen::Index>(sizeof(double));
    const Eigen::Index m = (l2_bytes / 2) / std::max<Eigen::Index>(bytes_per_point, 1) / 8 * 8;
    return std::clamp(m, min_chunk_points, max_chunk_points);
  }

  namespace
  {
    // Columns [j0, j1) of the symmetric matrix whose lower triangle is `lower`, written
    // into dst. dst may be `lower` itself (then only its strict upper triangle changes,
    // and it reads nothing it writes), else it is written in full. The transposed reads
    // go tile by tile so that they stay in L1.
    constexpr Eigen::Index mirror_tile = 32;
    void symmetric_columns(Eigen::Block<Eigen::MatrixXd> lower, Eigen::Block<Eigen::MatrixXd> dst,
                           Eigen::Index j0, Eigen::Index j1)
    {
      const bool in_place = dst.data() == lower.data();
      for (Eigen::Index i0 = 0; i0 < j1; i0 += mirror_tile)
        {
          const Eigen::Index i1 = std::min(i0 + mirror_tile, j1);
          for (Eigen::Index j = std::max(j0, i0 + 1); j < j1; ++j)
            for (Eigen::Index i = i0; i < std::min(i1, j); ++i)
              dst(i, j) = lower(j, i);
        }
      if (!in_place)
        for (Eigen::Index j = j0; j < j1; ++j)
          dst.col(j).tail(dst.rows() - j) = lower.col(j).tail(dst.rows() - j);
    }

    // All n_threads threads wait here until all have arrived (once; C++17 has no
    // std::barrier). Spins with yield: the wait is short, the products are balanced.
    class SpinBarrier
    {
    public:
      explicit SpinBarrier(int n_threads)
        : n_threads_(n_threads)
      {}
      void arrive_and_wait()
      {
        arrived_.fetch_add(1, std::memory_order_acq_rel);
        while (arrived_.load(std::memory_order_acquire) < n_threads_)
          std::this_thread::yield();
      }

    private:
      const int n_threads_;
      std::atomic<int> arrived_{0};
    };

    // Column ranges [split[t], split[t + 1]) of an n x n block for the threads, of equal
    // work: equal widths for a full block; for a lower triangle, equal areas (columns
    // [0, c) hold n c - c^2 / 2 entries, so c_t = n (1 - sqrt(1 - t / n_threads))).
    std::vector<Eigen::Index> column_split(Eigen::Index n, int n_threads, bool lower_triangle)
    {
      std::vector<Eigen::Index> split(n_threads + 1);
      for (int t = 0; t <= n_threads; ++t)
        {
          const double f = static_cast<double>(t) / n_threads;
          split[t] = lower_triangle ? n - std::llround(static_cast<double>(n) * std::sqrt(1.0 - f))
                                    : std::llround(static_cast<double>(n) * f);
        }
      return split;
    }

    // One block product of the chunked assembly: the block at (row, col) of R11 (lower
    // triangle; symmetric) or R12 (full) gets B_c^T (diag(w) B_c + diag(w_r) B_r,c +
    // diag(w_z) B_z,c), the w's being columns of the chunk's weight matrix (-1: none).
    struct BlockProduct
    {
      bool symmetric;
      Eigen::Index row, col;
      int w, w_r, w_z;
    };
  } // namespace

  Eigen::MatrixXd initial_strain_residual(const StressStructureValues &s,
                                          const DisplacementStructureValues &d,
                                          const Eigen::Ref<const Eigen::VectorXd> &r,
                                          const Eigen::Matrix4d &c)
  {
    Eigen::MatrixXd e0(r.size(), n_stress_components);
    e0.col(rr) = d.u0_r.col(0);
    e0.col(zz) = d.u0_z.col(1);
    e0.col(tt) = d.u0.col(0).cwiseQuotient(r);
    e0.col(rz) = d.u0_z.col(0) + d.u0_r.col(1);
    return e0 - s.s0 * c.transpose(); // rows: (e0 - C s0)^T
  }

  void add_polynomial_blocks(const Eigen::Ref<const Eigen::VectorXd> &mu,
                             const Eigen::Ref<const Eigen::VectorXd> &r, const BasisValues &b,
                             const StressStructureValues &s, const DisplacementStructureValues &d,
                             const Eigen::Matrix4d &c_stress, ReissnerSystem &sys,
                             Eigen::Index chunk_points, const bool full_r11)
  {
    const Eigen::Matrix4d c = block_compliance(c_stress, s.hoop_coupled);
    const Eigen::Index n = b.value.cols(), n_q = b.value.rows();
    const Eigen::Index chunk =
      chunk_points > 0 ? chunk_points : assembly_chunk_points(n, l2_cache_bytes());

    // 1. The block products and the columns of the pointwise weight matrix they use.
    // R11 block (k, l) = - int C_kl omega_k omega_l B^T B: lower triangle at (l, k), l >= k.
    // R12 blocks: X_c against the strains e_c(Phi_m) (assembly.h), expanded into B, B_r, B_z.
    std::vector<BlockProduct> products;
    std::vector<std::array<int, 3>> r11_weights; // (k, l, column)
    int n_w = 0;
    for (int k = 0; k < n_stress_components; ++k)
      for (int l = k; l < n_stress_components; ++l)
        if (c(k, l) != 0.0)
          {
            r11_weights.push_back({k, l, n_w});
            products.push_back({true, l * n, k * n, n_w++, -1, -1});
          }
    const int w12 = n_w; // 8 columns: the R12 weights, in the order below
    products.push_back({false, rr * n, 0, w12 + 0, w12 + 1, -1}); // rr . du_r/dr
    products.push_back({false, tt * n, 0, w12 + 2, -1, -1});      // tt . u_r / r
    products.push_back({false, rz * n, 0, w12 + 3, -1, w12 + 4}); // rz . du_r/dz
    products.push_back({false, zz * n, n, w12 + 5, -1, w12 + 6}); // zz . du_z/dz
    products.push_back({false, rz * n, n, w12 + 7, w12 + 8, -1}); // rz . du_z/dr
    n_w += 9;

    // 2. Every block product is split by columns between the threads, each taking the
    // same share of work of every product (column_split), so the threads stay balanced
    // whatever the products cost (whole blocks per thread left one thread 30 % longer
    // busy). Thread t's part of a lower triangle is a small triangle on the diagonal and
    // the rectangle below it (one GEMM). Thread 0 also takes p_s and p_u (10 columns).
    // Each entry is summed over the chunks in order by one thread: runs with the same
    // thread count give identical bits.
    const int n_threads = static_cast<int>(std::max<Eigen::Index>(1, std::min<Eigen::Index>(rfm::n_threads(), n / 8)));
    const std::vector<Eigen::Index> full_split = column_split(n, n_threads, false);
    const std::vector<Eigen::Index> lower_split = column_split(n, n_threads, true);

    // 3. Chunks of points: weights, then the thread's block products with the chunk's B
    // in cache.
    Eigen::MatrixXd bv(n, 6), bv_r(n, 2), bv_z(n, 2);
    auto run = [&](int thread) {
      Eigen::MatrixXd w(chunk, n_w), g(chunk, n), v(chunk, 6), v_r(chunk, 2), v_z(chunk, 2);
      for (Eigen::Index start = 0; start < n_q; start += chunk)
        {
          const Eigen::Index m = std::min(chunk, n_q - start);
          const bool first = start == 0;
          const auto mu_c = mu.segment(start, m);
          const auto om = s.omega.middleRows(start, m);
          const auto u = d.omega.middleRows(start, m);
          const auto u_r = d.omega_r.middleRows(start, m);
          const auto u_z = d.omega_z.middleRows(start, m);
          const auto r_c = r.segment(start, m);
          for (const std::array<int, 3> &kl : r11_weights)
            w.col(kl[2]).head(m) =
              -c(kl[0], kl[1]) * mu_c.cwiseProduct(om.col(kl[0])).cwiseProduct(om.col(kl[1]));
          w.col(w12 + 0).head(m) = mu_c.cwiseProduct(om.col(rr)).cwiseProduct(u_r.col(0));
          w.col(w12 + 1).head(m) = mu_c.cwiseProduct(om.col(rr)).cwiseProduct(u.col(0));
          w.col(w12 + 2).head(m) = mu_c.cwiseProduct(om.col(tt)).cwiseProduct(u.col(0)).cwiseQuotient(r_c);
          w.col(w12 + 3).head(m) = mu_c.cwiseProduct(om.col(rz)).cwiseProduct(u_z.col(0));
          w.col(w12 + 4).head(m) = mu_c.cwiseProduct(om.col(rz)).cwiseProduct(u.col(0));
          w.col(w12 + 5).head(m) = mu_c.cwiseProduct(om.col(zz)).cwiseProduct(u_z.col(1));
          w.col(w12 + 6).head(m) = mu_c.cwiseProduct(om.col(zz)).cwiseProduct(u.col(1));
          w.col(w12 + 7).head(m) = mu_c.cwiseProduct(om.col(rz)).cwiseProduct(u_r.col(1));
          w.col(w12 + 8).head(m) = mu_c.cwiseProduct(om.col(rz)).cwiseProduct(u.col(1));
          if (s.hoop_coupled) // the rr block's sigma_tt against u_r / r
            w.col(w12 + 0).head(m) += mu_c.cwiseProduct(om.col(rr)).cwiseProduct(u.col(0)).cwiseQuotient(r_c);

          const auto b_c = b.value.middleRows(start, m);
          const auto b_r = b.d_r.middleRows(start, m);
          const auto b_z = b.d_z.middleRows(start, m);
          for (const BlockProduct &p : products)
            {
              const std::vector<Eigen::Index> &split = p.symmetric ? lower_split : full_split;
              const Eigen::Index c0 = split[thread], c1 = split[thread + 1], width = c1 - c0;
              if (width == 0)
                continue;
              auto g_c = g.topLeftCorner(m, width);
              g_c = w.col(p.w).head(m).asDiagonal() * b_c.middleCols(c0, width);
              if (p.w_r >= 0)
                g_c += w.col(p.w_r).head(m).asDiagonal() * b_r.middleCols(c0, width);
              if (p.w_z >= 0)
                g_c += w.col(p.w_z).head(m).asDiagonal() * b_z.middleCols(c0, width);
              if (p.symmetric)
                {
                  auto diagonal = sys.r11.block(p.row + c0, p.col + c0, width, width);
                  auto below = sys.r11.block(p.row + c1, p.col + c0, n - c1, width);
                  const auto b_diagonal = b_c.middleCols(c0, width);
                  const auto b_below = b_c.rightCols(n - c1);
                  if (first)
                    {
                      diagonal.triangularView<Eigen::Lower>() = b_diagonal.transpose() * g_c;
                      if (c1 < n)
                        below.noalias() = b_below.transpose() * g_c;
                    }
                  else
                    {
                      diagonal.triangularView<Eigen::Lower>() += b_diagonal.transpose() * g_c;
                      if (c1 < n)
                        below.noalias() += b_below.transpose() * g_c;
                    }
                }
              else
                {
                  auto block = sys.r12.block(p.row, p.col + c0, n, width);
                  if (first)
                    block.noalias() = b_c.transpose() * g_c;
                  else
                    block.noalias() += b_c.transpose() * g_c;
                }
            }
          if (thread != 0)
            continue;

          // p_s = int X . (e(u0) - C s0) and p_u = int s0 . e(Phi), with e(Phi) expanded
          // as in the R12 products (the traction term is added by the caller).
          const Eigen::MatrixXd residual = initial_strain_residual(
            StressStructureValues{Eigen::MatrixXd(), s.s0.middleRows(start, m)},
            DisplacementStructureValues{Eigen::MatrixXd(), Eigen::MatrixXd(), Eigen::MatrixXd(),
                                        d.u0.middleRows(start, m), d.u0_r.middleRows(start, m),
                                        d.u0_z.middleRows(start, m)},
            r_c, c_stress);
          for (int k = 0; k < n_stress_components; ++k)
            v.col(k).head(m) = mu_c.cwiseProduct(om.col(k)).cwiseProduct(residual.col(k));
          if (s.hoop_coupled)
            v.col(rr).head(m) += mu_c.cwiseProduct(om.col(rr)).cwiseProduct(residual.col(tt));
          const auto s0 = s.s0.middleRows(start, m);
          const Eigen::VectorXd m_rr = mu_c.cwiseProduct(s0.col(rr));
          const Eigen::VectorXd m_zz = mu_c.cwiseProduct(s0.col(zz));
          const Eigen::VectorXd m_tt = mu_c.cwiseProduct(s0.col(tt)).cwiseQuotient(r_c);
          const Eigen::VectorXd m_rz = mu_c.cwiseProduct(s0.col(rz));
          v.col(4).head(m) = u_r.col(0).cwiseProduct(m_rr) + u.col(0).cwiseProduct(m_tt) +
                             u_z.col(0).cwiseProduct(m_rz);
          v.col(5).head(m) = u_z.col(1).cwiseProduct(m_zz) + u_r.col(1).cwiseProduct(m_rz);
          v_r.col(0).head(m) = u.col(0).cwiseProduct(m_rr);
          v_r.col(1).head(m) = u.col(1).cwiseProduct(m_rz);
          v_z.col(0).head(m) = u.col(0).cwiseProduct(m_rz);
          v_z.col(1).head(m) = u.col(1).cwiseProduct(m_zz);
          if (first)
            {
              bv.noalias() = b_c.transpose() * v.topRows(m);
              bv_r.noalias() = b_r.transpose() * v_r.topRows(m);
              bv_z.noalias() = b_z.transpose() * v_z.topRows(m);
            }
          else
            {
              bv.noalias() += b_c.transpose() * v.topRows(m);
              bv_r.noalias() += b_r.transpose() * v_r.topRows(m);
              bv_z.noalias() += b_z.transpose() * v_z.topRows(m);
            }
        }
    };
    // 4. R11: mirror each symmetric block below the diagonal (its product gave its lower
    // triangle), zero the blocks with C_kl = 0; with full_r11 also the diagonal blocks, and
    // copy the off-diagonal ones to their transposed place (a symmetric block is its own
    // transpose; memory-bound: no faster on two threads than on one); R12:
    // u_r does no work on sigma_zz, u_z none on sigma_rr and sigma_tt. Column tiles are
    // dealt out to the threads in turn (each writes only its own columns), after all
    // products are done, on the same threads: on two freshly started threads this pass
    // took 0.41 ms at Lame p = 14, on one thread 0.28 ms.
    auto mirror = [&](int thread) {
      for (Eigen::Index j0 = thread * mirror_tile; j0 < n; j0 += n_threads * mirror_tile)
        {
          const Eigen::Index j1 = std::min(j0 + mirror_tile, n);
          for (int k = 0; k < n_stress_components; ++k)
            for (int l = k; l < n_stress_components; ++l)
              {
                auto lower = sys.r11.block(l * n, k * n, n, n);
                auto upper = sys.r11.block(k * n, l * n, n, n);
                if (c(k, l) == 0.0)
                  {
                    lower.middleCols(j0, j1 - j0).setZero();
                    if (full_r11)
                      upper.middleCols(j0, j1 - j0).setZero();
                    continue;
                  }
                // Each block is computed as its lower triangle: the blocks below the
                // diagonal need their upper halves in any case.
                if (full_r11 || l != k)
                  symmetric_columns(lower, lower, j0, j1);
                if (full_r11 && l != k)
                  symmetric_columns(lower, upper, j0, j1);
              }
          sys.r12.block(zz * n, j0, n, j1 - j0).setZero();
          sys.r12.block(rr * n, n + j0, n, j1 - j0).setZero();
          sys.r12.block(tt * n, n + j0, n, j1 - j0).setZero();
        }
    };
    SpinBarrier products_done(n_threads);
    const BlasThreadsOff one_blas_thread; // the parallelism is ours here (nested)
    run_on_threads(n_threads, [&](int thread) {
      std::exception_ptr error; // still arrive at the barrier, then rethrow
      try
        {
          run(thread);
        }
      catch (...)
        {
          error = std::current_exception();
        }
      products_done.arrive_and_wait();
      if (error)
        std::rethrow_exception(error);
      mirror(thread);
    });
    for (int k = 0; k < n_stress_components; ++k)
      sys.p_s.segment(k * n, n) = bv.col(k);
    sys.p_u.segment(0, n) = bv.col(4) + bv_r.col(0) + bv_z.col(0);
    sys.p_u.segment(n, n) = bv.col(5) + bv_r.col(1) + bv_z.col(1);
  }
} // namespace rfm
