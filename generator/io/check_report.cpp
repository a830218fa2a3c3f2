// SPDX-License-Identifier: MIT
#include "io/check_report.hpp"

#include "io/json_fields.hpp"

#include <fmt/format.h>

#include <cmath>
#include <type_traits>

namespace admitgen::io {
namespace {

using checks::Status;

/// The status as the text report spells it (a failure stands out in capitals).
const char* status_text(Status status) {
  switch (status) {
    case Status::pass: return "pass";
    case Status::fail: return "FAIL";
    case Status::not_applicable: return "n/a";
  }
  return "?";
}

const char* status_json(Status status) { return status == Status::fail ? "fail" : status_text(status); }

/// A frequency that may be infinite (a band reaching infinite frequency): the number, or "inf".
Json frequency(double hz) { return std::isinf(hz) ? Json("inf") : Json(hz); }

Json passivity_json(const checks::PassivityDetails& d) {
  const PassivityResult& p = d.test;
  Json bands = Json::array();
  for (std::size_t i = 0; i < p.bands.size(); ++i) {
    const NegativeBand& b = p.bands[i];
    bands.push_back({{"f_lo_hz", b.lo}, {"f_hi_hz", frequency(b.hi)}, {"min_re", b.min_re}, {"at_hz", frequency(b.at)},
                     {"where", checks::band_place_text(d.places.at(i))}});
  }
  return {{"passive", p.passive}, {"method", p.method}, {"crossings_hz", p.crossings}, {"negative_bands", bands},
          {"min_re", p.min_re}, {"min_at_hz", frequency(p.min_at)}};
}

/// Sets j[key] when the figure is there (a figure a rate does not have is left out).
template <class T>
void put(Json& j, const char* key, const std::optional<T>& value) {
  if (value) j[key] = *value;
}

/// {"rates": [f(rate), ...]}.
template <class Rate, class F>
Json rates_json(const std::vector<Rate>& rates, F f) {
  Json list = Json::array();
  for (const auto& r : rates) list.push_back(f(r));
  return {{"rates", list}};
}

Json details_json(const checks::CheckDetails& details) {
  return std::visit(
      [](const auto& d) -> Json {
        using D = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<D, checks::CausalityDetails>) {
          return {{"slowest_rate_per_s", d.slowest_rate_per_s ? Json(*d.slowest_rate_per_s) : Json(nullptr)}};
        } else if constexpr (std::is_same_v<D, checks::DiscreteStabilityDetails>) {
          return rates_json(d.rates, [](const checks::StabilityRate& r) {
            Json j{{"fs_hz", r.fs_hz}};
            put(j, "min_margin", r.min_margin);
            put(j, "slowest_time_constant_s", r.slowest_time_constant_s);
            return j;
          });
        } else if constexpr (std::is_same_v<D, checks::PassivityDetails>) {
          return passivity_json(d);
        } else if constexpr (std::is_same_v<D, checks::DiscretePassivityDetails>) {
          return rates_json(d.rates, [](const checks::DiscretePassivityRate& r) {
            if (!r.passivity) return Json{{"fs_hz", r.fs_hz}, {"skipped", "unstable (see discrete_stability)"}};
            Json j = passivity_json(*r.passivity);
            j["fs_hz"] = r.fs_hz;
            return j;
          });
        } else if constexpr (std::is_same_v<D, checks::HeadroomDetails>) {
          return rates_json(d.rates, [](const checks::HeadroomRate& r) {
            return Json{{"fs_hz", r.fs_hz}, {"max_state_l1", r.max_state_l1}, {"output_l1", r.output_l1},
                        {"output_range", r.output_range}, {"output_table_mantissa_sum", r.output_table_mantissa_sum}};
          });
        } else if constexpr (std::is_same_v<D, checks::LimitCycleDetails>) {
          return rates_json(d.rates, [](const checks::LimitCycleRate& r) {
            Json j{{"fs_hz", r.fs_hz}};
            put(j, "zero_decay_bound", r.zero_decay_bound);
            put(j, "simulated_samples", r.simulated_samples);
            return j;
          });
        } else {
          // Not applicable, and header_integrity: admitgen.check/1 has no figures for them (its count of
          // values compared is in the summary).
          static_assert(std::is_same_v<D, std::monostate> || std::is_same_v<D, checks::HeaderIntegrityDetails>);
          return Json::object();
        }
      },
      details);
}

}  // namespace

std::string check_report_json(const checks::CheckReport& report) {
  Json list = Json::array();
  for (const auto& c : report.checks)
    list.push_back({{"check", c.name},
                    {"status", status_json(c.status)},
                    {"method", c.method},
                    {"summary", c.summary},
                    {"failures", c.failures},
                    {"details", details_json(c.details)}});
  const Json doc{{"schema", "admitgen.check/1"}, {"subject", report.subject}, {"kind", report.kind},
                 {"passed", report.passed()}, {"failed", report.failed_checks()}, {"checks", list}};
  return doc.dump(2) + "\n";
}

std::string check_report_text(const checks::CheckReport& report) {
  std::string s = fmt::format("admitgen check {} ({})\n", report.subject, report.kind);
  for (const auto& c : report.checks) {
    s += fmt::format("  {:<4} {:<22} {}\n", status_text(c.status), c.name, c.summary);
    for (const auto& f : c.failures) s += fmt::format("         - {}\n", f);
  }
  const auto failed = report.failed_checks();
  s += failed.empty() ? "all checks passed\n" : fmt::format("{} check(s) failed\n", failed.size());
  return s;
}

}  // namespace admitgen::io
