#pragma once
// The one element loop: gather → local kernel → scatter, colour by colour
// (docs/architecture.md). KernelBlock<Kernel> implements BlockContribution
// (contributions/element_type.hpp) for any element kernel; a kernel supplies
//
//   struct Kernel : SomeKinematics<...> {          // contributions/kinematics.hpp: State, gather, dof
//                                                  // (and optionally add: R += f_e node by node)
//     static constexpr bool kPressure;             // carries follower pressure (theory manual §6)
//     static constexpr bool kStartStiffness;       // has the stress-free start's K₀ (theory manual §7.2)
//     static constexpr bool kSolid;                // Gauss-point states are SolidPoint
//     explicit Kernel(const BlockContext&);        // reference data, the part's material
//     void internal(int e, const State&, Vector& f, Matrix* K) const;
//     double length2(const Model&, const int* en, const State&) const;  // L_e² of the round-off yardstick:
//                                      // the larger of the element's length² and its nodes' largest |x|²
//     void pressure(const State&, double p, Vector& f, Matrix* K) const;             // if kPressure
//     double subtract_pressure(const State&, double p, Vector& f, Matrix* K) const;  // optional: f −= f_p,
//                                      // K −= ∂f_p/∂u in place, returns ‖f_p‖² (else pressure() and a subtraction)
//     double volume(const State&, const VolumeMeasure&, Vector* grad) const;         // if kPressure
//     void start(int e, double T0, Matrix& K) const;                                 // if kStartStiffness
//     void points(int e, const State&, std::vector<MembranePoint or SolidPoint>&) const;
//     double energy(int e, const State&) const;                                      // if kSolid
//     // optional, the inverse element (theory manual §13): s the imaged state (x = the model's
//     // positions), ue the element's unknowns (its reference nodes X = x + ue), f = f_int(X, x),
//     // K = ∂f_int/∂X; and its Gauss points (reference X, current x)
//     void inverse(int e, const State& s, const Vector& ue, Vector& f, Matrix* K) const;
//     void inverse_points(int e, const State& s, const Vector& ue, std::vector<MembranePoint>&) const;
//   };
//
// Parallel assembly: each colour is one OpenMP loop; elements of a colour touch disjoint
// entries of R and K, so no locks are needed and every entry receives its contributions in
// the same order whatever the number of threads: results are identical bit for bit.
#include <fmt/format.h>

#include <exception>
#include <stdexcept>
#include <vector>

#include "contributions/element_type.hpp"
#include "model/node_label.hpp"

namespace tunica {

/// Runs body(e) for every element of a layout, colour by colour; the runs of a colour in parallel,
/// each run's elements in order on one thread. An exception of a kernel (an inverted element) is
/// rethrown after the colour: the one of the lowest element index, so that the message does not
/// depend on the threads.
template <class Body>
void for_each_coloured(const BlockLayout& layout, Body&& body) {
  std::exception_ptr error;
  int error_element = -1;
  // Small colours run on one thread: below ~1000 elements the fork/join costs more than it saves.
  constexpr int kMinParallel = 1024;
  for (std::size_t c = 0; c + 1 < layout.colour_start.size(); ++c) {
    const int begin = layout.colour_start[c], end = layout.colour_start[c + 1];
    const int elements = layout.run_start[end] - layout.run_start[begin];
#pragma omp parallel for schedule(static) if (elements >= kMinParallel && end - begin > 1)
    for (int r = begin; r < end; ++r)
      for (int k = layout.run_start[r]; k < layout.run_start[r + 1]; ++k) {
        const int e = layout.order[k];
        try {
          body(e);
        } catch (...) {
#pragma omp critical(tunica_assembly_error)
          if (error_element < 0 || e < error_element) {
            error = std::current_exception();
            error_element = e;
          }
        }
      }
    if (error) std::rethrow_exception(error);
  }
}

template <class Kernel>
class KernelBlock final : public BlockContribution {
public:
  static constexpr int kDofs = Kernel::kNodes * Kernel::kUnknowns;
  using Vector = Eigen::Matrix<double, kDofs, 1>;
  using Matrix = Eigen::Matrix<double, kDofs, kDofs>;
  using State = typename Kernel::State;
  /// The kernel has the inverse element (theory manual §13).
  static constexpr bool kInverse = requires(const Kernel& k, const State& s, const Vector& v, Vector& f, Matrix* M) {
    k.inverse(0, s, v, f, M);
  };

