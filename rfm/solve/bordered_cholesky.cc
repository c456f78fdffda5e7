#include "rfm/solve/bordered_cholesky.h"

#include "rfm/hardware.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread> // yield
#include <vector>

namespace rfm
{
  namespace
  {
    using Eigen::Index;
    using Status = BorderedCholesky::Status;

    struct Task
    {
      enum Kind
      {
        load,
        after_first_block,
        potrf,
        trsm,
        update,
        scale
      } kind;
      int i, j, k; // tile (i, j); k: the column applied (update), else j (load: column j)
    };

    class TiledFactorization
    {
    public:
      TiledFactorization(Eigen::Ref<Eigen::MatrixXd> a, const Index n1, const Index tile,
                         const BorderedCholeskyJobs &jobs)
        : a_(a)
        , jobs_(jobs)
      {
        // Tile boundaries at multiples of 8 (the kernels' widths), the blocks apart.
        auto cut = [&](const Index lo, const Index hi) {
          const Index n = hi - lo, count = std::max<Index>(1, (n + tile - 1) / tile);
          for (Index q = 0; q < count; ++q)
            {
              const Index at = std::min(hi, lo + (n * q / count + 7) / 8 * 8);
              if (q == 0 || (at > offsets_.back() && at < hi)) // no empty tile
                offsets_.push_back(q == 0 ? lo : at);
            }
        };
        cut(0, n1);
        n1_tiles_ = static_cast<int>(offsets_.size());
        if (a.rows() > n1)
          cut(n1, a.rows());
        offsets_.push_back(a.rows());
        nt_ = static_cast<int>(offsets_.size()) - 1;
        applied_.assign(nt_ * nt_, 0);
        final_.assign(nt_ * nt_, 0);
        scaled_.assign(nt_ * nt_, 0);
        e_.setConstant(a.rows() - n1, std::numeric_limits<double>::quiet_NaN());
        column_sums_.resize(nt_ * nt_);
        row_sums_.resize(nt_ * nt_);
        loaded_.assign(nt_, 0);
        m_columns_.resize(nt_);
        m_rows_.resize(nt_);
        for (int k = 0; k < n1_tiles_; ++k)
          first_block_tiles_ += nt_ - k;

        for (int j = 0; j < nt_; ++j)
          tasks_.push_back({Task::load, j, j, j});

        // The sequential order, which is also the priority: column k's factorization,
        // then its updates with the next column first (the look-ahead), and the scaling
        // of the trailing block before its first column.
        for (int k = 0; k < nt_; ++k)
          {
            if (k == n1_tiles_)
              {
                for (int i = n1_tiles_; i < nt_; ++i)
                  tasks_.push_back({Task::scale, i, i, i});
                for (int j = n1_tiles_; j < nt_; ++j)
                  for (int i = j + 1; i < nt_; ++i)
                    tasks_.push_back({Task::scale, i, j, j});
              }
            tasks_.push_back({Task::potrf, k, k, k});
            for (int i = k + 1; i < nt_; ++i)
              tasks_.push_back({Task::trsm, i, k, k});
            for (int j = k + 1; j < nt_; ++j)
              for (int i = j; i < nt_; ++i)
                tasks_.push_back({Task::update, i, j, k});
          }
        // Last in priority: a worker takes it when no tile task is ready.
        if (jobs_.after_first_block)
          tasks_.push_back({Task::after_first_block, 0, 0, 0});
        started_.assign(tasks_.size(), 0);
      }

      void run(const int n_threads)
      {
        run_on_threads(n_threads, [&](int) {
          try
            {
              work();
            }
          catch (...)
            {
              {
                const std::lock_guard<std::mutex> lock(mutex_);
                stop_ = true;
              }
              progress_.fetch_add(1, std::memory_order_release);
              throw;
            }
        });
      }

