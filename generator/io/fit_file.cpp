// SPDX-License-Identifier: MIT
#include "io/fit_file.hpp"

#include "core/bounded_read.hpp"
#include "core/errors.hpp"
#include "io/record_fields.hpp"
#include "model/order.hpp"

#include <fmt/format.h>

namespace admitgen::io {

// ---- the field lists of fit.json (docs/formats.md, "fit.json") ------------------------------------

namespace {

/// An order's name ("Q1S1"), refused on reading unless it is one.
struct OrderName {
  Json write(const std::string& order) const { return order; }
  void read(const Field& f, std::string& order) const {
    order = f.text();
    try {
      Order::parse(order);
    } catch (const InputError&) {
      f.fail("expected an order QxSy");
    }
  }
};

/// The number of slices, or kAutomaticSlices when automatic (empty).
struct Slices {
  Json write(const std::optional<std::int64_t>& slices) const { return slices ? Json(*slices) : Json(kAutomaticSlices); }
  void read(const Field& f, std::optional<std::int64_t>& slices) const {
    slices.reset();
    if (!f.json().is_string()) {
      slices = f.integer();
    } else if (f.text() != kAutomaticSlices) {
      f.fail(fmt::format("expected a number of slices or \"{}\"", kAutomaticSlices));
    }
  }
};

/// Three quantile rows, each as long as `f_hz` (read before them).
struct QuantileRows {
  const std::vector<double>& f_hz;
  Json write(const std::array<std::vector<double>, 3>& rows) const { return rows; }
  void read(const Field& f, std::array<std::vector<double>, 3>& out) const {
    const auto rows = f.elements();
    if (rows.size() != 3) f.fail("expected three quantile rows");
    for (std::size_t i = 0; i < 3; ++i) {
      out[i] = rows[i].numbers();
      if (out[i].size() != f_hz.size()) rows[i].fail(fmt::format("expected {} values (one per f_hz)", f_hz.size()));
    }
  }
};

}  // namespace

template <class V>
void fields(V& v, FitParameter& p) {
  v("name", p.name);
  v("mean", p.mean);
  v("std", p.std);
  v.pair("ci95", p.ci95_lo, p.ci95_hi);
  v("max_likelihood", p.max_likelihood);
}

template <class V>
void fields(V& v, FitInput& in) {
  v("path", in.path);
  v("sha256", in.sha256);
  v("points", in.points);
  v("f_min_hz", in.f_min_hz);
  v("f_max_hz", in.f_max_hz);
  v("columns", in.columns);
  v("quantity", in.quantity);
  v("read_as", in.read_as);
  v("rho_c", in.rho_c, kNullable | kOptional);
  v("band", in.band, kNullable | kOptional);
}

template <class V>
void fields(V& v, FitSamplerSettings& s) {
  v("method", s.method);
  v("dlogz", s.dlogz);
  v("max_iterations", s.max_iterations);
  v("missed_mode_retries", s.missed_mode_retries);
  v("runs", s.runs);
  v.custom("slices", s.slices, Slices{});
  v("residues", s.residues);
  v.ignored("truncation_tolerance_nats");  // written by versions with the residue box's correction
}

template <class V>
void fields(V& v, FitSettingsRecord& s) {
  v("live", s.live);
  v("seed", s.seed);
  v.object("priors", [&s](auto& w) {
    w("source", s.priors_source);
    w("symmetry_reduced", s.symmetry_reduced);
    w("residues", s.residue_prior);
    w("ranges", s.prior_ranges);
  });
  v("likelihood", s.likelihood);
  v("select", s.select);
  v("qmax", s.qmax);
  v("smax", s.smax);
  v("sampler", s.sampler);
  v("passive", s.passive);
  v("grid_growth", s.grid_growth);
  v("target", s.target);
}

template <class V>
void fields(V& v, FitTarget& t) {
  v("max_band_delta_alpha", t.max_band_delta_alpha);
  v("max_relative_rms", t.max_relative_rms);
  v("max_buffers", t.max_buffers);
}

template <class V>
void fields(V& v, FitAccuracy& a) {
  v("buffers", a.buffers);
  v("relative_rms_residual", a.relative_rms_residual);
  v("max_band_delta_alpha", a.max_band_delta_alpha);
  v("worst_band_hz", a.worst_band_hz);
  v("meets_target", a.meets_target);
  v("conditioning", a.conditioning);
}

template <class V>
void fields(V& v, FitGrid& g) {
  v("qmax", g.qmax);
  v("smax", g.smax);
  v("steps", g.steps, kPlain);
  v("edge", g.edge, kPlain);
}

template <class V>
void fields(V& v, FitPassiveEstimate& e) {
  v("poles_from", e.poles_from);
  v("sample_rank", e.sample_rank);
  v("residues", e.residues);
  v("parameters", e.parameters);
  v("log_likelihood", e.log_likelihood);
  v("relative_rms_residual", e.relative_rms_residual);
  v("delta_log_likelihood_vs_best_sample", e.delta_log_likelihood_vs_best_sample);
  v("best_sample_relative_rms_residual", e.best_sample_relative_rms_residual);
  v("certified_passive", e.certified_passive);
  v("min_re_G", e.min_re_G);
  v("constraint_rounds", e.constraint_rounds);
  v("sampled_poles_relative_rms_residual", e.sampled_poles_relative_rms_residual);
  v("pole_search_steps", e.pole_search_steps);
  v("passivity_cost", e.passivity_cost);
  v("passive_bound_relative_rms_residual", e.passive_bound_relative_rms_residual);
  v("conditioning", e.conditioning);
  v("best_sample_conditioning", e.best_sample_conditioning);
  v("conditioning_tradeoff", e.conditioning_tradeoff, kPlain);
}

template <class V>
void fields(V& v, FitGoodness& g) {
  v("estimate", g.estimate);
  v("relative_rms_residual", g.relative_rms_residual);
  v("max_abs_delta_alpha", g.max_abs_delta_alpha);
}

template <class V>
void fields(V& v, FitModel& m) {
  v.custom("order", m.order, OrderName{});
  v("Q", m.q);
  v("S", m.s);
  v("live", m.live);
  v("log_evidence", m.log_evidence);
  v("log_evidence_error", m.log_evidence_error);
  v("max_log_likelihood", m.max_log_likelihood);
  v("information_nats", m.information_nats);
  v("likelihood_calls", m.likelihood_calls);
  v("iterations", m.iterations);
  v("stopped_by", m.stopped_by);
  v("seconds", m.seconds);
  v("parameters", m.parameters);
  v("passive_estimate", m.passive_estimate);
  v("log_passive_prior_fraction", m.log_passive_prior_fraction);
  v("goodness_of_fit", m.goodness_of_fit);
  v("accuracy", m.accuracy);
  v("sampler", m.sampler);
  v("sampler_note", m.sampler_note, kPlain);
  // Written by versions with the residue box's correction (docs/formats.md); read and ignored.
  for (const char* key : {"truncation_correction_nats", "truncation_correction_error_nats", "reweighted_ess_ratio",
                          "residue_draws_gibbs_weight"})
    v.ignored(key);
}

template <class V>
void fields(V& v, FitPredictive& p) {
  v("draws", p.draws);
  v("quantiles", p.quantiles);
  v("f_hz", p.f_hz);
  v.custom("re_G", p.re_G, QuantileRows{p.f_hz});
  v.custom("im_G", p.im_G, QuantileRows{p.f_hz});
  v.custom("alpha", p.alpha, QuantileRows{p.f_hz});
}

template <class V>
void fields(V& v, FitRecord& fit) {
  v("schema", fit.schema);
  v("version", fit.version);
  v("input", fit.input);
  v("settings", fit.settings);
  v("models", fit.models);
  v("bayes_factors_deciban", fit.bayes_factors_deciban);
  v("bayes_factor_errors_deciban", fit.bayes_factor_errors_deciban);
  v.object("selected", [&fit](auto& w) {
    w("order", fit.selected_order);
    w("rule", fit.selected_rule);
  });
  v("parameters", fit.parameters);
  v("log_evidence_error", fit.log_evidence_error_meaning);
  v("predictive", fit.predictive);
  v("warnings", fit.warnings, kPlain);
  v("notes", fit.notes, kPlain | kOptional);
  v("posterior", fit.posterior);
  v("grid", fit.grid);
}

// ---- writer and reader ----------------------------------------------------------------------------

std::string fit_text(const FitRecord& fit) { return write_record(fit).dump(2) + "\n"; }

bool is_json(const std::string& text) { return !Json::parse(text, nullptr, false).is_discarded(); }

FitRecord parse_fit(const std::string& text, const std::string& file) {
  const Json doc = parse_json(text, file);
  FitRecord fit;
  read_record(document_root(doc, file, kFitSchema, "fit"), fit);
  bool known = false;
  try {
    known = fit.model() != nullptr;
  } catch (const InputError&) {  // not an order at all
  }
  if (!known)
    Field(doc.at("selected").at("order"), file, "selected.order").fail("the selected order is not among the fitted models");
  return fit;
}

FitRecord read_fit_file(const std::string& path) {
  return parse_fit(read_bounded(path, kMaxDocumentBytes, "fit.json"), path);
}

std::vector<KeyNode> fit_keys() { return record_keys<FitRecord>(); }

}  // namespace admitgen::io
