/// @file output.cpp
/// JSON, text, and the Markdown + HTML report (gnuplot figures) of a GapResult.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hstmon_gap/gap.hpp"
#include "hstmon_plot/gnuplot.hpp"
#include "hstmon_plot/html_report.hpp"

namespace hstmon::gap {

namespace {

using nlohmann::json;

__attribute__((format(printf, 1, 2))) std::string sfmt(const char* f, ...) {
  char buf[1024];
  va_list ap;
  va_start(ap, f);
  std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  return buf;
}

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json part_json(const PartStats& p) {
  json j = {{"label", p.label}, {"fraction", p.fraction}};
  json r = json::object();
  for (std::size_t c = 0; c < kChannels; ++c) {
    if (std::isfinite(p.rms_w[c])) r[channel_names()[c]] = p.rms_w[c];
  }
  j["rms_over_noise"] = r;
  return j;
}

json where_json(const Where& w) {
  json ch = json::object();
  for (std::size_t c = 0; c < kChannels; ++c) {
    const auto& s = w.channels[c];
    if (!s.present) continue;
    ch[channel_names()[c]] = {{"unit", c == 3 ? "rad/s" : "Pa"}, {"mean", s.mean}, {"rms", s.rms},
                              {"noise", s.noise}, {"rms_over_noise", s.rms_w},
                              {"rms_over_noise_within_uncertainty", s.rms_w_within},
                              {"noise_estimates", {{"white", s.noise_white}, {"adc_step", s.adc_step},
                                                   {"spread", s.noise_spread}}}};
  }
  json moves = json::object();
  for (const auto& [name, v] : w.parameter_moves) moves[name] = v;
  json j = {{"significant", w.significant}, {"rms_over_noise", w.rms_w_total}, {"sample_period", w.sample_period},
            {"channels", ch}, {"steady_settings", w.steady_settings},
            {"parameter_uncertainty", {{"z", w.uncertainty_z}, {"moves", moves}}}};
  auto arr = [](const std::vector<PartStats>& v) {
    json a = json::array();
    for (const auto& p : v) a.push_back(part_json(p));
    return a;
  };
  json eq = json::array();
  for (const auto& e : w.equations) {
    if (!e.available) continue;
    json bl = json::array();
    for (const auto& b : e.by_load) bl.push_back({{"label", b.label}, {"mean", b.mean}, {"rms_over_noise", b.rms_w}});
    eq.push_back({{"equation", e.equation}, {"unit", e.unit}, {"mean", e.mean}, {"rms", e.rms}, {"noise", e.noise},
                  {"rms_over_noise", e.rms_w}, {"by_load", bl}, {"dependence", e.dependence}});
  }
  j["equations"] = eq;
  j["located_equation"] = w.located >= 0 ? json(equation_names()[static_cast<std::size_t>(w.located)]) : json(nullptr);
  j["load_bins"] = arr(w.load_bins);
  j["phases"] = arr(w.phases);
  j["bands"] = arr(w.bands);
  return j;
}

json fit_json(const EffectFit& f) {
  json params = json::object(), unc = json::object(), units = json::object(), ident = json::object();
  for (const auto& p : f.params) {
    const std::string key = f.effects.size() > 1 || p.effect == "nominal" ? p.effect + "." + p.name : p.name;
    params[key] = p.value;
    unc[key] = num(p.se);
    units[key] = p.unit;
    ident[key] = p.identified;
  }
  json names = json::array();
  for (Effect e : f.effects) names.push_back(effect_info(e).name);
  json before = json::object(), after = json::object();
  for (std::size_t c = 0; c < kChannels; ++c) {
    if (!std::isfinite(f.rms_before_check[c])) continue;
    before[channel_names()[c]] = f.rms_before_check[c];
    after[channel_names()[c]] = num(f.rms_after_check[c]);
  }
  json j = {{"effect", f.name}, {"effects", names}, {"params", params}, {"std_error", unc}, {"units", units},
            {"identified", ident}, {"k", f.k}, {"delta_bic_fit", num(f.delta_bic_fit)},
            {"shrink_fit", num(f.shrink_fit)}, {"shrink_check", num(f.shrink_check)},
            {"rms_over_noise_check", {{"before", f.rms_w_before_check}, {"after", num(f.rms_w_after_check)}}},
            {"rms_check_before", before}, {"rms_check_after", after}, {"converged", f.converged},
            {"evaluations", f.evaluations}, {"autocorrelation_time", f.autocorrelation_time}};
  if (f.offset_channel >= 0) j["offset_channel"] = channel_names()[static_cast<std::size_t>(f.offset_channel)];
  return j;
}

}  // namespace

std::string to_json(const GapResult& r, int indent) {
  json j;
  if (!r.ok) {
    j = {{"error", r.error}};
    return j.dump(indent);
  }
  j["where"] = {{"fit", where_json(r.where_fit)}, {"check", where_json(r.where_check)}};
  j["start"] = {{"fit", r.start_fit}, {"check", r.start_check}};
  j["step_lead"] = {{"fit", r.step_lead_fit}, {"check", r.step_lead_check}};
  json rk = json::array(), rej = json::array(), ni = json::array();
  for (const auto& f : r.ranking) rk.push_back(fit_json(f));
  for (const auto& f : r.rejected) rej.push_back(fit_json(f));
  for (const auto& n : r.not_identifiable) ni.push_back({{"effect", effect_info(n.effect).name}, {"reason", n.reason}});
  j["ranking"] = rk;
  j["rejected"] = rej;
  j["not_identifiable"] = ni;
  json env = json::array();
  for (const auto& sg : r.envelope.segments) {
    json m = json::object(), mo = json::object(), lo = json::object(), hi = json::object();
    for (std::size_t c = 0; c < kChannels; ++c) {
      m[channel_names()[c]] = sg.measured[c];
      mo[channel_names()[c]] = sg.model[c];
      lo[channel_names()[c]] = sg.lo[c];
      hi[channel_names()[c]] = sg.hi[c];
    }
    env.push_back({{"t", {sg.t0, sg.t1}}, {"p_sup", sg.Psupl}, {"kp", sg.kp}, {"measured", m}, {"model", mo},
                   {"shift_min", lo}, {"shift_max", hi}, {"outside", sg.outside},
                   {"worst_channel", sg.worst_channel >= 0 ? json(channel_names()[static_cast<std::size_t>(sg.worst_channel)]) : json(nullptr)}});
  }
  j["envelope"] = {{"out", r.envelope.out}, {"outside", r.envelope.outside}, {"settings", env}, {"text", r.envelope.text}};
  json disc = json::array();
  for (const auto& d : r.discovered) {
    json terms = json::array();
    for (const auto& t : d.terms) {
      terms.push_back({{"form", t.form}, {"unit", t.unit}, {"coefficient", t.coefficient}, {"std_error", num(t.std_error)}});
    }
    disc.push_back({{"equation", d.equation}, {"terms", terms}, {"shrink_check", d.shrink_check},
                    {"shrink_fit", d.shrink_fit}, {"rms_over_noise_check", {{"before", d.rms_w_before_check}, {"after", d.rms_w_after_check}}},
                    {"reading", d.reading}, {"simulated", d.simulated}});
    if (d.simulated) {
      json after = json::object();
      for (std::size_t c = 0; c < kChannels; ++c) {
        if (std::isfinite(d.channel_rms_w_after_check[c])) after[channel_names()[c]] = d.channel_rms_w_after_check[c];
      }
      disc.back()["model_shrink_check"] = d.model_shrink_check;
      disc.back()["rms_over_noise_after_check"] = after;
    }
  }
  j["discovered"] = disc;
  json rem = json::object();
  for (std::size_t c = 0; c < kChannels; ++c) {
    if (std::isfinite(r.remaining_rms_w[c])) rem[channel_names()[c]] = r.remaining_rms_w[c];
  }
  j["remaining_check"] = {{"rms_over_noise", rem}, {"where", r.remaining_where}};
  j["verdict_rule"] = "explained only when every measured channel of the check log is within 2x its noise (RMS) after the top-ranked effect set";
  j["verdict"] = r.verdict;
  if (!r.evidence_missing.empty()) j["evidence_missing"] = r.evidence_missing;
  j["explained_by"] = r.explained_by;
  j["cannot_tell_apart"] = r.cannot_tell_apart;
  j["verdict_text"] = r.verdict_text;
  j["seconds"] = r.seconds;
  json st = json::array();
  for (const auto& [name, sec] : r.stage_seconds) st.push_back({{"stage", name}, {"seconds", sec}});
  j["stage_seconds"] = st;
  j["simulations"] = r.simulations;
  return j.dump(indent);
}

std::string to_text(const GapResult& r) {
  std::ostringstream o;
  if (!r.ok) return "error: " + r.error + "\n";
  auto where = [&](const char* title, const Where& w) {
    o << sfmt("%s: residual (data - nominal model), RMS/noise pooled %.3g%s\n", title, w.rms_w_total,
                  w.significant ? "  [significant gap]" : "  [within noise]");
    o << "  channel      mean        RMS       noise   RMS/noise\n";
    for (std::size_t c = 0; c < kChannels; ++c) {
      const auto& s = w.channels[c];
      if (!s.present) continue;
      o << sfmt("  %-6s %11.4g %10.4g %10.4g %9.3g\n", channel_names()[c], s.mean, s.rms, s.noise,
                    s.rms_w);
    }
    auto parts = [&](const std::vector<PartStats>& v) {
      for (const auto& p : v) {
        o << sfmt("  %-28s %4.0f %%  RMS/noise", p.label.c_str(), 100 * p.fraction);
        for (std::size_t c = 0; c < kChannels; ++c) {
          if (!std::isfinite(p.rms_w[c])) continue;
          o << sfmt("  %s %.3g", channel_names()[c], p.rms_w[c]);
        }
        o << "\n";
      }
    };
    parts(w.load_bins);
    parts(w.phases);
    parts(w.bands);
    o << "  balance equations on the measured signals (imbalance: a loss the model lacks is > 0):\n";
    o << "  equation        unit       mean        RMS  RMS/noise\n";
    for (const auto& e : w.equations) {
      if (!e.available) continue;
      o << sfmt("  %-12s %7s %10.3g %10.3g %10.3g%s\n", e.equation.c_str(), e.unit.c_str(), e.mean, e.rms, e.rms_w,
                w.located >= 0 && &e == &w.equations[static_cast<std::size_t>(w.located)] ? "  <- located" : "");
    }
    if (w.located >= 0) {
      o << "  " << w.equations[static_cast<std::size_t>(w.located)].equation << ": "
        << w.equations[static_cast<std::size_t>(w.located)].dependence << "\n";
    }
  };
  // Out of envelope comes first: nothing below names an effect.
  if (r.envelope.out) o << "OUT OF ENVELOPE - " << r.verdict_text << "\n\n";
  o << "model runs start from the first sample (choose_initial_state): fit log " << r.start_fit << ", check log "
    << r.start_check << "\n";
  o << sfmt("input steps take effect %.2g (fit) / %.2g (check) of a sample interval before the row that shows them\n\n",
            r.step_lead_fit, r.step_lead_check);
  where("fit log", r.where_fit);
  where("check log", r.where_check);
  o << "\nranking (fit on the fit log, judged on the check log; shrink = share of its gap above the noise removed):\n";
  int i = 0;
  for (const auto& f : r.ranking) {
    o << sfmt("  %d. %-40s shrink_check %5.1f %%  dBIC_fit %.4g\n", ++i, f.name.c_str(),
                  100 * f.shrink_check, f.delta_bic_fit);
    for (const auto& p : f.params) {
      o << sfmt("       %s.%s = %.4g +- %.2g %s%s\n", p.effect.c_str(), p.name.c_str(), p.value, p.se,
                    p.unit.c_str(), p.identified ? "" : "  (not identified)");
    }
  }
  for (const auto& n : r.not_identifiable) o << "  not identifiable: " << effect_info(n.effect).name << " - " << n.reason << "\n";
  if (!r.envelope.segments.empty() && !r.envelope.out) o << "\noperating-point envelope: " << r.envelope.text << "\n";
  for (const auto& d : r.discovered) {
    o << "\nbeyond the library (" << d.equation << ", STLSQ fitted on the fit log, judged on the check log):\n";
    for (const auto& t : d.terms) {
      o << sfmt("  %+.4g * %s  (+- %.2g %s)\n", t.coefficient, t.form.c_str(), t.std_error, t.unit.c_str());
    }
    o << sfmt("  %s; shrinks the check-log imbalance by %.0f %% (RMS/noise %.3g -> %.3g)\n", d.reading.c_str(),
              100.0 * d.shrink_check, d.rms_w_before_check, d.rms_w_after_check);
    if (d.simulated) {
      o << sfmt("  the model with it: check-log gap shrinks by %.0f %%; RMS/noise after", 100.0 * d.model_shrink_check);
      for (std::size_t c = 0; c < kChannels; ++c) {
        if (std::isfinite(d.channel_rms_w_after_check[c])) o << sfmt(" %s %.3g", channel_names()[c], d.channel_rms_w_after_check[c]);
      }
      o << "\n";
    }
  }
  o << "\nverdict: " << r.verdict_text << "\n";
  o << sfmt("(%d simulations, %.1f s:", r.simulations, r.seconds);
  for (const auto& [name, sec] : r.stage_seconds) o << sfmt(" %s %.2f", name.c_str(), sec);
  o << ")\n";
  return o.str();
}

namespace {

using sim::gnuplot_quote;

std::string range(const sim::AxisRange& a) { return sfmt("[%.9g:%.9g]", a.lo, a.hi); }

sim::VerdictTone verdict_tone(const std::string& verdict) {
  if (verdict == "no_significant_gap" || verdict == "explained" || verdict == "explained_by_pair") {
    return sim::VerdictTone::kGood;
  }
  if (verdict == "partly_explained") return sim::VerdictTone::kWarning;
  return sim::VerdictTone::kBad;
}

// The per-channel table of one log's residual for the HTML page.
void where_table(sim::HtmlReport& page, const Where& w) {
  std::vector<std::vector<std::string>> rows;
  for (std::size_t c = 0; c < kChannels; ++c) {
    const auto& s = w.channels[c];
    if (!s.present) continue;
    rows.push_back({channel_names()[c], c == 3 ? "rad/s" : "Pa", sfmt("%.4g", s.mean), sfmt("%.4g", s.rms),
                    sfmt("%.4g", s.noise), sfmt("%.3g", s.rms_w)});
  }
  page.table({"channel", "unit", "mean", "RMS", "noise", "RMS/noise"}, rows);
}

// The three figures (gnuplot script, run once). Display units: bar, rpm; kp in 1e-8 SI.
std::string plot_script(const GapResult& r, const std::filesystem::path& dir, const bool present[kChannels]) {
  namespace fs = std::filesystem;
  const char* units[kChannels] = {"bar", "bar", "bar", "rpm"};
  const double scale[kChannels] = {1e-5, 1e-5, 1e-5, 60.0 / (2.0 * M_PI)};
  const double floor[kChannels] = {0.1, 0.1, 0.1, 1.0};  // narrowest y range [display unit]
  const std::string fit = gnuplot_quote((dir / "fit.dat").string());
  const std::string check = gnuplot_quote((dir / "check.dat").string());
  auto column = [&](const std::vector<std::array<double, kChannels>>& v, std::size_t c) {
    std::vector<double> out;
    out.reserve(v.size());
    for (const auto& x : v) out.push_back(x[c] * scale[c]);
    return out;
  };
  auto difference = [](std::vector<double> a, const std::vector<double>& b) {
    for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) a[k] -= b[k];
    return a;
  };
  auto append = [](std::vector<double> a, const std::vector<double>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  std::vector<double> kp;
  for (double v : r.kp_fit) kp.push_back(v * 1e8);
  for (double v : r.kp_check) kp.push_back(v * 1e8);
  const sim::AxisRange kp_range = sim::readable_range(kp, 0.1);
  double kp_max = 0.0;
  for (double v : kp) kp_max = std::max(kp_max, v);
  const std::string kp_label = "kp [1e-8 m^3/(s Pa^0.5)]";
  // A panel for a channel the logs do not have: says so instead of drawing nothing or zeros.
  auto absent = [&](std::size_t c) {
    return sfmt("unset border\nunset tics\nunset grid\nunset xlabel\nunset ylabel\nset label 1 '%s is not in the logs' at graph 0.5,0.5 center\n"
                "set xrange [0:1]\nset yrange [0:1]\nplot NaN notitle\nunset label 1\nset border\nset tics\nset grid\n",
                channel_names()[c]);
  };

  std::ostringstream gp;
  gp << "set terminal pngcairo size 1200,900 noenhanced font 'sans,10'\nset grid\nset datafile missing 'nan'\n";
  // 1. residual over time (fit log), load regime (kp) shaded on the second axis.
  gp << "set output " << gnuplot_quote((dir / "residual_time.png").string()) << "\n";
  gp << "set multiplot layout 4,1 title 'Residual over time, fit log (data - nominal model)' margins 0.08,0.92,0.06,0.9 spacing 0,0.05\n";
  gp << "set y2tics\nset y2label " << gnuplot_quote(kp_label) << "\nset y2range [0:" << sfmt("%.9g", kp_max > 0 ? 1.1 * kp_max : 1.0) << "]\n";
  const sim::AxisRange t_fit = r.t_fit.size() > 1 && r.t_fit.back() > r.t_fit.front()
                                   ? sim::AxisRange{r.t_fit.front(), r.t_fit.back()} : sim::readable_range(r.t_fit, 1.0);
  for (std::size_t c = 0; c < kChannels; ++c) {
    gp << (c + 1 == kChannels ? "set xlabel 't [s]'\n" : "unset xlabel\n");
    if (!present[c]) {
      gp << "unset y2tics\nunset y2label\n" << absent(c) << "set y2tics\nset y2label " << gnuplot_quote(kp_label) << "\n";
      continue;
    }
    gp << "set xrange " << range(t_fit) << "\n";
    const auto res = difference(column(r.data_fit, c), column(r.nominal_fit, c));
    gp << "set ylabel '" << channel_names()[c] << " [" << units[c] << "]'\nset yrange " << range(sim::readable_range(res, floor[c])) << "\n";
    if (c == 0) gp << "set key at screen 0.92,0.975 right top horizontal maxrows 1\n";
    gp << "plot " << fit << " u 1:($2*1e8) axes x1y2 w filledcurves x1 lc rgb '#e0e0f0' " << (c == 0 ? "t 'kp (load regime, right axis)'" : "notitle")
       << ", '' u 1:($" << 3 + c << "-$" << 7 + c << ") w l lc rgb 'red' " << (c == 0 ? "t 'residual (fit log)'" : "notitle") << "\n";
    if (c == 0) gp << "unset key\n";
  }
  gp << "unset multiplot\nunset y2tics\nunset y2label\nset y2range [*:*]\n";
  // 2. residual vs load.
  gp << "set output " << gnuplot_quote((dir / "residual_vs_load.png").string()) << "\n";
  gp << "set multiplot layout 2,2 title 'Residual vs load (data - nominal model)' margins 0.08,0.98,0.07,0.9 spacing 0.08,0.1\n";
  for (std::size_t c = 0; c < kChannels; ++c) {
    if (!present[c]) {
      gp << "unset xlabel\nunset ylabel\n" << absent(c);
      continue;
    }
    const auto res = append(difference(column(r.data_fit, c), column(r.nominal_fit, c)),
                            difference(column(r.data_check, c), column(r.nominal_check, c)));
    gp << "set xlabel " << gnuplot_quote(kp_label) << "\nset xrange " << range(kp_range) << "\n";
    gp << "set ylabel 'residual " << channel_names()[c] << " [" << units[c] << "]'\nset yrange "
       << range(sim::readable_range(res, floor[c])) << "\n";
    if (c == 0) gp << "set key at screen 0.98,0.975 right top horizontal maxrows 1\n";
    gp << "plot " << fit << " u ($2*1e8):($" << 3 + c << "-$" << 7 + c << ") w p pt 7 ps 0.3 " << (c == 0 ? "t 'fit log'" : "notitle")
       << ", " << check << " u ($2*1e8):($" << 3 + c << "-$" << 7 + c << ") w p pt 7 ps 0.3 " << (c == 0 ? "t 'check log'" : "notitle") << "\n";
    if (c == 0) gp << "unset key\n";
  }
  gp << "unset multiplot\n";
  // 3. before/after on the check log for the top-ranked effect.
  // Without a ranked effect there is no "after": data and nominal model only.
  const bool ranked = !r.ranking.empty();
  const std::string best = ranked ? r.ranking.front().name : std::string();
  gp << "set output " << gnuplot_quote((dir / "before_after.png").string()) << "\n";
  gp << "set multiplot layout 4,1 title "
     << gnuplot_quote(ranked ? "Check log: data, nominal model and the model with " + best
                             : std::string("Check log: data and nominal model (no effect ranked)"))
     << " margins 0.08,0.98,0.06,0.9 spacing 0,0.05\n";
  const sim::AxisRange t_check = r.t_check.size() > 1 && r.t_check.back() > r.t_check.front()
                                     ? sim::AxisRange{r.t_check.front(), r.t_check.back()} : sim::readable_range(r.t_check, 1.0);
  for (std::size_t c = 0; c < kChannels; ++c) {
    gp << (c + 1 == kChannels ? "set xlabel 't [s]'\n" : "unset xlabel\n");
    if (!present[c]) {
      gp << absent(c);
      continue;
    }
    const auto all = append(append(column(r.data_check, c), column(r.nominal_check, c)),
                            ranked ? column(r.best_check, c) : std::vector<double>());
    double level = 0.0;
    for (double v : all) {
      if (std::isfinite(v)) level = std::max(level, std::fabs(v));
    }
    gp << "set xrange " << range(t_check) << "\nset ylabel '" << channel_names()[c] << " [" << units[c] << "]'\nset yrange "
       << range(sim::readable_range(all, std::max(floor[c], 0.02 * level))) << "\n";
    if (c == 0) gp << "set key at screen 0.98,0.975 right top horizontal maxrows 1\n";
    gp << "plot " << check << " u 1:" << 3 + c << " w l lc rgb 'gray' " << (c == 0 ? "t 'data'" : "notitle") << ", '' u 1:"
       << 7 + c << " w l lc rgb 'red' " << (c == 0 ? "t 'nominal model'" : "notitle");
    if (ranked) gp << ", '' u 1:" << 11 + c << " w l lc rgb 'blue' " << (c == 0 ? "t " + gnuplot_quote(best) : std::string("notitle"));
    gp << "\n";
    if (c == 0) gp << "unset key\n";
  }
  gp << "unset multiplot\n";
  return gp.str();
}

}  // namespace

std::string write_report(const GapResult& r, const std::string& dir, const std::string& fit_name,
                         const std::string& check_name, std::string* plot_warning) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return "cannot create " + dir + ": " + ec.message();
  if (!r.ok) return r.error;
  const double scale[kChannels] = {1e-5, 1e-5, 1e-5, 60.0 / (2.0 * M_PI)};
  // Data file: t kp data[4] nominal[4] best[4] for the check log; t kp data nominal for the fit log.
  {
    std::ofstream f(fs::path(dir) / "check.dat");
    for (std::size_t k = 0; k < r.t_check.size(); ++k) {
      f << r.t_check[k] << ' ' << r.kp_check[k];
      for (const auto* s : {&r.data_check, &r.nominal_check, &r.best_check}) {
        for (int c = 0; c < kChannels; ++c) f << ' ' << (*s)[k][static_cast<std::size_t>(c)] * scale[c];
      }
      f << '\n';
    }
    std::ofstream g(fs::path(dir) / "fit.dat");
    for (std::size_t k = 0; k < r.t_fit.size(); ++k) {
      g << r.t_fit[k] << ' ' << r.kp_fit[k];
      for (const auto* s : {&r.data_fit, &r.nominal_fit}) {
        for (int c = 0; c < kChannels; ++c) g << ' ' << (*s)[k][static_cast<std::size_t>(c)] * scale[c];
      }
      g << '\n';
    }
  }
  bool present[kChannels];
  for (std::size_t c = 0; c < kChannels; ++c) present[c] = r.where_fit.channels[c].present && r.where_check.channels[c].present;
  // File names relative to the folder: plots.gp reruns from inside it (cd DIR && gnuplot
  // plots.gp); gnuplot changes into it first here, as a user would.
  const std::string script = plot_script(r, fs::path(), present);
  {
    std::ofstream f(fs::path(dir) / "plots.gp");  // kept, so the plots can be restyled by hand
    f << script;
  }
  const std::string plot_error = sim::run_gnuplot("cd " + gnuplot_quote(fs::path(dir).string()) + "\n" + script);
  struct Figure {
    const char* file;
    const char* title;
  };
  const Figure figures[3] = {{"residual_time.png", "Where: residual over time (fit log; shaded: kp)"},
                             {"residual_vs_load.png", "Residual vs load"},
                             {"before_after.png", "Before / after on the check log (top-ranked effect)"}};
  const std::string text = to_text(r);
  std::ofstream md(fs::path(dir) / "report.md");
  md << "# hstmon gap report\n\nFit log: `" << fit_name << "`; check log: `" << check_name << "`.\n\n";
  md << "**Verdict:** " << r.verdict_text << "\n\n## Summary\n\n```\n" << text << "```\n\n";
  if (plot_error.empty()) {
    for (const auto& f : figures) md << "## " << f.title << "\n\n![](" << f.file << ")\n\n";
  } else {
    md << "(no plots: " << plot_error << "; data in fit.dat / check.dat, script plots.gp)\n";
  }

