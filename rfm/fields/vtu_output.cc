#include "rfm/fields/vtu_output.h"

#include <fmt/core.h>

#include <stdexcept>
#include <vector>

namespace rfm
{
  std::string fields_vtu(const FieldEvaluator &evaluate, const VtuGrid &grid,
                         const std::function<bool(double, double)> &inside,
                         const DensityEvaluator &constitutive_error)
  {
    if (grid.n_r < 2 || grid.n_z < 2 || !(grid.r_max > grid.r_min) || !(grid.z_max > grid.z_min))
      throw std::invalid_argument("fields_vtu: need at least 2 x 2 points on a non-empty box");
    const Eigen::Index n = static_cast<Eigen::Index>(grid.n_r) * grid.n_z;
    Eigen::VectorXd r(n), z(n);
    for (int j = 0; j < grid.n_z; ++j)
      for (int i = 0; i < grid.n_r; ++i)
        {
          const Eigen::Index k = static_cast<Eigen::Index>(j) * grid.n_r + i;
          r[k] = grid.r_min + (grid.r_max - grid.r_min) * i / (grid.n_r - 1);
          z[k] = grid.z_min + (grid.z_max - grid.z_min) * j / (grid.n_z - 1);
        }
    // The points inside (all without `inside`), their fields, and the cells kept.
    std::vector<char> in(n, 1);
    if (inside)
      for (Eigen::Index k = 0; k < n; ++k)
        in[k] = inside(r[k], z[k]);
    std::vector<Eigen::Index> index;
    for (Eigen::Index k = 0; k < n; ++k)
      if (in[k])
        index.push_back(k);
    Eigen::VectorXd ri(index.size()), zi(index.size());
    for (std::size_t k = 0; k < index.size(); ++k)
      ri[k] = r[index[k]], zi[k] = z[index[k]];
    const FieldValues fi = evaluate(ri, zi);
    FieldValues f;
    f.u.setZero(n, 2);
    f.sigma.setZero(n, n_stress_components);
    for (std::size_t k = 0; k < index.size(); ++k)
      f.u.row(index[k]) = fi.u.row(k), f.sigma.row(index[k]) = fi.sigma.row(k);
    Eigen::VectorXd error;
    if (constitutive_error)
      {
        const Eigen::VectorXd ei = constitutive_error(ri, zi, fi);
        error.setZero(n);
        for (std::size_t k = 0; k < index.size(); ++k)
          error[index[k]] = ei[static_cast<Eigen::Index>(k)];
      }
    std::vector<long> cells;
    for (int j = 0; j + 1 < grid.n_z; ++j)
      for (int i = 0; i + 1 < grid.n_r; ++i)
        {
          const long k = static_cast<long>(j) * grid.n_r + i;
          if (in[k] && in[k + 1] && in[k + 1 + grid.n_r] && in[k + grid.n_r])
            cells.push_back(k);
        }
    const long n_cells = static_cast<long>(cells.size());

    std::string out;
    out += "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "<UnstructuredGrid>\n";
    out += fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, n_cells);
    out += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (Eigen::Index k = 0; k < n; ++k)
      out += fmt::format("{:.17g} {:.17g} 0\n", r[k], z[k]);
    out += "</DataArray>\n</Points>\n<Cells>\n"
           "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const long k : cells)
      out += fmt::format("{} {} {} {}\n", k, k + 1, k + 1 + grid.n_r, k + grid.n_r);
    out += "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (long c = 1; c <= n_cells; ++c)
      out += fmt::format("{}\n", 4 * c);
    out += "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (long c = 0; c < n_cells; ++c)
      out += "9\n"; // VTK_QUAD
    out += "</DataArray>\n</Cells>\n<PointData Scalars=\"sigma_rr\" Vectors=\"displacement\">\n";
    auto scalar = [&](const char *name, auto value) {
      out += fmt::format("<DataArray type=\"Float64\" Name=\"{}\" format=\"ascii\">\n", name);
      for (Eigen::Index k = 0; k < n; ++k)
        out += fmt::format("{:.17g}\n", value(k));
      out += "</DataArray>\n";
    };
    scalar("u_r", [&](Eigen::Index k) { return f.u(k, 0); });
    scalar("u_z", [&](Eigen::Index k) { return f.u(k, 1); });
    scalar("sigma_rr", [&](Eigen::Index k) { return f.sigma(k, rr); });
    scalar("sigma_zz", [&](Eigen::Index k) { return f.sigma(k, zz); });
    scalar("sigma_tt", [&](Eigen::Index k) { return f.sigma(k, tt); });
    scalar("sigma_rz", [&](Eigen::Index k) { return f.sigma(k, rz); });
    if (constitutive_error)
      scalar("constitutive_error", [&](Eigen::Index k) { return error[k]; });
    out += "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n";
    for (Eigen::Index k = 0; k < n; ++k)
      out += fmt::format("{:.17g} {:.17g} 0\n", f.u(k, 0), f.u(k, 1));
    out += "</DataArray>\n</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    return out;
  }
} // namespace rfm