      BorderedCholesky result() const
      {
        BorderedCholesky out;
        out.status = status_;
        out.e = e_;
        out.m_l1_norm = m_l1_norm();
        if (status_ != Status::ok || e_.size() == 0)
          return out;
        // |E K E|_1 from the per-tile sums, added in a fixed order.
        Eigen::VectorXd sums = Eigen::VectorXd::Zero(e_.size());
        const Index n1 = offsets_[n1_tiles_];
        for (int i = n1_tiles_; i < nt_; ++i)
          for (int j = n1_tiles_; j <= i; ++j)
            {
              sums.segment(offsets_[j] - n1, column_sums_[at(i, j)].size()) +=
                column_sums_[at(i, j)];
              sums.segment(offsets_[i] - n1, row_sums_[at(i, j)].size()) += row_sums_[at(i, j)];
            }
        out.k_l1_norm = sums.maxCoeff();
        return out;
      }

    private:
      int at(int i, int j) const { return i * nt_ + j; }
      Index size(int i) const { return offsets_[i + 1] - offsets_[i]; }
      Eigen::Block<Eigen::Ref<Eigen::MatrixXd>> tile(int i, int j)
      {
        return a_.block(offsets_[i], offsets_[j], size(i), size(j));
      }
      bool trailing(int j) const { return j >= n1_tiles_; }

      // A tile of the trailing block needs every first-block column (k < n1_tiles_), then
      // its scaling, before the trailing block's own columns.
      bool ready(const Task &t) const
      {
        auto updated = [&](int i, int j, int k) {
          return applied_[at(i, j)] == k && (!trailing(j) || k < n1_tiles_ || scaled_[at(i, j)]);
        };
        switch (t.kind)
          {
            case Task::load:
              return true;
            case Task::after_first_block:
              return n_first_block_final_ == first_block_tiles_;
            case Task::potrf: // the trailing block's first pivot after all its scales
              return loaded_[t.k] && updated(t.k, t.k, t.k) &&
                     (!trailing(t.k) || n_diagonal_scaled_ == nt_ - n1_tiles_);
            case Task::trsm:
              return loaded_[t.k] && final_[at(t.k, t.k)] && updated(t.i, t.k, t.k);
            case Task::update:
              return loaded_[t.j] && final_[at(t.i, t.k)] && final_[at(t.j, t.k)] &&
                     updated(t.i, t.j, t.k);
            case Task::scale:
              return applied_[at(t.i, t.j)] == n1_tiles_ &&
                     (t.i == t.j || (scaled_[at(t.i, t.i)] && scaled_[at(t.j, t.j)]));
          }
        return false;
      }

