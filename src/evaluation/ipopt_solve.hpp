#pragma once
// Internal: what the two Ipopt transcriptions (the optimal reaching manoeuvre, the engagement
// bound) share: their objective is one of their variables, and one solve with the same options.

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include <array>
#include <cstddef>
#include <mutex>
#include <string>

namespace smoothsteer::detail {

//! A TNLP that minimises one of its variables (the reaching distance S, the bound z). Ipopt asks
//! for each sparse derivative twice, its pattern (values null) and then its values; the
//! transcriptions give the two separately. The objective being linear, the Lagrangian's Hessian
//! is the constraints' alone.
class MinimumOfVariableNlp : public Ipopt::TNLP {
 public:
  using Index = Ipopt::Index;
  using Number = Ipopt::Number;

  bool eval_f(Index, const Number* x, bool, Number& objective) final {
    objective = x[objective_index()];
    return true;
  }
  bool eval_grad_f(Index n, const Number*, bool, Number* gradient) final;
  bool eval_jac_g(Index, const Number* x, bool, Index, Index, Index* rows, Index* columns,
                  Number* values) final;
  bool eval_h(Index, const Number* x, bool, Number, Index, const Number* multipliers, bool, Index,
              Index* rows, Index* columns, Number* values) final;

 protected:
  virtual Index objective_index() const = 0;
  virtual void jacobian_pattern(Index* rows, Index* columns) const = 0;
  virtual void jacobian_values(const Number* x, Number* values) const = 0;
  virtual void hessian_pattern(Index* rows, Index* columns) const = 0;
  //! Sum over the constraints of multiplier times Hessian, in hessian_pattern()'s order.
  virtual void hessian_values(const Number* x, const Number* multipliers, Number* values) const = 0;
  //! The convergence that finalize_solution() reports: an optimum or an acceptable point.
  static bool converged(Ipopt::SolverReturn status) noexcept {
    return status == Ipopt::SUCCESS || status == Ipopt::STOP_AT_ACCEPTABLE_POINT;
  }
};

//! Appends the (row, column) pairs of a sparsity pattern at `entry`.
template <std::size_t N>
void append_pattern(const Ipopt::Index (&pairs)[N][2], Ipopt::Index* rows, Ipopt::Index* columns,
                    Ipopt::Index& entry) noexcept {
  for (const auto& pair : pairs) {
    rows[entry] = pair[0];
    columns[entry] = pair[1];
    ++entry;
  }
}

//! Writes a sparsity pattern entry by entry: (row, column) pairs in Ipopt's order.
struct SparsityWriter {
  Ipopt::Index* rows;
  Ipopt::Index* columns;
  Ipopt::Index entry = 0;
  void add(Ipopt::Index row, Ipopt::Index column) noexcept {
    rows[entry] = row;
    columns[entry] = column;
    ++entry;
  }
};

//! The rows e_k - z <= 0 and -e_k - z <= 0 of a min-max transcription, two per node k = 0..nodes-1
//! from row `first_row`, with e_k at variable stride k + offset and z at `z_index`: their values
//! into g, their sparsity and their (constant) Jacobian entries appended.
struct MinMaxRows {
  Ipopt::Index first_row = 0;
  int nodes = 0;
  int stride = 1;
  int offset = 0;
  Ipopt::Index z_index = 0;

  void evaluate(const Ipopt::Number* x, Ipopt::Number* g) const noexcept {
    for (int k = 0; k < nodes; ++k) {
      const Ipopt::Number e = x[stride * k + offset];
      g[first_row + 2 * k] = e - x[z_index];
      g[first_row + 2 * k + 1] = -e - x[z_index];
    }
  }
  void append_pattern(SparsityWriter& pattern) const noexcept {
    for (int k = 0; k < nodes; ++k) {
      const Ipopt::Index e = stride * k + offset;
      pattern.add(first_row + 2 * k, e);
      pattern.add(first_row + 2 * k, z_index);
      pattern.add(first_row + 2 * k + 1, e);
      pattern.add(first_row + 2 * k + 1, z_index);
    }
  }
  void append_values(Ipopt::Number* values, Ipopt::Index& entry) const noexcept {
    for (int k = 0; k < nodes; ++k) {
      for (const double value : {1.0, -1.0, -1.0, -1.0}) values[entry++] = value;
    }
  }
};

//! Lambda_i(j) of a trapezoidal transcription: the sums of the multipliers of defect rows 0..2 of
//! the one or two intervals (of `intervals`, `rows_per_interval` rows each) that touch node j.
inline std::array<double, 3> node_multipliers(const Ipopt::Number* multipliers, int j,
                                              int intervals, int rows_per_interval) noexcept {
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i) {
    if (j >= 1) sum[i] += multipliers[rows_per_interval * (j - 1) + i];
    if (j < intervals) sum[i] += multipliers[rows_per_interval * j + i];
  }
  return sum;
}

//! The settings a solve takes from its problem.
struct IpoptSettings {
  double tolerance = 1e-8;
  int max_iterations = 3000;
  bool exact_hessian = true;       //!< false: L-BFGS ("limited-memory")
  bool check_derivatives = false;  //!< Ipopt's second-order derivative test, printed
};

//! What a solve reports besides what finalize_solution() wrote.
struct IpoptOutcome {
  std::string status;  //!< Ipopt's return status as text
  bool converged = false;
  int iterations = 0;
};

//! One Ipopt solve of `nlp`, quiet, with the adaptive barrier strategy. Near bang-bang or
//! degenerate optima the last digits come slowly, so a point feasible to 1e-8 and optimal to
//! 1e-6 for 10 iterations is accepted (the callers re-simulate the result anyway). Holds
//! ipopt_mutex() during the solve.
IpoptOutcome solve_nlp(const Ipopt::SmartPtr<Ipopt::TNLP>& nlp, const IpoptSettings& settings);

//! Ipopt's return status as text.
const char* status_text(Ipopt::ApplicationReturnStatus status);

//! Held around every Ipopt solve of the process: this build's MUMPS (the sequential libdmumps
//! with its MPI stub) keeps global state, so two solves must not run at the same time.
std::mutex& ipopt_mutex();

}  // namespace smoothsteer::detail
