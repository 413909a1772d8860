#include "fit/material_parametrization.hpp"

#include <fmt/format.h>

#include <cmath>

#include "io/read_params.hpp"

namespace tunica {

namespace {

constexpr double kDiagMin = 1e-4;    // lower bound of the Cholesky diagonal: a_ii ≥ 1e-8
constexpr double kEntryMax = 100;    // |L_ij| ≤ 100: a_ij ≤ 3e4, far beyond arterial values
constexpr double kLogScaleMax = 60;  // |ln c| ≤ 60

/// Lower-triangular L (n×n) from its entries row by row: L11, L21, L22, L31, L32, L33.
Eigen::MatrixXd lower_from(const Eigen::VectorXd& entries, int n) {
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  int k = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) L(i, j) = entries(k++);
  return L;
}

/// Fung's matrix A from the constants vector (c first): 2-D (a1, a2, a4), 3-D (a1, a2, a3, a4, a5, a6).
Eigen::MatrixXd fung_matrix(const Eigen::VectorXd& k, int n) {
  Eigen::MatrixXd A(n, n);
  if (n == 2) {
    A << k(1), k(3), k(3), k(2);
  } else {
    A << k(1), k(4), k(6),  //
        k(4), k(2), k(5),   //
        k(6), k(5), k(3);
  }
  return A;
}

MaterialParametrization fung(int n) {
  MaterialParametrization m;
  m.model = n == 2 ? "fung2d" : "fung3d";
  m.material_type = "fung";
  m.doc = n == 2 ? "Fung, the paper's two-dimensional approach: c, a1, a2, a4 (a3 = a5 = a6 = a7 = 0)"
                 : "Fung with the radial terms: c, a1 … a6 (a7 = 0; the tube has no in-plane shear)";
  m.constants = {{"c", Dimension::pressure}, {"a1", Dimension::dimensionless}, {"a2", Dimension::dimensionless}};
  if (n == 3) m.constants.push_back({"a3", Dimension::dimensionless});
  m.constants.push_back({"a4", Dimension::dimensionless});
  if (n == 3) {
    m.constants.push_back({"a5", Dimension::dimensionless});
    m.constants.push_back({"a6", Dimension::dimensionless});
  }
  const int nl = n * (n + 1) / 2;
  m.theta_names = {"ln_c"};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j) m.theta_names.push_back(fmt::format("L{}{}", i + 1, j + 1));
  m.lower = Eigen::VectorXd::Constant(1 + nl, -kEntryMax);
  m.upper = Eigen::VectorXd::Constant(1 + nl, kEntryMax);
  m.lower(0) = -kLogScaleMax;
  m.upper(0) = kLogScaleMax;
  for (int i = 0; i < n; ++i) m.lower(1 + i * (i + 1) / 2 + i) = kDiagMin;  // L(i, i) at θ index 1, 3, 6
  // A = L Lᵀ; constants (c, entries of A in deck order).
  m.constants_of = [n, nl](const Eigen::VectorXd& theta) {
    const Eigen::MatrixXd L = lower_from(theta.segment(1, nl), n);
    const Eigen::MatrixXd A = L * L.transpose();
    Eigen::VectorXd k(1 + nl);
    k(0) = std::exp(theta(0));
    if (n == 2)
      k.tail(3) << A(0, 0), A(1, 1), A(0, 1);
    else
      k.tail(6) << A(0, 0), A(1, 1), A(2, 2), A(0, 1), A(1, 2), A(0, 2);
    return k;
  };
  m.theta_of = [n, nl, lower = m.lower, upper = m.upper](const Eigen::VectorXd& k,
                                                         bool* projected) -> std::optional<Eigen::VectorXd> {
    if (!(k(0) > 0)) return std::nullopt;
    Eigen::MatrixXd A = fung_matrix(k, n);
    // Project onto positive definite matrices: raise eigenvalues below 1e-8.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
    bool changed = false;
    Eigen::VectorXd ev = eig.eigenvalues();
    for (int i = 0; i < n; ++i)
      if (ev(i) < 1e-8) {
        ev(i) = 1e-8;
        changed = true;
      }
    if (changed) A = eig.eigenvectors() * ev.asDiagonal() * eig.eigenvectors().transpose();
    const Eigen::MatrixXd L = Eigen::LLT<Eigen::MatrixXd>(A).matrixL();
    Eigen::VectorXd theta(1 + nl);
    theta(0) = std::log(k(0));
    int idx = 1;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) theta(idx++) = L(i, j);
    for (int i = 0; i < theta.size(); ++i) {
      const double clamped = std::min(std::max(theta(i), lower(i)), upper(i));
      if (clamped != theta(i)) changed = true;
      theta(i) = clamped;
    }
    if (projected) *projected = changed;
    return theta;
  };
  // Starting shapes of Fung's matrix: isotropic soft/medium/stiff and two anisotropic ones.
  const double shapes[5][3] = {{1, 1, 0}, {0.2, 0.2, 0}, {5, 5, 0}, {3, 0.5, 0}, {0.5, 3, 0}};
  for (const auto& s : shapes) {
    Eigen::VectorXd k = Eigen::VectorXd::Zero(1 + nl);
    k(0) = 1;
    k(1) = s[0];
    k(2) = s[1];
    if (n == 2) {
      k(3) = s[2];
    } else {
      k(3) = 0.1 * std::min(s[0], s[1]);  // a3: a weak radial term
      k(4) = s[2];
    }
    m.starts.push_back(*m.theta_of(k, nullptr));
  }
  return m;
}

