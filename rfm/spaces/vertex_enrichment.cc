#include "rfm/spaces/vertex_enrichment.h"

#include "rfm/spaces/basis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <stdexcept>

namespace rfm
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /// The local stress columns' polynomials of total degree <= d (OutlineModel: up to 24) at
    /// a point: L_a(u') L_b(w'), Legendre polynomials in the offsets along and across the
    /// bisector over rho_0, u = rho cos theta and w = rho sin theta, mapped so that the body's
    /// part of the disc, rho <= rho_0 and |theta| <= alpha, spans [-1, 1] in both:
    /// u in [min(cos alpha, 0), 1], |w| <= 1 (sin alpha for alpha < pi / 2). The span is that of
    /// the monomials xi^a eta^b of the offsets, but the monomials lose their independence with
    /// the degree, most on a disc the body fills only half of (a 186-degree vertex): on issue
    /// 24's heated hub at p = 16 with rfm.vertex_local_degree_ratio 1 (degree 16) the
    /// orthonormalization dropped 777 directions with the monomials, 565 with these, and the
    /// indicator was 3.1e-7 against 1.0e-7.
    class WedgeLegendre
    {
    public:
      WedgeLegendre(const int degree, const double beta, const double alpha)
        : pu_(degree + 1), pw_(degree + 1), dp_(degree + 1), c_(std::cos(beta)), s_(std::sin(beta)),
          u_min_(alpha > 0.5 * pi ? std::cos(alpha) : 0.0), w_max_(alpha >= 0.5 * pi ? 1.0 : std::sin(alpha))
      {}
      /// At the offsets (dr, dz) from the vertex, over the disc's radius rho_0.
      void at(const double dr, const double dz, const double rho_0)
      {
        const double u = (dr * c_ + dz * s_) / rho_0, w = (dz * c_ - dr * s_) / rho_0;
        const int d = static_cast<int>(pu_.size()) - 1;
        legendre_values(d, 2.0 * (u - u_min_) / (1.0 - u_min_) - 1.0, pu_, dp_);
        legendre_values(d, w / w_max_, pw_, dp_);
      }
      double operator()(const int a, const int b) const { return pu_[a] * pw_[b]; }

    private:
      Eigen::VectorXd pu_, pw_, dp_;
      double c_, s_, u_min_, w_max_;
    };
    /// The angle from the bisector (direction beta) of the direction phi, in [-pi, pi].
    double from_bisector(const double phi, const double beta)
    {
      const double theta = phi - beta;
      return theta - 2.0 * pi * std::round(theta / (2.0 * pi));
    }

    // The Gauss directions of every angular panel [panels[i], panels[i + 1]] in theta (about
    // the bisector at beta): f(phi, w_theta) with phi = theta + beta the direction in the (r, z)
    // plane and w_theta the angular weight.
    template <class F>
    void for_each_direction(const std::vector<double> &panels, const GaussRule1D &ga, const double beta, F &&f)
    {
      for (std::size_t p = 0; p + 1 < panels.size(); ++p)
        {
          const double a = panels[p], b = panels[p + 1];
          for (Eigen::Index k = 0; k < ga.nodes.size(); ++k)
            f(a + (b - a) * 0.5 * (ga.nodes[k] + 1.0) + beta, (b - a) * 0.5 * ga.weights[k]);
        }
    }
  }

  VertexEnrichment::VertexEnrichment(const axisym::Point at,
                                     const std::array<double, 2> leaving_direction,
                                     const Wedge &wedge, std::vector<WedgeMode> modes,
                                     const double cutoff_radius, const Material &material,
                                     const int multiplier_degree, const int local_degree,
                                     const int local_displacement_degree)
    : at_(at)
    , beta_(std::atan2(leaving_direction[1], leaving_direction[0]) + wedge.half_angle())
    , wedge_(wedge)
    , modes_(std::move(modes))
    , cutoff_radius_(cutoff_radius)
    , material_(material)
    , multiplier_degree_(multiplier_degree)
    , local_degree_(local_degree)
    , local_displacement_degree_(local_displacement_degree)
  {
    if (!(cutoff_radius > 0.0))
      throw std::invalid_argument("VertexEnrichment: the cutoff radius must be positive");
    if (!(at.r > 0.0))
      throw std::invalid_argument("VertexEnrichment: the vertex must lie off the axis (r > 0)");
    if (local_displacement_degree_ > local_degree_ || local_displacement_degree_ < -1)
      throw std::invalid_argument("VertexEnrichment: the local displacement degree must be in "
                                  "[-1, local_degree]");
    if (multiplier_degree < 0)
      throw std::invalid_argument("VertexEnrichment: the multiplier degree must be >= 0");
    if (!(std::hypot(leaving_direction[0], leaving_direction[1]) > 0.0))
      throw std::invalid_argument("VertexEnrichment: the face direction must not be zero");
    // The faces: leaving along beta - alpha, arriving along beta + alpha.
    const double alpha = wedge.half_angle();
    std::array<double, 2> t[2];
    for (int f = 0; f < 2; ++f)
      {
        const double a = beta_ + (f == 0 ? -alpha : alpha);
        t[f] = {std::cos(a), std::sin(a)};
        normal_[f] = {-t[f][1], t[f][0]};
      }
    // The smooth stress families that meet both faces' conditions: with l_f the face's line
    // function (1 for a clamped face, which has none) and A_f the tensors that meet face f's
    // condition on it (free: t t; symmetry: t t and n n), l_0 l_1 E (E the three unit
    // tensors), l_1 A_0 and l_0 A_1 (a clamped face's A is E, whose family l_other E the
    // first one already is), and the hoop stress.
    const WedgeFace face[2] = {wedge.face_minus(), wedge.face_plus()};
    auto factor = [&](const int f) { return face[f] == WedgeFace::clamped ? 0 : (1 << f); };
    auto dyad = [](const std::array<double, 2> &a) {
      return std::array<double, 3>{a[0] * a[0], a[1] * a[1], a[0] * a[1]};
    };
    for (const std::array<double, 3> e : {std::array<double, 3>{1, 0, 0}, std::array<double, 3>{0, 1, 0},
                                          std::array<double, 3>{0, 0, 1}})
      families_.push_back({e, factor(0) | factor(1), false});
    for (int f = 0; f < 2; ++f)
      {
        if (face[f] == WedgeFace::clamped)
          continue;
        families_.push_back({dyad(t[f]), factor(1 - f), false, f, f});
        if (face[f] == WedgeFace::symmetry)
          families_.push_back({dyad(normal_[f]), factor(1 - f), false, -1, f});
      }
    families_.push_back({{0, 0, 0}, 0, true});
    // Displacements: e_r and e_z times l_f of each face where u is constrained (clamped or
    // symmetry), and on a symmetry face its tangent times the other face's factor.
    auto constrained = [&](const int f) { return face[f] == WedgeFace::free ? 0 : (1 << f); };
    vector_families_.push_back({{1, 0}, constrained(0) | constrained(1)});
    vector_families_.push_back({{0, 1}, constrained(0) | constrained(1)});
    for (int f = 0; f < 2; ++f)
      if (face[f] == WedgeFace::symmetry)
        vector_families_.push_back({t[f], constrained(1 - f)});
    // A complex pair's two columns, Re and Im of rho^lambda F, mix under a change of the unit
    // of length (rho^(i b) turns by b log s): they are taken of (rho / rho_0)^(i b) rho^a F
    // instead, the same span, so that the orthonormalization's cut keeps the same directions
    // in any unit (issue 24's hub at 133 degrees, lambda = 1.905 + 0.388 i: stresses at p = 8
    // 1.3e-4 of the largest apart between metres and decimetres).
    column_modes_ = modes_;
    for (WedgeMode &mode : column_modes_)
      if (mode.lambda.imag() != 0.0)
        mode.a *= std::exp(std::complex<double>(0.0, -mode.lambda.imag() * std::log(cutoff_radius_)));
  }

  void VertexEnrichment::set_hoop_shadow(const bool on)
  {
    shadows_.clear();
    if (!on)
      return;
    for (const WedgeMode &mode : column_modes_)
      shadows_.emplace_back(wedge_, mode, beta_, at_.r, material_.poisson_ratio, frame_ ? &*frame_ : nullptr);
    // None at all (every mode near a resonance): no columns.
    if (std::none_of(shadows_.begin(), shadows_.end(), [](const WedgeShadow &s) { return s.valid(); }))
      shadows_.clear();
  }

  Eigen::Index VertexEnrichment::n_full_families() const
  {
    return static_cast<Eigen::Index>(
      std::count_if(families_.begin(), families_.end(), [this](const Family &f) { return !reduced(f); }));
  }

  Eigen::Index VertexEnrichment::n_reduced_families() const
  {
    return static_cast<Eigen::Index>(families_.size()) - n_full_families();
  }

  Eigen::Index VertexEnrichment::n_local_columns() const
  {
    if (local_degree_ < 0)
      return 0;
    // Per polynomial of the disc a block of the full families (or of the displacement ones,
    // where they are more), then the reduced families' polynomials along their faces.
    const Eigen::Index block = std::max(n_full_families(), static_cast<Eigen::Index>(vector_families_.size()));
    return block * (local_degree_ + 1) * (local_degree_ + 2) / 2 + n_reduced_families() * (local_degree_ + 1);
  }

  Eigen::Index VertexEnrichment::n_inner_columns() const
  {
    if (inner_degree_ < 0)
      return 0;
    return n_full_families() * (inner_degree_ + 1) * (inner_degree_ + 2) / 2 + n_reduced_families() * (inner_degree_ + 1);
  }

  void VertexEnrichment::set_inner_disc(const int degree)
  {
    if (degree < -1)
      throw std::invalid_argument("VertexEnrichment::set_inner_disc: the degree must be >= -1");
    inner_degree_ = degree;
  }

  Eigen::Index VertexEnrichment::n_fields() const
  {
    Eigen::Index n = 0;
    for (const WedgeMode &m : modes_)
      n += m.lambda.imag() == 0.0 ? 1 : 2;
    return n;
  }

  EdgeColumns VertexEnrichment::evaluate(const Eigen::Ref<const Eigen::VectorXd> &r,
                                         const Eigen::Ref<const Eigen::VectorXd> &z,
                                         const bool modes_only) const
  {
    const Eigen::Index n = r.size(), per = columns_per_field();
    EdgeColumns out = EdgeColumns::zero(n, modes_only ? n_mode_columns() : n_columns());
    const double nu = material_.poisson_ratio;
    const double mu = material_.youngs_modulus / (2.0 * (1.0 + nu));
    const int d = multiplier_degree_;
    const double e_over_rv = material_.youngs_modulus / at_.r;
    std::vector<double> xi_pow(d + 1), eta_pow(d + 1);
    WedgeLegendre legendre(std::max(local_degree_, 0), beta_, wedge_.half_angle()),
      inner_legendre(std::max(inner_degree_, 0), beta_, wedge_.half_angle());
    Eigen::VectorXd along(std::max({local_degree_, inner_degree_, 0}) + 1), along_d(along.size());
    // The local columns per polynomial of the disc (n_local_columns).
    const Eigen::Index block = std::max(n_full_families(), static_cast<Eigen::Index>(vector_families_.size()));
    // One real field at a point: (sigma_rr, sigma_zz, sigma_tt, sigma_rz), the plane strains
    // (e_rr, e_zz, gamma_rz) and (u_r, u_z), all per unit amplitude, u already over mu.
    struct Field
    {
      double s[4], e[3], u[2];
    };
    std::vector<Field> fields(static_cast<std::size_t>(n_fields()));
    std::vector<Field> shadow_fields(fields.size()); // the hoop shadows (set_hoop_shadow)
    const bool wide = section_support();
    VertexFactors factors;
    if (wide)
      factors = factors_(r, z);
    // The modes' monomials: scaled by rho_0 in the disc, by the section's reach without it.
    const double mode_scale = wide ? length_scale_ : cutoff_radius_;
    for (Eigen::Index k = 0; k < n; ++k)
      {
        const double dr = r[k] - at_.r, dz = z[k] - at_.z;
        const double rho = std::hypot(dr, dz);
        const Cutoff chi = edge_cutoff(rho, cutoff_radius_);
        const bool in_disc = !(chi.value == 0.0 && chi.derivative == 0.0);
        if (!in_disc && !wide)
          continue;
        const double phi = std::atan2(dz, dr);
        const double theta = from_bisector(phi, beta_);
        // Curved faces (set_curved_faces): the stresses at the mapped angle theta_m (from
        // the bisector), seen in the direction phi_m, then turned by `turn`.
        double theta_m = theta, phi_m = phi, turn = 0.0;
        if (frame_ && rho > 0.0)
          {
            const auto [mapped, a] = frame_->mapped_angle(r[k], z[k], 1e-14 * cutoff_radius_);
            theta_m = mapped - wedge_.half_angle();
            phi_m = beta_ + theta_m;
            turn = a;
          }
        const double c_turn = std::cos(turn), s_turn = std::sin(turn);
        // Meridian stresses turned by the rotation Q(turn): Q S Q^T (sigma_tt, nu times the
        // trace, stays).
        auto turned = [c_turn, s_turn](const double (&w)[4], double (&out)[4]) {
          const std::array<double, 3> t = turned_tensor(w[rr], w[zz], w[rz], c_turn, s_turn);
          out[rr] = t[0], out[zz] = t[1], out[rz] = t[2];
          out[tt] = w[tt];
        };
        std::size_t f = 0;
        for (const WedgeMode &mode : column_modes_)
          {
            const bool singular = mode.lambda.real() < 1.0;
            WedgeFieldValues v{}, v_mapped{};
            if (rho > 0.0)
              {
                v = wedge_.evaluate(mode, rho, theta);
                v_mapped = frame_ ? wedge_.evaluate(mode, rho, theta_m) : v;
              }
            for (int part = 0; part < (mode.lambda.imag() == 0.0 ? 1 : 2); ++part, ++f)
              {
                Field &fl = fields[f];
                // Polar to meridian components (phi the direction of the point from v).
                const MeridianWedgeField m = meridian_wedge_field(v, 1.0, part, phi, mu, nu);
                const bool no_value = rho == 0.0 && singular;
                // Plane-strain Hooke's law (the displacement of mu = 1 scaled by 1 / mu): the
                // strains of the straight wedge's displacement.
                double s[4];
                for (int comp = 0; comp < 4; ++comp)
                  s[comp] = no_value ? 0.0 : m.s[comp];
                const double tr = nu * (s[rr] + s[zz]);
                fl.e[0] = (s[rr] - tr) / (2.0 * mu);
                fl.e[1] = (s[zz] - tr) / (2.0 * mu);
                fl.e[2] = s[rz] / mu;
                fl.u[0] = m.u[0];
                fl.u[1] = m.u[1];
                if (frame_ && !no_value)
                  turned(meridian_wedge_field(v_mapped, 1.0, part, phi_m, mu, nu).s, s);
                for (int comp = 0; comp < 4; ++comp)
                  fl.s[comp] = s[comp];
                // The hoop shadow: displacement and strains at the point, the stresses T at
                // the mapped angle and turned on curved faces (wedge_shadow.h).
                Field &sh = shadow_fields[f];
                sh = Field{};
                const std::size_t mi = static_cast<std::size_t>(&mode - column_modes_.data());
                if (mi < shadows_.size() && shadows_[mi].valid() && rho > 0.0)
                  {
                    const WedgeShadow::Values sv = shadows_[mi].evaluate(rho, theta);
                    const WedgeShadow::Values st = frame_ ? shadows_[mi].evaluate(rho, theta_m) : sv;
                    auto take = [&](const std::complex<double> x) { return part == 0 ? x.real() : x.imag(); };
                    // Stresses (nu times the trace for sigma_tt; the hoop term is added with
                    // the column's u_r) and displacement in meridian components.
                    const MeridianWedgeField ts = meridian_wedge_field({st.t[0], st.t[1], st.t[2], sv.u[0], sv.u[1]},
                                                                       1.0, part, phi_m, mu, nu);
                    const MeridianWedgeField us =
                      frame_ ? meridian_wedge_field({0.0, 0.0, 0.0, sv.u[0], sv.u[1]}, 1.0, part, phi, mu, nu) : ts;
                    for (int comp = 0; comp < 4; ++comp)
                      sh.s[comp] = ts.s[comp];
                    if (frame_)
                      turned(ts.s, sh.s);
                    sh.u[0] = us.u[0];
                    sh.u[1] = us.u[1];
                    // The strains (polar, engineering shear) in meridian components.
                    const std::array<double, 3> t = turned_tensor(
                      take(sv.e[0]), take(sv.e[1]), 0.5 * take(sv.e[2]), std::cos(phi), std::sin(phi));
                    sh.e[0] = t[0] / mu, sh.e[1] = t[1] / mu, sh.e[2] = 2.0 * t[2] / mu;
                  }
              }
          }
        // grad chi = chi'(rho) (dr, dz) / rho (chi'(0) = 0).
        const double chi_r = rho > 0.0 ? chi.derivative * dr / rho : 0.0;
        const double chi_z = rho > 0.0 ? chi.derivative * dz / rho : 0.0;
        // The modes' scalar factor and its gradient: the cutoff, or the section support's
        // displacement factor (its stress factors per component below).
        const double f_u = wide ? factors.u[k] : chi.value;
        const double f_r = wide ? factors.u_r[k] : chi_r;
        const double f_z = wide ? factors.u_z[k] : chi_z;
        const double xi_m = dr / mode_scale, eta_m = dz / mode_scale;
        xi_pow[0] = eta_pow[0] = 1.0;
        for (int i = 1; i <= d; ++i)
          {
            xi_pow[i] = xi_pow[i - 1] * xi_m;
            eta_pow[i] = eta_pow[i - 1] * eta_m;
          }
        const int last = d + (shadows_.empty() ? 0 : 1); // the shadow after the monomials
        for (std::size_t j = 0; j < fields.size(); ++j)
          {
            Eigen::Index col = static_cast<Eigen::Index>(j) * per;
            for (int deg = 0; deg <= last; ++deg)
              for (int b = 0; b <= (deg > d ? 0 : deg); ++b, ++col)
                {
                  const Field &fl = deg > d ? shadow_fields[j] : fields[j];
                  // g = f xi^a eta^b (a + b = deg; the shadow's 1) and its gradient.
                  const int a = deg > d ? 0 : deg - b;
                  const double mono = xi_pow[a] * eta_pow[b];
                  const double mono_r = a > 0 ? a * xi_pow[a - 1] * eta_pow[b] / mode_scale : 0.0;
                  const double mono_z = b > 0 ? b * xi_pow[a] * eta_pow[b - 1] / mode_scale : 0.0;
                  const double g = f_u * mono;
                  const double g_r = f_r * mono + f_u * mono_r;
                  const double g_z = f_z * mono + f_u * mono_z;
                  for (int comp = 0; comp < n_stress_components; ++comp)
                    out.stress[comp](k, col) = (wide ? factors.stress(k, comp) * mono : g) * fl.s[comp];
                  // The hoop strain's share of sigma_tt (the header): E times the column's own
                  // u_r over r_v.
                  out.stress[tt](k, col) += e_over_rv * g * fl.u[0];
                  out.u[0](k, col) = g * fl.u[0];
                  out.u[1](k, col) = g * fl.u[1];
                  // e(g u) = g e(u) + sym(grad g (x) u), engineering shear.
                  out.strain[rr](k, col) = g * fl.e[0] + g_r * fl.u[0];
                  out.strain[zz](k, col) = g * fl.e[1] + g_z * fl.u[1];
                  out.strain[tt](k, col) = g * fl.u[0] / r[k];
                  out.strain[rz](k, col) = g * fl.e[2] + g_z * fl.u[0] + g_r * fl.u[1];
                }
          }
        if (!in_disc || modes_only)
          continue;
        // The local stress columns: chi q (l_0 / rho_0)^a (l_1 / rho_0)^b T, q of WedgeLegendre;
        // the displacement columns chi m (l_0 / rho_0)^a (l_1 / rho_0)^b V, m a monomial.
        const double xi = dr / cutoff_radius_, eta = dz / cutoff_radius_;
        Eigen::Index col = n_mode_columns();
        // The faces' functions over rho_0 with their gradients: the line's, or on an arc the
        // circle's (R^2 - |x - c|^2) / (2 R); and the tangent dyads of arc faces at x.
        double l[2], l_r[2], l_z[2];
        std::array<double, 3> arc_dyad[2];
        for (int face = 0; face < 2; ++face)
          if (frame_ && frame_->face_is_arc(face))
            {
              const axisym::Point c = frame_->face_center(face);
              const double radius = frame_->face_radius(face), x = r[k] - c.r, y = z[k] - c.z;
              l[face] = (radius * radius - x * x - y * y) / (2.0 * radius * cutoff_radius_);
              l_r[face] = -x / (radius * cutoff_radius_);
              l_z[face] = -y / (radius * cutoff_radius_);
              const double d2 = x * x + y * y;
              arc_dyad[face] = {y * y / d2, x * x / d2, -x * y / d2};
            }
          else
            {
              l[face] = (dr * normal_[face][0] + dz * normal_[face][1]) / cutoff_radius_;
              l_r[face] = normal_[face][0] / cutoff_radius_;
              l_z[face] = normal_[face][1] / cutoff_radius_;
            }
        // A stress family at this point times q (the face functions over rho_0 times `scale`),
        // in column `at`.
        auto add_family = [&](const Family &fam, const double q, const double scale, const Eigen::Index at) {
          double w = q;
          if (fam.factors & 1)
            w *= scale * l[0];
          if (fam.factors & 2)
            w *= scale * l[1];
          if (fam.hoop)
            out.stress[tt](k, at) = w;
          else
            {
              const std::array<double, 3> &T =
                fam.tangent_of >= 0 && frame_ && frame_->face_is_arc(fam.tangent_of) ? arc_dyad[fam.tangent_of]
                                                                                   : fam.tensor;
              out.stress[rr](k, at) = w * T[0];
              out.stress[zz](k, at) = w * T[1];
              out.stress[rz](k, at) = w * T[2];
            }
        };
        // The full families times q from column `at` on; returns the column after them.
        auto add_families = [&](const double q, const double scale, Eigen::Index at) {
          for (const Family &fam : families_)
            if (!reduced(fam))
              add_family(fam, q, scale, at++);
          return at;
        };
        // The reduced families times chi L_j(s_f) (j <= degree), s_f the offset along the
        // family's face over the radius; from column `at` on, returns the column after them.
        auto add_reduced = [&](const double chi_value, const double radius, const int degree, const double scale,
                               Eigen::Index at) {
          if (degree < 0)
            return at;
          for (const Family &fam : families_)
            if (reduced(fam))
              {
                const int f = fam.own_face;
                // The face's direction: the normal turned back.
                const double s_f = (dr * normal_[f][1] - dz * normal_[f][0]) / radius;
                legendre_values(degree, s_f, along.head(degree + 1), along_d.head(degree + 1));
                for (int j = 0; j <= degree; ++j)
                  add_family(fam, chi_value * along[j], scale, at++);
              }
          return at;
        };
        // c x^a y^b, multiplied out in that order.
        auto times_monomial = [](double c, const double x, const double y, const int a, const int b) {
          for (int i = 0; i < a; ++i)
            c *= x;
          for (int i = 0; i < b; ++i)
            c *= y;
          return c;
        };
        legendre.at(dr, dz, cutoff_radius_);
        for (int deg = 0; deg <= local_degree_; ++deg)
          for (int b = 0; b <= deg; ++b)
            {
              // The stresses' polynomial (WedgeLegendre); the displacements' monomial and its
              // gradient.
              const double q = chi.value * legendre(deg - b, b);
              const int a_pow = deg - b;
              const double mono = times_monomial(1.0, xi, eta, a_pow, b);
              double mono_r = 0.0, mono_z = 0.0;
              if (a_pow > 0)
                mono_r = a_pow * std::pow(xi, a_pow - 1) * std::pow(eta, b) / cutoff_radius_;
              if (b > 0)
                mono_z = b * std::pow(xi, a_pow) * std::pow(eta, b - 1) / cutoff_radius_;
              const Eigen::Index first = col;
              for (std::size_t v = 0; v < vector_families_.size() && deg <= local_displacement_degree_; ++v)
                {
                  const VectorFamily &fam = vector_families_[v];
                  // g = chi mono L, L the product of the scaled line functions.
                  double lf = 1.0, lf_r = 0.0, lf_z = 0.0;
                  for (int f = 0; f < 2; ++f)
                    if (fam.factors & (1 << f))
                      {
                        lf_r = lf_r * l[f] + lf * l_r[f];
                        lf_z = lf_z * l[f] + lf * l_z[f];
                        lf *= l[f];
                      }
                  const double g = chi.value * mono * lf;
                  const double g_r = chi_r * mono * lf + chi.value * (mono_r * lf + mono * lf_r);
                  const double g_z = chi_z * mono * lf + chi.value * (mono_z * lf + mono * lf_z);
                  const Eigen::Index c = first + static_cast<Eigen::Index>(v);
                  out.u[0](k, c) = g * fam.vector[0];
                  out.u[1](k, c) = g * fam.vector[1];
                  out.strain[rr](k, c) = g_r * fam.vector[0];
                  out.strain[zz](k, c) = g_z * fam.vector[1];
                  out.strain[tt](k, c) = g * fam.vector[0] / r[k];
                  out.strain[rz](k, c) = g_z * fam.vector[0] + g_r * fam.vector[1];
                }
              add_families(q, 1.0, first);
              col = first + block;
            }
        col = add_reduced(chi.value, cutoff_radius_, local_degree_, 1.0, col);
        // The inner disc's stress columns: chi_in q (l_0 / rho_in)^a (l_1 / rho_in)^b T, q of
        // WedgeLegendre over rho_in.
        const double rho_in = inner_disc_ratio * cutoff_radius_;
        const Cutoff chi_in = edge_cutoff(rho, rho_in);
        if (inner_degree_ < 0 || chi_in.value == 0.0)
          continue;
        inner_legendre.at(dr, dz, rho_in);
        col = n_mode_columns() + n_local_columns();
        for (int deg = 0; deg <= inner_degree_; ++deg)
          for (int b = 0; b <= deg; ++b)
            col = add_families(chi_in.value * inner_legendre(deg - b, b), 1.0 / inner_disc_ratio, col);
        add_reduced(chi_in.value, rho_in, inner_degree_, 1.0 / inner_disc_ratio, col);
      }
    return out;
  }

  std::vector<double> VertexEnrichment::angular_panels(const std::vector<double> &extra_breaks,
                                                       const double max_width, const double min_gap) const
  {
    // Angular breaks in theta: the faces, at a reflex vertex the faces' lines continued into
    // the body (theta = +-(pi - alpha)), where the omegas of the trimmed faces have a kink,
    // and the extra ones inside the wedge.
    const double alpha = wedge_.half_angle();
    std::vector<double> breaks{-alpha, alpha};
    if (alpha > 0.5 * pi + 1e-12)
      breaks.push_back(pi - alpha), breaks.push_back(alpha - pi);
    for (const double theta : extra_breaks)
      if (theta > -alpha && theta < alpha)
        breaks.push_back(theta);
    std::sort(breaks.begin(), breaks.end());
    std::vector<double> panels;
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
      {
        const double a = breaks[i], b = breaks[i + 1];
        if (!(b - a > min_gap))
          continue;
        const int pieces = static_cast<int>(std::ceil((b - a) / max_width - 1e-9));
        for (int k = 0; k < pieces; ++k)
          panels.push_back(a + (b - a) * k / pieces);
      }
    panels.push_back(alpha);
    return panels;
  }

  void VertexEnrichment::set_curved_faces(const WedgeFrame &frame)
  {
    if (section_support())
      throw std::logic_error("VertexEnrichment::set_curved_faces: a vertex with a curved face keeps its disc");
    const double tol = 1e-9 * cutoff_radius_;
    if (!(std::hypot(frame.vertex().r - at_.r, frame.vertex().z - at_.z) <= tol &&
          std::abs(frame.angle() - 2.0 * wedge_.half_angle()) <= 1e-9))
      throw std::invalid_argument("VertexEnrichment::set_curved_faces: the frame is not this vertex's");
    const WedgeFace face[2] = {wedge_.face_minus(), wedge_.face_plus()};
    for (int f = 0; f < 2; ++f)
      if (frame.face_is_arc(f) && face[f] != WedgeFace::free)
        throw std::invalid_argument("VertexEnrichment::set_curved_faces: a curved face must be a traction face");
    if (frame.curved())
      frame_ = frame;
    if (!shadows_.empty())
      set_hoop_shadow(true); // with the faces' curvature
  }

  Quadrature2D VertexEnrichment::near_rule(const int n_radial, const int n_angular, const int n_layers,
                                           const std::vector<Circle> &rims, const int n_beyond_rims,
                                           const int n_outer) const
  {
    if (n_radial < 1 || n_angular < 1 || n_layers < 0)
      throw std::invalid_argument("VertexEnrichment::near_rule: point counts must be positive");
    if (frame_)
      return frame_->near_rule(cutoff_radius_, n_radial, n_angular, n_layers, rims, n_beyond_rims, n_outer);
    if (!rims.empty())
      throw std::invalid_argument("VertexEnrichment::near_rule: rims only on curved faces");
    const std::vector<double> panels = angular_panels({}, 0.5 * pi, 1e-12);
    // Radial layers [0.2^(i+1), 0.2^i] rho_0, the innermost [0, 0.2^L rho_0] with rho = rho_in s^2;
    // the outermost with n_outer points a direction where that is more.
    const bool outer = n_layers > 0 && n_outer > std::min(n_radial, n_angular);
    const double outer_from = 0.2 * cutoff_radius_;
    const GaussRule1D radial = outer ? polar_radial_rule(cutoff_radius_, n_radial, n_layers, {outer_from},
                                                         std::max(n_radial, n_outer))
                                     : polar_radial_rule(cutoff_radius_, n_radial, n_layers);
    const GaussRule1D ga = gauss_legendre(n_angular), ga_outer = gauss_legendre(std::max(n_angular, n_outer));
    std::vector<double> rs, zs, ws;
    for (const bool in_outer : {false, true})
      {
        if (in_outer && !outer)
          break;
        for_each_direction(panels, in_outer ? ga_outer : ga, beta_, [&](const double phi, const double w_theta) {
          const double c = std::cos(phi), s = std::sin(phi);
          for (Eigen::Index i = 0; i < radial.nodes.size(); ++i)
            if ((outer && radial.nodes[i] > outer_from) == in_outer)
              {
                rs.push_back(at_.r + radial.nodes[i] * c);
                zs.push_back(at_.z + radial.nodes[i] * s);
                ws.push_back(w_theta * radial.weights[i]);
              }
        });
      }
    Quadrature2D q;
    const auto n_points = static_cast<Eigen::Index>(rs.size());
    q.r = Eigen::Map<const Eigen::VectorXd>(rs.data(), n_points);
    q.z = Eigen::Map<const Eigen::VectorXd>(zs.data(), n_points);
    q.weights = Eigen::Map<const Eigen::VectorXd>(ws.data(), n_points);
    return q;
  }

  void VertexEnrichment::set_section_support(VertexFactorFunction factors,
                                             std::function<double(double)> reach,
                                             std::vector<double> ray_breaks, const double length_scale)
  {
    if (!factors || !(length_scale > 0.0))
      throw std::invalid_argument("VertexEnrichment::set_section_support: factors and a positive "
                                  "length scale are needed");
    if (frame_ && reach)
      throw std::logic_error("VertexEnrichment::set_section_support: the section rule follows straight "
                             "faces; a vertex with a curved face takes the support without a reach");
    factors_ = std::move(factors);
    reach_ = std::move(reach);
    ray_breaks_ = std::move(ray_breaks);
    length_scale_ = length_scale;
  }

  Quadrature2D VertexEnrichment::section_rule(const int n_radial, const int n_angular,
                                              const std::vector<Circle> &circles, const int n_layers,
                                              const int n_outer) const
  {
    if (!has_section_rule())
      throw std::logic_error("VertexEnrichment::section_rule: no section support with a reach");
    const Quadrature2D disc = near_rule(n_radial, n_angular, n_layers, {}, 0, n_outer);
    // Also broken at the directions of the outline's vertices, where the reach has a kink.
    std::vector<double> vertex_breaks;
    for (const double phi : ray_breaks_)
      vertex_breaks.push_back(from_bisector(phi, beta_));
    // The circles' tangent directions seen from the vertex: there a ray's chord through the
    // circle starts or ends.
    for (const Circle &k : circles)
      {
        const double dr = k.centre.r - at_.r, dz = k.centre.z - at_.z, d = std::hypot(dr, dz);
        if (!(d > k.radius))
          continue;
        const double half = std::asin(k.radius / d), mid = std::atan2(dz, dr);
        for (const double phi : {mid - half, mid + half})
          vertex_breaks.push_back(from_bisector(phi, beta_));
      }
    const GaussRule1D ga = gauss_legendre(n_angular), gr = gauss_legendre(n_radial);
    // Where a ray nearly grazes a curved edge, or runs almost along a line that ends at an
    // outline vertex, the reach has a near-singular slope at a panel's end (issue 24's hub
    // with a step for its taper: the rays from the step's vertex that meet the inner arc
    // next to its end on the symmetry plane; the section's area came out 5.8e-6 short with
    // 11 points a panel, 3e-7 with 20, and the Lagrange functional below the exact minimum). Each panel is therefore
    // halved until its moments of the reach, rho_max^2 and rho_max^8 (what the columns'
    // products of degree up to 6 in rho weigh along a ray), agree with its halves' to 1e-13
    // of the section's (at most 40 halvings: toward a grazing end the panels shrink
    // geometrically, the rest stay).
    const std::vector<double> panels = [&] {
      const std::vector<double> coarse = angular_panels(vertex_breaks, 0.125 * pi, 1e-9);
      const double L = length_scale_;
      auto moments = [&](const double a, const double b) {
        std::array<double, 2> m{0.0, 0.0};
        for_each_direction({a, b}, ga, beta_, [&](const double phi, const double w_theta) {
          const double x = std::max(reach_(phi), cutoff_radius_) / L, x2 = x * x;
          m[0] += w_theta * x2, m[1] += w_theta * x2 * x2 * x2 * x2;
        });
        return m;
      };
      const double tolerance = 1e-13 * 2.0 * pi;
      std::vector<double> out{coarse.front()};
      std::function<void(double, double, std::array<double, 2>, int)> refine =
        [&](const double a, const double b, const std::array<double, 2> whole, const int depth) {
          const double c = 0.5 * (a + b);
          const std::array<double, 2> left = moments(a, c), right = moments(c, b);
          const bool converged = std::abs(left[0] + right[0] - whole[0]) <= tolerance &&
                                 std::abs(left[1] + right[1] - whole[1]) <= tolerance;
          if (converged || depth >= 40)
            {
              out.push_back(b);
              return;
            }
          refine(a, c, left, depth + 1);
          refine(c, b, right, depth + 1);
        };
      for (std::size_t i = 0; i + 1 < coarse.size(); ++i)
        refine(coarse[i], coarse[i + 1], moments(coarse[i], coarse[i + 1]), 0);
      return out;
    }();
    std::vector<double> r, z, w;
    const double rho_0 = cutoff_radius_;
    for_each_direction(panels, ga, beta_, [&](const double phi, const double w_theta) {
      const double c = std::cos(phi), s = std::sin(phi);
      const double reach = reach_(phi);
      if (!(reach > rho_0))
        return;
      // [rho_0, reach] in geometric pieces of ratio at most 3, also broken where the ray
      // crosses a circle.
      const int pieces = std::max(1, static_cast<int>(std::ceil(std::log(reach / rho_0) / std::log(3.0) - 1e-9)));
      const double ratio = std::pow(reach / rho_0, 1.0 / pieces);
      std::vector<double> ends;
      for (int piece = 1; piece < pieces; ++piece)
        ends.push_back(rho_0 * std::pow(ratio, piece));
      for (const Circle &k : circles)
        {
          // |at + t (c, s) - centre| = radius
          const double dr = at_.r - k.centre.r, dz = at_.z - k.centre.z;
          const double b = c * dr + s * dz, disc = b * b - (dr * dr + dz * dz - k.radius * k.radius);
          if (!(disc > 0.0))
            continue;
          for (const double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)})
            if (t > rho_0 * (1.0 + 1e-9) && t < reach * (1.0 - 1e-9))
              ends.push_back(t);
        }
      std::sort(ends.begin(), ends.end());
      ends.push_back(reach);
      double lo = rho_0;
      for (const double hi : ends)
        {
          if (!(hi > lo * (1.0 + 1e-12)))
            continue;
          for (Eigen::Index i = 0; i < gr.nodes.size(); ++i)
            {
              const double rho = lo + (hi - lo) * 0.5 * (gr.nodes[i] + 1.0);
              r.push_back(at_.r + rho * c);
              z.push_back(at_.z + rho * s);
              w.push_back(w_theta * (hi - lo) * 0.5 * gr.weights[i] * rho);
            }
          lo = hi;
        }
    });
    Quadrature2D q;
    const Eigen::Index n_disc = disc.weights.size(), n_rays = static_cast<Eigen::Index>(w.size());
    q.r.resize(n_disc + n_rays), q.z.resize(n_disc + n_rays), q.weights.resize(n_disc + n_rays);
    q.r.head(n_disc) = disc.r, q.z.head(n_disc) = disc.z, q.weights.head(n_disc) = disc.weights;
    q.r.tail(n_rays) = Eigen::Map<const Eigen::VectorXd>(r.data(), n_rays);
    q.z.tail(n_rays) = Eigen::Map<const Eigen::VectorXd>(z.data(), n_rays);
    q.weights.tail(n_rays) = Eigen::Map<const Eigen::VectorXd>(w.data(), n_rays);
    return q;
  }
} // namespace rfm
