// SPDX-License-Identifier: MIT
#include "io/check_report.hpp"

#include "io/record_fields.hpp"

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

/// The status as the JSON spells it.
struct StatusName {
  Json write(Status status) const { return status == Status::fail ? "fail" : status_text(status); }
};

/// A frequency that may be infinite (a band reaching infinite frequency): the number, or "inf".
struct Frequency {
  Json write(double hz) const { return std::isinf(hz) ? Json("inf") : Json(hz); }
};

/// The negative bands of a passivity test, each with where it lies (`places[i]` for band i).
struct NegativeBands {
  const std::vector<checks::BandPlace>& places;
  Json write(const std::vector<NegativeBand>& bands) const {
    Json out = Json::array();
    for (std::size_t i = 0; i < bands.size(); ++i) {
      const NegativeBand& b = bands[i];
      out.push_back({{"f_lo_hz", b.lo}, {"f_hi_hz", Frequency{}.write(b.hi)}, {"min_re", b.min_re},
                     {"at_hz", Frequency{}.write(b.at)}, {"where", checks::band_place_text(places.at(i))}});
    }
    return out;
  }
};

/// Why a rate's discrete passivity was not tested.
struct Skipped {
  Json write(const std::optional<checks::PassivityDetails>&) const { return "unstable (see discrete_stability)"; }
};

/// The figures of one check: its details record, {} when the check did not apply and for header_integrity
/// (admitgen.check/1 has no figures for it: its count of values compared is in the summary).
struct Details {
  Json write(const checks::CheckDetails& details) const {
    return std::visit(
        [](const auto& d) -> Json {
          using D = std::decay_t<decltype(d)>;
          if constexpr (std::is_same_v<D, std::monostate> || std::is_same_v<D, checks::HeaderIntegrityDetails>)
            return Json::object();
          else
            return write_record(d);
        },
        details);
  }
};

/// What `admitgen check --json` writes.
struct CheckDocument {
  std::string schema = "admitgen.check/1", subject, kind;
  bool passed = false;
  std::vector<std::string> failed;
  std::vector<checks::CheckResult> checks;
};

}  // namespace

// ---- the field lists of the check report (docs/formats.md, "check report") ------------------------

template <class V>
void fields(V& v, checks::CausalityDetails& d) {
  v("slowest_rate_per_s", d.slowest_rate_per_s, kNullable);
}

template <class V>
void fields(V& v, checks::StabilityRate& r) {
  v("fs_hz", r.fs_hz);
  v("min_margin", r.min_margin);
  v("slowest_time_constant_s", r.slowest_time_constant_s);
}

template <class V>
void fields(V& v, checks::DiscreteStabilityDetails& d) {
  v("rates", d.rates);
}

template <class V>
void fields(V& v, checks::PassivityDetails& d) {
  v("passive", d.test.passive);
  v("method", d.test.method);
  v("crossings_hz", d.test.crossings);
  v.custom("negative_bands", d.test.bands, NegativeBands{d.places});
  v("min_re", d.test.min_re);
  v.custom("min_at_hz", d.test.min_at, Frequency{});
}

/// A tested rate: the members of passivity_continuous, then fs_hz; a skipped (unstable) one: fs_hz, skipped.
template <class V>
void fields(V& v, checks::DiscretePassivityRate& r) {
  if (r.passivity) fields(v, *r.passivity);
  v("fs_hz", r.fs_hz);
  if (!r.passivity) v.custom("skipped", r.passivity, Skipped{});
}

template <class V>
void fields(V& v, checks::DiscretePassivityDetails& d) {
  v("rates", d.rates);
}

template <class V>
void fields(V& v, checks::HeadroomRate& r) {
  v("fs_hz", r.fs_hz);
  v("max_state_l1", r.max_state_l1);
  v("output_l1", r.output_l1);
  v("output_range", r.output_range);
  v("output_table_mantissa_sum", r.output_table_mantissa_sum);
}

template <class V>
void fields(V& v, checks::HeadroomDetails& d) {
  v("rates", d.rates);
}

template <class V>
void fields(V& v, checks::LimitCycleRate& r) {
  v("fs_hz", r.fs_hz);
  v("zero_decay_bound", r.zero_decay_bound);
  v("simulated_samples", r.simulated_samples);
}

template <class V>
void fields(V& v, checks::LimitCycleDetails& d) {
  v("rates", d.rates);
}

template <class V>
void fields(V& v, checks::FidelityRate& r) {
  v("fs_hz", r.fs_hz);
  v("max_rel_deviation", r.max_rel_deviation);
  v("at_hz", r.at_hz);
  v("max_rel_deviation_above_band", r.max_rel_deviation_above_band);
  v("noise_floor", r.noise_floor);
  v("min_full_scale_snr_db", r.min_full_scale_snr_db);
  v("snr_at_hz", r.snr_at_hz);
}

template <class V>
void fields(V& v, checks::FidelityDetails& d) {
  v("tolerance", d.tolerance);
  v("min_full_scale_snr_db", d.min_full_scale_snr_db);
  v("rates", d.rates);
}

template <class V>
void fields(V& v, checks::CheckResult& c) {
  v("check", c.name);
  v.custom("status", c.status, StatusName{});
  v("method", c.method);
  v("summary", c.summary);
  v("failures", c.failures);
  v.custom("details", c.details, Details{});
}

template <class V>
void fields(V& v, CheckDocument& d) {
  v("schema", d.schema);
  v("subject", d.subject);
  v("kind", d.kind);
  v("passed", d.passed);
  v("failed", d.failed);
  v("checks", d.checks);
}

// ---- writers --------------------------------------------------------------------------------------

std::string check_report_json(const checks::CheckReport& report) {
  CheckDocument d;
  d.subject = report.subject;
  d.kind = report.kind;
  d.passed = report.passed();
  d.failed = report.failed_checks();
  d.checks = report.checks;
  return write_record(d).dump(2) + "\n";
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

std::vector<KeyNode> check_report_keys() { return record_keys<CheckDocument>(); }

std::vector<std::pair<std::string, std::vector<KeyNode>>> check_details_keys() {
  return {{"causality", record_keys<checks::CausalityDetails>()},
          {"discrete_stability", record_keys<checks::DiscreteStabilityDetails>()},
          {"passivity_continuous", record_keys<checks::PassivityDetails>()},
          {"passivity_discrete", record_keys<checks::DiscretePassivityDetails>()},
          {"headroom", record_keys<checks::HeadroomDetails>()},
          {"limit_cycle", record_keys<checks::LimitCycleDetails>()},
          {"fidelity", record_keys<checks::FidelityDetails>()}};
}

}  // namespace admitgen::io