  explicit KernelBlock(BlockContext ctx)
      : model_(ctx.model), block_(ctx.block), part_(ctx.part.name), first_element_(ctx.first_element), kernel_(ctx),
        layout_(std::move(ctx.layout)),
        curvature_(std::move(ctx.curvature)),
        points_per_element_(element_type(ctx.block.kind).points_per_element(ctx.part)) {
    // The registration, the model's kind and the kernel must agree on the element's size: the
    // scatter positions are laid out from the registration, the loop indexes them with kDofs.
    const ElementType& type = element_type(block_.kind);
    std::string wrong;
    const auto agree = [&](const char* what, long kernel, long other, const char* where) {
      if (kernel != other) wrong += fmt::format("; {}: the kernel has {}, {} {}", what, kernel, where, other);
    };
    agree("nodes", Kernel::kNodes, nodes_per_element(block_.kind), "the model's kind");
    agree("unknowns per node", Kernel::kUnknowns, type.unknowns_per_node, "the registration");
    agree("solid", Kernel::kSolid, type.solid, "the registration");
    agree("pressure", Kernel::kPressure, type.pressure, "the registration");
    agree("inverse", kInverse, type.inverse, "the registration");
    agree("scatter codes per element", kDofs * kDofs,
          block_.size() ? static_cast<long>(layout_.scatter.size()) / block_.size() : kDofs * kDofs, "the layout");
    if (Kernel::kStartStiffness)
      agree("curvatures (one per element)", block_.size(), static_cast<long>(curvature_.size()), "the context");
    if (!wrong.empty()) throw std::logic_error("element type " + type.name + " disagrees with itself" + wrong);
    compact_.resize(block_.size());
    runs_.resize(kRuns * static_cast<std::size_t>(block_.size()));
    for (int e = 0; e < block_.size(); ++e)
      compact_[e] = find_runs(layout_.scatter.data() + static_cast<std::size_t>(kDofs) * kDofs * e,
                              runs_.data() + kRuns * static_cast<std::size_t>(e));
  }

  void assemble(const Eigen::VectorXd& u, double pressure, Eigen::VectorXd& R, TangentMatrix* K,
                double& scale2) const override {
    std::vector<double> scale_e(block_.size());  // per element: summed in element order, whatever the threads
    for_each_coloured(layout_, [&](int e) {
      Vector f;
      Matrix Ke;
      State s;
      const int* en = block_.element(e);
      Kernel::gather(model_, en, u, s);
      try {
        kernel_.internal(e, s, f, K ? &Ke : nullptr);
      } catch (const std::domain_error& err) {  // an inadmissible state: where, for the run's message
        throw std::domain_error(fmt::format("{}, in element {} of part '{}' (its first node: {})", err.what(),
                                            first_element_ + e, part_, node_label(model_, en[0])));
      }
      double s2 = f.squaredNorm();
      if constexpr (Kernel::kPressure) {
        if (pressure != 0.0) {
          if constexpr (requires(Vector& r, Matrix* M) { kernel_.subtract_pressure(s, pressure, r, M); }) {
            s2 += kernel_.subtract_pressure(s, pressure, f, K ? &Ke : nullptr);
          } else {
            Vector fp;
            Matrix dfp;
            kernel_.pressure(s, pressure, fp, K ? &dfp : nullptr);
            s2 += fp.squaredNorm();
            f -= fp;
            if (K) Ke -= dfp;
          }
        }
      }
      // Stiffness × L_e bounds the round-off of the forces: near zero strain that of the stresses,
      // and positions held to a relative precision give an element at |x| from the origin strains
      // with round-off ε|x|/h (user guide §6, round-off).
      if (K) s2 += Ke.colwise().squaredNorm().sum() * kernel_.length2(model_, en, s);
      scale_e[e] = s2;
      scatter(e, en, f, K ? &Ke : nullptr, layout_.scatter.data() + kDofs * kDofs * e, R, K);
    });
    for (double s2 : scale_e) scale2 += s2;
  }