MaterialParametrization neo_hookean() {
  MaterialParametrization m;
  m.model = "neo_hookean";
  m.material_type = "neo_hookean";
  m.doc = "incompressible neo-Hookean: mu";
  m.constants = {{"mu", Dimension::pressure}};
  m.theta_names = {"ln_mu"};
  m.lower = Eigen::VectorXd::Constant(1, -kLogScaleMax);
  m.upper = Eigen::VectorXd::Constant(1, kLogScaleMax);
  m.constants_of = [](const Eigen::VectorXd& t) { return Eigen::VectorXd::Constant(1, std::exp(t(0))); };
  m.theta_of = [](const Eigen::VectorXd& k, bool* projected) -> std::optional<Eigen::VectorXd> {
    if (projected) *projected = false;
    if (!(k(0) > 0)) return std::nullopt;
    return Eigen::VectorXd::Constant(1, std::log(k(0)));
  };
  m.starts = {Eigen::VectorXd::Zero(1)};
  return m;
}

MaterialParametrization mooney_rivlin() {
  MaterialParametrization m;
  m.model = "mooney_rivlin";
  m.material_type = "mooney_rivlin";
  m.doc = "incompressible Mooney–Rivlin: b1 > 0, b2 ≥ 0";
  m.constants = {{"b1", Dimension::pressure}, {"b2", Dimension::pressure}};
  m.theta_names = {"ln_b1", "b2_over_b1"};
  m.lower = Eigen::Vector2d(-kLogScaleMax, 0.0);
  m.upper = Eigen::Vector2d(kLogScaleMax, 1e3);
  m.constants_of = [](const Eigen::VectorXd& t) {
    const double b1 = std::exp(t(0));
    return Eigen::VectorXd(Eigen::Vector2d(b1, t(1) * b1));  // b2 = t b1
  };
  m.theta_of = [](const Eigen::VectorXd& k, bool* projected) -> std::optional<Eigen::VectorXd> {
    if (!(k(0) > 0)) return std::nullopt;
    const double t = std::min(std::max(k(1) / k(0), 0.0), 1e3);
    if (projected) *projected = t != k(1) / k(0);
    return Eigen::VectorXd(Eigen::Vector2d(std::log(k(0)), t));
  };
  m.starts = {Eigen::Vector2d(0.0, 0.1), Eigen::Vector2d(0.0, 1.0)};
  return m;
}

}  // namespace

std::unique_ptr<MembraneMaterial> MaterialParametrization::make_material(const Eigen::VectorXd& k) const {
  static const UnitSystem units("mm", "N");
  YAML::Node node;
  for (std::size_t i = 0; i < constants.size(); ++i) node[constants[i].name] = fmt::format("{:.17g}", k(i));
  const MaterialType& type = material_types().at(material_type);
  const Params p = read_params(DeckNode(node, "<fit>", "material"), type.spec, units);
  return type.make(p);
}

Eigen::MatrixXd MaterialParametrization::constants_jacobian(const Eigen::VectorXd& theta) const {
  const int n = static_cast<int>(theta.size());
  Eigen::MatrixXd T(constants.size(), n);
  for (int j = 0; j < n; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(theta(j)));
    Eigen::VectorXd a = theta, b = theta;
    a(j) += h;
    b(j) -= h;
    T.col(j) = (constants_of(a) - constants_of(b)) / (2.0 * h);
  }
  return T;
}

const std::map<std::string, MaterialParametrization>& material_parametrizations() {
  static const std::map<std::string, MaterialParametrization> all = [] {
    std::map<std::string, MaterialParametrization> m;
    for (MaterialParametrization p : {fung(2), fung(3), neo_hookean(), mooney_rivlin()}) m[p.model] = std::move(p);
    return m;
  }();
  return all;
}

const MaterialParametrization& material_parametrization(const std::string& name) {
  const auto& all = material_parametrizations();
  auto it = all.find(name);
  if (it == all.end()) {
    std::string list;
    for (const auto& [k, v] : all) list += (list.empty() ? "" : ", ") + k;
    throw InputError({"--model", 0, 0, name}, "unknown model '" + name + "' (known: " + list + ")");
  }
  return it->second;
}

}  // namespace tunica