      // Runs one task outside the lock; a status other than ok stops the factorization.
      Status execute(const Task &t)
      {
        switch (t.kind)
          {
            case Task::load:
              {
                const Index c0 = offsets_[t.j], w = size(t.j), n1 = offsets_[n1_tiles_];
                if (trailing(t.j))
                  {
                    a_.block(c0, c0, a_.rows() - c0, w).triangularView<Eigen::Lower>().setZero();
                    return Status::ok;
                  }
                jobs_.load(c0, c0 + w);
                // This column block's share of |M|_1: its columns, and the mirrored rows
                // below its diagonal tile.
                const auto m = a_.block(c0, c0, n1 - c0, w);
                Eigen::VectorXd columns = m.bottomRows(n1 - c0 - w).cwiseAbs().colwise().sum().transpose();
                Eigen::VectorXd rows = Eigen::VectorXd::Zero(n1 - c0);
                rows.tail(n1 - c0 - w) = m.bottomRows(n1 - c0 - w).cwiseAbs().rowwise().sum();
                const auto d = m.topRows(w);
                for (Index c = 0; c < w; ++c)
                  {
                    columns[c] += d.col(c).tail(w - c).cwiseAbs().sum();
                    rows.segment(c + 1, w - c - 1) += d.col(c).tail(w - c - 1).cwiseAbs();
                  }
                m_columns_[t.j] = std::move(columns);
                m_rows_[t.j] = std::move(rows);
                return Status::ok;
              }
            case Task::after_first_block:
              jobs_.after_first_block(m_l1_norm());
              return Status::ok;
            case Task::potrf:
              {
                auto d = tile(t.k, t.k);
                const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(d);
                if (llt.info() != Eigen::Success)
                  return trailing(t.k) ? Status::schur_not_positive
                                       : Status::stress_block_not_positive;
                return Status::ok;
              }
            case Task::trsm:
              {
                auto b = tile(t.i, t.k);
                tile(t.k, t.k)
                  .triangularView<Eigen::Lower>()
                  .transpose()
                  .solveInPlace<Eigen::OnTheRight>(b);
                return Status::ok;
              }
            case Task::update:
              {
                // K accumulates +L21 L21^T; everything else is Cholesky's -L L^T.
                const double sign = trailing(t.j) && !trailing(t.k) ? 1.0 : -1.0;
                auto c = tile(t.i, t.j);
                if (t.i == t.j)
                  c.selfadjointView<Eigen::Lower>().rankUpdate(tile(t.i, t.k), sign);
                else
                  c.noalias() += sign * (tile(t.i, t.k) * tile(t.j, t.k).transpose());
                return Status::ok;
              }
            case Task::scale:
              {
                const Index n1 = offsets_[n1_tiles_];
                auto c = tile(t.i, t.j);
                if (t.i == t.j)
                  {
                    const Eigen::VectorXd diagonal = c.diagonal();
                    if (!(diagonal.minCoeff() > 0.0))
                      return Status::zero_schur_column;
                    e_.segment(offsets_[t.i] - n1, size(t.i)) =
                      diagonal.cwiseSqrt().cwiseInverse();
                  }
                const auto ei = e_.segment(offsets_[t.i] - n1, size(t.i));
                const auto ej = e_.segment(offsets_[t.j] - n1, size(t.j));
                if (t.i == t.j) // the strict upper triangle stays untouched
                  c.triangularView<Eigen::Lower>() = ei.asDiagonal() * c * ej.asDiagonal();
                else
                  c = ei.asDiagonal() * c * ej.asDiagonal();
                // Column sums of |E K E| from this lower tile: its own columns, and the
                // mirrored rows (strictly lower part only on the diagonal).
                if (t.i == t.j)
                  {
                    const Eigen::MatrixXd lower = c.triangularView<Eigen::Lower>().toDenseMatrix();
                    column_sums_[at(t.i, t.j)] = lower.cwiseAbs().colwise().sum().transpose();
                    row_sums_[at(t.i, t.j)] =
                      c.triangularView<Eigen::StrictlyLower>().toDenseMatrix().cwiseAbs().rowwise().sum();
                  }
                else
                  {
                    column_sums_[at(t.i, t.j)] = c.cwiseAbs().colwise().sum().transpose();
                    row_sums_[at(t.i, t.j)] = c.cwiseAbs().rowwise().sum();
                  }
                return Status::ok;
              }
          }
        return Status::ok;
      }