  void assemble_inverse(const Eigen::VectorXd& u, double pressure, Eigen::VectorXd& R, TangentMatrix* K,
                        double& scale2) const override {
    if constexpr (kInverse) {
      const Eigen::VectorXd zero = Eigen::VectorXd::Zero(u.size());
      std::vector<double> scale_e(block_.size());
      for_each_coloured(layout_, [&](int e) {
        Vector f, ue;
        Matrix Ke;
        State s;
        const int* en = block_.element(e);
        Kernel::gather(model_, en, zero, s);  // the imaged state: x = the model's positions
        for (int a = 0; a < kDofs; ++a) ue(a) = u(Kernel::dof(model_, en, a));
        kernel_.inverse(e, s, ue, f, K ? &Ke : nullptr);
        double s2 = f.squaredNorm();
        if (pressure != 0.0) {  // on the imaged surface: f_p(x̂), no stiffness, (13.2)
          Vector fp;
          kernel_.pressure(s, pressure, fp, nullptr);
          s2 += fp.squaredNorm();
          f -= fp;
        }
        if (K) s2 += Ke.colwise().squaredNorm().sum() * kernel_.length2(model_, en, s);
        scale_e[e] = s2;
        scatter(e, en, f, K ? &Ke : nullptr, layout_.scatter.data() + kDofs * kDofs * e, R, K);
      });
      for (double s2 : scale_e) scale2 += s2;
    } else {
      BlockContribution::assemble_inverse(u, pressure, R, K, scale2);
    }
  }

  void inverse_points(const Eigen::VectorXd& u, std::vector<MembranePoint>& out) const override {
    if constexpr (kInverse) {
      const Eigen::VectorXd zero = Eigen::VectorXd::Zero(u.size());
      for (int e = 0; e < block_.size(); ++e) {
        State s;
        Vector ue;
        const int* en = block_.element(e);
        Kernel::gather(model_, en, zero, s);
        for (int a = 0; a < kDofs; ++a) ue(a) = u(Kernel::dof(model_, en, a));
        kernel_.inverse_points(e, s, ue, out);
      }
    }
  }

  void pressure_load(const Eigen::VectorXd& u, double sign, Eigen::VectorXd& g) const override {
    if constexpr (Kernel::kPressure) {
      for (int e = 0; e < block_.size(); ++e) {
        State s;
        Vector f;
        const int* en = block_.element(e);
        Kernel::gather(model_, en, u, s);
        kernel_.pressure(s, sign, f, nullptr);
        for (int a = 0; a < kDofs; ++a) g(Kernel::dof(model_, en, a)) += f(a);
      }
    }
  }

  void add_volume(const Eigen::VectorXd& u, const VolumeMeasure& how, double& V, Eigen::VectorXd* grad) const override {
    if constexpr (Kernel::kPressure) {
      for (int e = 0; e < block_.size(); ++e) {
        State s;
        Vector ge;
        const int* en = block_.element(e);
        Kernel::gather(model_, en, u, s);
        V += kernel_.volume(s, how, grad ? &ge : nullptr);
        if (grad)
          for (int a = 0; a < kDofs; ++a) (*grad)(Kernel::dof(model_, en, a)) += ge(a);
      }
    }
  }

  void reference_diagonal(Eigen::VectorXd& diag) const override {
    const Eigen::VectorXd u0 = Eigen::VectorXd::Zero(diag.size());
    for (int e = 0; e < block_.size(); ++e) {
      State s;
      Vector f;
      Matrix Ke;
      const int* en = block_.element(e);
      Kernel::gather(model_, en, u0, s);
      kernel_.internal(e, s, f, &Ke);
      for (int a = 0; a < kDofs; ++a) diag(Kernel::dof(model_, en, a)) += Ke(a, a);
    }
  }

