// SPDX-License-Identifier: MIT
#include "checks/check_suite.hpp"


#include <fmt/format.h>


namespace admitgen::checks {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

CheckSubject subject_from_header(const codegen::EmittedHeader& header, const std::string& text,
                                 const std::string& origin) {
  CheckSubject s;
  s.origin = origin;
  s.kind = "header";
  s.header = header;
  s.surface = s.header->surface;
  s.data_f_min_hz = s.header->data_f_min_hz;
  s.data_f_max_hz = s.header->data_f_max_hz;
  s.header_text = text;
  return s;
}

CheckSubject subject_from_fit(const FitRecord& fit, const std::string& origin, const std::string& order,
                              Estimate estimate) {
  CheckSubject s;
  s.origin = origin;
  s.kind = "fit";
  if (estimate == Estimate::passive && !fit_has_passive_estimate(fit, order, origin)) {
    estimate = Estimate::mean;
    s.note = "the fit holds no passive estimate (written by an older admitgen): its posterior mean is checked";
  }
  s.surface = multipole_from_fit(fit, order, estimate, origin, Causality::reported);  // named by check_causality
  s.data_f_min_hz = fit.input.f_min_hz;
  s.data_f_max_hz = fit.input.f_max_hz;
  return s;
}

std::string term_location(int fs_hz, const codegen::DiscreteModel& m, bool pair, std::size_t i) {
  if (!pair)
    return fmt::format("fs {} Hz, real pole {} (lambda {:.6g} 1/s = {:.4g} Hz)", fs_hz, i + 1, m.real[i].lambda,
                       m.real[i].lambda / (2 * kPi));
  return fmt::format("fs {} Hz, pair {} (alpha {:.6g} 1/s, beta {:.6g} 1/s = {:.4g} Hz)", fs_hz, i + 1,
                     m.pair[i].alpha, m.pair[i].beta, m.pair[i].beta / (2 * kPi));
}

CheckReport run_checks(const CheckSubject& s) {
  CheckReport r;
  r.subject = s.origin;
  r.kind = s.kind;
  r.checks = {check_causality(s),    check_discrete_stability(s), check_continuous_passivity(s),
              check_discrete_passivity(s), check_headroom(s),   check_limit_cycles(s),
              check_fidelity(s),           check_header_integrity(s)};
  return r;
}

}  // namespace admitgen::checks