  sim::HtmlReport page("hstmon gap report");
  page.verdict(r.verdict_text, verdict_tone(r.verdict));
  page.paragraph("Fit log: " + fit_name + "; check log: " + check_name + ".");
  page.heading("Residual of the nominal model, check log (SI units)");
  where_table(page, r.where_check);
  page.heading("Residual of the nominal model, fit log (SI units)");
  where_table(page, r.where_fit);
  if (!r.ranking.empty()) {
    page.heading("Ranking (fitted on the fit log, judged on the check log)");
    std::vector<std::vector<std::string>> rows;
    int i = 0;
    for (const auto& f : r.ranking) {
      std::string params;
      for (const auto& p : f.params) {
        params += sfmt("%s%s.%s = %.4g ± %.2g %s%s", params.empty() ? "" : "; ", p.effect.c_str(), p.name.c_str(), p.value,
                       p.se, p.unit.c_str(), p.identified ? "" : " (not identified)");
      }
      rows.push_back({sfmt("%d. %s", ++i, f.name.c_str()), sfmt("%.1f %%", 100 * f.shrink_check), sfmt("%.4g", f.delta_bic_fit), params});
    }
    page.table({"effect", "shrink (check log)", "ΔBIC (fit log)", "parameters"}, rows);
  }
  for (const auto& f : figures) {
    page.heading(f.title);
    if (plot_error.empty()) {
      page.image((fs::path(dir) / f.file).string(), f.title);
    } else {
      page.paragraph("no plot: " + plot_error);
    }
  }
  page.heading("Full text report");
  page.preformatted(text);
  if (plot_warning != nullptr) *plot_warning = plot_error;
  return page.write((fs::path(dir) / "report.html").string());
}

}  // namespace hstmon::gap