  void start_stiffness(const StartTension& t, const Eigen::VectorXd& d, Eigen::VectorXd& Kd,
                       TangentMatrix& K) const override {
    if constexpr (Kernel::kStartStiffness) {
      for_each_coloured(layout_, [&](int e) {
        const double T0 = t.at(curvature_[e]);  // theory manual (7.8) or (7.14)
        Matrix Ke;
        kernel_.start(e, T0, Ke);
        const int* en = block_.element(e);
        Vector f = Vector::Zero();
        if (d.size() > 0) {
          Vector de;
          for (int a = 0; a < kDofs; ++a) de(a) = d(Kernel::dof(model_, en, a));
          f = Ke * de;
        }
        scatter(e, en, f, &Ke, layout_.scatter.data() + kDofs * kDofs * e, Kd, &K);
      });
    }
  }

  void membrane_points(const Eigen::VectorXd& u, std::vector<MembranePoint>& out) const override {
    if constexpr (!Kernel::kSolid) points(u, out);
  }

  void solid_points(const Eigen::VectorXd& u, std::vector<SolidPoint>& out) const override {
    if constexpr (Kernel::kSolid) points(u, out);
  }

  void add_energy(const Eigen::VectorXd& u, double& energy) const override {
    if constexpr (Kernel::kSolid) {
      for (int e = 0; e < block_.size(); ++e) {
        State s;
        Kernel::gather(model_, block_.element(e), u, s);
        energy += kernel_.energy(e, s);
      }
    } else {
      std::vector<MembranePoint> pts;
      points(u, pts);
      for (const auto& pt : pts) energy += pt.W * pt.weight;
    }
  }

private:
  /// Appends the points of every element: the registration's points_per_element each (the
  /// writers index them by it), checked.
  template <class Point>
  void points(const Eigen::VectorXd& u, std::vector<Point>& out) const {
    for (int e = 0; e < block_.size(); ++e) {
      State s;
      Kernel::gather(model_, block_.element(e), u, s);
      const std::size_t before = out.size();
      kernel_.points(e, s, out);
      if (out.size() - before != static_cast<std::size_t>(points_per_element_))
        throw std::logic_error(fmt::format("element type {}: its kernel gave {} points for an element, its "
                                           "registration's points_per_element says {}",
                                           element_type(block_.kind).name, out.size() - before, points_per_element_));
    }
  }

  /// R(dof a) += f(a); K += K_e through the element's codes (BlockLayout): K_e(a, b) is added to
  /// the split storage at its code, those of the upper triangle only where it is stored. Every entry
  /// of K receives one term per element, in the elements' order, as a full matrix's entry would.
  void scatter(int e, const int* en, const Vector& f, const Matrix* Ke, const int* code, Eigen::VectorXd& R,
               TangentMatrix* K) const {
    if constexpr (requires { Kernel::add(model_, en, f, R); }) {
      Kernel::add(model_, en, f, R);
    } else {
      for (int a = 0; a < kDofs; ++a) R(Kernel::dof(model_, en, a)) += f(a);
    }
    if (!K) return;
    double* values = K->values();
    if (K->split() && compact_[e]) {
      scatter_runs(runs_.data() + kRuns * static_cast<std::size_t>(e), *Ke, values, K->upper() != nullptr);
      return;
    }
    // Unsigned: −1 (not free-free) is beyond the stored codes as well.
    const unsigned stored = static_cast<unsigned>(K->stored());
    for (int a = 0; a < kDofs; ++a)
      for (int b = 0; b < kDofs; ++b)
        if (const unsigned k = static_cast<unsigned>(code[a * kDofs + b]); k < stored) values[k] += (*Ke)(a, b);
  }

