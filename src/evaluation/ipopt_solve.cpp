#include "ipopt_solve.hpp"

#include <algorithm>

namespace smoothsteer::detail {

bool MinimumOfVariableNlp::eval_grad_f(Index n, const Number*, bool, Number* gradient) {
  std::fill(gradient, gradient + n, 0.0);
  gradient[objective_index()] = 1.0;
  return true;
}

bool MinimumOfVariableNlp::eval_jac_g(Index, const Number* x, bool, Index, Index, Index* rows,
                                      Index* columns, Number* values) {
  if (values == nullptr) {
    jacobian_pattern(rows, columns);
  } else {
    jacobian_values(x, values);
  }
  return true;
}

bool MinimumOfVariableNlp::eval_h(Index, const Number* x, bool, Number, Index,
                                  const Number* multipliers, bool, Index, Index* rows,
                                  Index* columns, Number* values) {
  if (values == nullptr) {
    hessian_pattern(rows, columns);
  } else {
    hessian_values(x, multipliers, values);
  }
  return true;
}

IpoptOutcome solve_nlp(const Ipopt::SmartPtr<Ipopt::TNLP>& nlp, const IpoptSettings& settings) {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  Ipopt::OptionsList& options = *app->Options();
  options.SetIntegerValue("print_level", settings.check_derivatives ? 4 : 0);
  options.SetStringValue("sb", "yes");
  options.SetStringValue("hessian_approximation",
                         settings.exact_hessian ? "exact" : "limited-memory");
  if (settings.check_derivatives) options.SetStringValue("derivative_test", "second-order");
  options.SetStringValue("mu_strategy", "adaptive");
  options.SetNumericValue("tol", settings.tolerance);
  options.SetIntegerValue("max_iter", settings.max_iterations);
  options.SetNumericValue("acceptable_tol", 1e-6);
  options.SetNumericValue("acceptable_constr_viol_tol", 1e-8);
  options.SetIntegerValue("acceptable_iter", 10);
  IpoptOutcome outcome;
  const std::lock_guard lock(ipopt_mutex());
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    outcome.status = "Ipopt initialisation failed";
    return outcome;
  }
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);
  outcome.status = status_text(status);
  outcome.converged =
      status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
  if (Ipopt::SmartPtr<Ipopt::SolveStatistics> statistics = app->Statistics();
      Ipopt::IsValid(statistics)) {
    outcome.iterations = statistics->IterationCount();
  }
  return outcome;
}

const char* status_text(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded:
      return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level:
      return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected:
      return "Infeasible_Problem_Detected";
    case Ipopt::Maximum_Iterations_Exceeded:
      return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed:
      return "Restoration_Failed";
    default:
      return "Ipopt_Error";
  }
}

std::mutex& ipopt_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace smoothsteer::detail