      void work()
      {
        std::unique_lock<std::mutex> lock(mutex_);
        while (true)
          {
            if (stop_ || n_done_ == tasks_.size())
              return;
            std::size_t pick = tasks_.size();
            for (std::size_t q = first_open_; q < tasks_.size(); ++q)
              if (!started_[q] && ready(tasks_[q]))
                {
                  pick = q;
                  break;
                }
            if (pick == tasks_.size())
              {
                // Nothing ready: wait for the next completion. A task takes 10 us to a few
                // ms; spinning (with yield) wakes within a microsecond, a condition
                // variable's wake-up took tens (measured 1.6 % of the Lame p = 14 solve).
                const std::size_t seen = progress_.load(std::memory_order_acquire);
                lock.unlock();
                while (progress_.load(std::memory_order_acquire) == seen)
                  std::this_thread::yield();
                lock.lock();
                continue;
              }
            started_[pick] = 1;
            while (first_open_ < tasks_.size() && started_[first_open_])
              ++first_open_;
            lock.unlock();
            const Task &t = tasks_[pick];
            const Status status = execute(t);
            lock.lock();
            if (status != Status::ok)
              {
                // Any failure stops the factorization. A failure in M stops it before any
                // trailing task, and every K_jj is checked before a trailing pivot, so
                // the status is the same on every thread count.
                if (status_ == Status::ok || status < status_)
                  status_ = status;
                stop_ = true;
              }
            switch (t.kind)
              {
                case Task::load:
                  loaded_[t.j] = 1;
                  break;
                case Task::after_first_block:
                  break;
                case Task::potrf:
                case Task::trsm:
                  final_[at(t.i, t.j)] = 1;
                  n_first_block_final_ += !trailing(t.j);
                  break;
                case Task::update:
                  applied_[at(t.i, t.j)] = t.k + 1;
                  break;
                case Task::scale:
                  scaled_[at(t.i, t.j)] = 1;
                  n_diagonal_scaled_ += t.i == t.j;
                  break;
              }
            ++n_done_;
            progress_.fetch_add(1, std::memory_order_release);
          }
      }

      // |M|_1 from the load tasks' sums, added in a fixed order.
      double m_l1_norm() const
      {
        const Index n1 = offsets_[n1_tiles_];
        Eigen::VectorXd sums = Eigen::VectorXd::Zero(n1);
        for (int j = 0; j < n1_tiles_; ++j)
          if (!loaded_[j]) // stopped before this load
            return std::numeric_limits<double>::quiet_NaN();
        for (int j = 0; j < n1_tiles_; ++j)
          {
            sums.segment(offsets_[j], size(j)) += m_columns_[j];
            sums.tail(n1 - offsets_[j]) += m_rows_[j];
          }
        return n1 > 0 ? sums.maxCoeff() : 0.0;
      }

      Eigen::Ref<Eigen::MatrixXd> a_;
      const BorderedCholeskyJobs &jobs_;
      std::vector<char> loaded_;
      std::vector<Eigen::VectorXd> m_columns_, m_rows_;
      int first_block_tiles_ = 0, n_first_block_final_ = 0;
      // Every diagonal scale has checked its K_jj before a trailing pivot can fail: a zero
      // column is then reported as such on every thread count.
      int n_diagonal_scaled_ = 0;
      std::vector<Index> offsets_;
      int n1_tiles_ = 0, nt_ = 0;
      std::vector<Task> tasks_;
      std::vector<char> started_, final_, scaled_;
      std::vector<int> applied_; // first-block and trailing updates applied to tile (i, j)
      Eigen::VectorXd e_;
      std::vector<Eigen::VectorXd> column_sums_, row_sums_;
      std::mutex mutex_;
      std::atomic<std::size_t> progress_{0}; // completions (and stops), for the waiters
      std::size_t first_open_ = 0, n_done_ = 0;
      bool stop_ = false;
      Status status_ = Status::ok;
    };
  } // namespace

  BorderedCholesky factorize_bordered(Eigen::Ref<Eigen::MatrixXd> a, const Eigen::Index n1,
                                      const int n_threads, const BorderedCholeskyJobs &jobs,
                                      const Eigen::Index tile)
  {
    eigen_assert(a.rows() == a.cols() && n1 >= 1 && n1 <= a.rows() && n_threads >= 1 &&
                 tile >= 8 && jobs.load);
    // The parallelism is ours: each task is one single-threaded call.
    const BlasThreadsOff one_blas_thread;
    TiledFactorization f(a, n1, tile, jobs);
    f.run(n_threads);
    return f.result();
  }

  BorderedCholesky factorize_bordered(Eigen::Ref<Eigen::MatrixXd> a, const Eigen::Index n1,
                                      const int n_threads, const Eigen::Index tile)
  {
    BorderedCholeskyJobs jobs;
    jobs.load = [](Eigen::Index, Eigen::Index) {}; // already in place
    return factorize_bordered(a, n1, n_threads, jobs, tile);
  }
} // namespace rfm
