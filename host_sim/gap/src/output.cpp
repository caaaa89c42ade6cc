/// @file output.cpp
/// JSON, text and Markdown/gnuplot report of a GapResult.
#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hstmon_gap/gap.hpp"

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
                              {"noise", s.noise}, {"rms_over_noise", s.rms_w}};
  }
  json j = {{"significant", w.significant}, {"rms_over_noise", w.rms_w_total}, {"sample_period", w.sample_period},
            {"channels", ch}};
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
  o << "\nranking (fit on the fit log, shrink = 1 - RMS_after/RMS_before on the check log, noise-weighted):\n";
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

std::string write_report(const GapResult& r, const std::string& dir, const std::string& fit_name,
                         const std::string& check_name) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) return "cannot create " + dir + ": " + ec.message();
  if (!r.ok) return r.error;
  const char* units[kChannels] = {"bar", "bar", "bar", "rpm"};
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
  std::ostringstream gp;
  gp << "set terminal pngcairo size 1200,900 noenhanced\nset grid\n";
  // 1. residual over time (fit log), transient/regime shading via kp on a second axis.
  gp << "set output '" << (fs::path(dir) / "residual_time.png").string() << "'\nset multiplot layout 4,1\n";
  for (int c = 0; c < kChannels; ++c) {
    gp << "set ylabel '" << channel_names()[static_cast<std::size_t>(c)] << " [" << units[c] << "]'\nset y2tics\n"
       << "set y2label 'kp'\nplot '" << (fs::path(dir) / "fit.dat").string() << "' u 1:2 axes x1y2 w filledcurves x1 lc rgb '#e0e0f0' t 'kp (load regime)', '' u 1:($"
       << 3 + c << "-$" << 7 + c << ") w l lc rgb 'red' t 'residual (fit log)'\n";
  }
  gp << "unset multiplot\nunset y2tics\nunset y2label\n";
  // 2. residual vs load.
  gp << "set output '" << (fs::path(dir) / "residual_vs_load.png").string() << "'\nset multiplot layout 2,2\n";
  for (int c = 0; c < kChannels; ++c) {
    gp << "set xlabel 'kp'\nset ylabel 'residual " << channel_names()[static_cast<std::size_t>(c)] << " [" << units[c]
       << "]'\nplot '" << (fs::path(dir) / "fit.dat").string() << "' u 2:($" << 3 + c << "-$" << 7 + c
       << ") w p pt 7 ps 0.3 t 'fit log', '" << (fs::path(dir) / "check.dat").string() << "' u 2:($" << 3 + c << "-$"
       << 7 + c << ") w p pt 7 ps 0.3 t 'check log'\n";
  }
  gp << "unset multiplot\nunset xlabel\n";
  // 3. before/after on the check log for the top-ranked effect.
  gp << "set output '" << (fs::path(dir) / "before_after.png").string() << "'\nset multiplot layout 4,1\n";
  for (int c = 0; c < kChannels; ++c) {
    gp << "set ylabel '" << channel_names()[static_cast<std::size_t>(c)] << " [" << units[c] << "]'\nplot '"
       << (fs::path(dir) / "check.dat").string() << "' u 1:" << 3 + c << " w l lc rgb 'gray' t 'data', '' u 1:"
       << 7 + c << " w l lc rgb 'red' t 'nominal model', '' u 1:" << 11 + c << " w l lc rgb 'blue' t '"
       << (r.ranking.empty() ? std::string("nominal") : r.ranking.front().name) << "'\n";
  }
  gp << "unset multiplot\n";
  {
    std::ofstream f(fs::path(dir) / "plots.gp");
    f << gp.str();
  }
  const std::string cmd = "gnuplot '" + (fs::path(dir) / "plots.gp").string() + "' 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  std::ofstream md(fs::path(dir) / "report.md");
  md << "# hstmon gap report\n\nFit log: `" << fit_name << "`; check log: `" << check_name << "`.\n\n";
  md << "**Verdict:** " << r.verdict_text << "\n\n## Summary\n\n```\n" << to_text(r) << "```\n\n";
  if (rc == 0) {
    md << "## Where: residual over time (fit log; shaded: kp)\n\n![](residual_time.png)\n\n"
       << "## Residual vs load\n\n![](residual_vs_load.png)\n\n"
       << "## Before / after on the check log (top-ranked effect)\n\n![](before_after.png)\n";
  } else {
    md << "(gnuplot not available: no plots; data in fit.dat / check.dat, script plots.gp)\n";
  }
  return {};
}

}  // namespace hstmon::gap