  // An element whose unknowns are all free, with a node's equations consecutive (System numbers them
  // node by node), has its codes in runs: in the d × d block of K_e of nodes a and b (d unknowns per
  // node), column l of a block below K's diagonal (node a's rows after node b's) is d consecutive
  // slots (rows ascending in one column of the lower triangle), row k of a block above it d
  // consecutive codes of the upper triangle, and in a diagonal block (a = b) column t from the
  // diagonal down and row t right of it start at the slot of the diagonal entry, in `lower` and
  // `upper`. Such an element keeps d codes per block (the start of each run, checked against all its
  // codes when the block is built): a third of the codes read per entry, no test per entry, and the
  // upper triangle skipped by block where it is not stored.
  static constexpr int kUnknowns = Kernel::kUnknowns, kRuns = kUnknowns * Kernel::kNodes * Kernel::kNodes;

  /// The starts of the runs of an element's codes `code` into runs[0 … kRuns), block (a, b) at
  /// kUnknowns · (a · nodes + b); false if its codes are not in runs.
  bool find_runs(const int* code, int* runs) const {
    constexpr int d = kUnknowns;
    const int S = layout_.slots;
    for (int a = 0; a < Kernel::kNodes; ++a)
      for (int b = 0; b < Kernel::kNodes; ++b) {
        int* r = runs + d * (a * Kernel::kNodes + b);
        const auto at = [&](int k, int l) { return code[(d * a + k) * kDofs + d * b + l]; };
        for (int t = 0; t < d; ++t) {
          if (a == b) {
            r[t] = at(t, t);
            if (r[t] < 0 || r[t] + d - t > S) return false;
            for (int k = t; k < d; ++k)
              if (at(k, t) != r[t] + k - t) return false;
            for (int l = t + 1; l < d; ++l)
              if (at(t, l) != S + r[t] + l - t) return false;
          } else if (at(0, 0) >= 0 && at(0, 0) < S) {  // below the diagonal: column t
            r[t] = at(0, t);
            if (r[t] < 0 || r[t] + d > S) return false;
            for (int k = 0; k < d; ++k)
              if (at(k, t) != r[t] + k) return false;
          } else {  // above the diagonal: row t
            r[t] = at(t, 0);
            if (r[t] < S) return false;
            for (int l = 0; l < d; ++l)
              if (at(t, l) != r[t] + l) return false;
          }
        }
      }
    return true;
  }

  /// K_e added through the runs of an element (find_runs); the upper triangle only if `upper`.
  void scatter_runs(const int* r, const Matrix& Ke, double* values, bool upper) const {
    constexpr int d = kUnknowns;
    using Run = Eigen::Map<Eigen::Matrix<double, d, 1>>;
    const int S = layout_.slots;
    for (int a = 0; a < Kernel::kNodes; ++a)
      for (int b = 0; b < Kernel::kNodes; ++b, r += d) {
        if (a == b) {
          for (int t = 0; t < d; ++t) {
            double* v = values + r[t];
            for (int k = t; k < d; ++k) v[k - t] += Ke(d * a + k, d * a + t);
            if (upper)
              for (int l = t + 1; l < d; ++l) v[S + l - t] += Ke(d * a + t, d * a + l);
          }
        } else if (r[0] < S) {
          for (int l = 0; l < d; ++l) Run(values + r[l]) += Ke.template block<d, 1>(d * a, d * b + l);
        } else if (upper) {
          for (int k = 0; k < d; ++k) Run(values + r[k]) += Ke.template block<1, d>(d * a + k, d * b).transpose();
        }
      }
  }

  const Model& model_;
  const ElementBlock& block_;
  std::string part_;        ///< the part's name, for messages
  int first_element_ = 0;   ///< the block's first element's index in its part
  Kernel kernel_;
  BlockLayout layout_;
  std::vector<double> curvature_;
  std::vector<char> compact_;  ///< per element: its codes are in runs (find_runs)
  std::vector<int> runs_;      ///< per element, kRuns starts of runs (where compact_)
  int points_per_element_ = 0;
};

/// The `make` of an element type implemented by Kernel.
template <class Kernel>
std::unique_ptr<BlockContribution> make_kernel_block(BlockContext ctx) {
  return std::make_unique<KernelBlock<Kernel>>(std::move(ctx));
}

}  // namespace tunica
