#pragma once
/// @file identified_outputs.hpp
/// What `hstmon identify` writes from a thesis fit: the JSON parameter file that
/// `hstmon replay --params` reads (hstmon::host::write_params_file), and a generated C++
/// header for firmware builds with the values as constexpr hstmon::ThesisParams<float> and
/// <double>, the per-setting kp, and a "generated, do not edit" banner.

#include <optional>
#include <string>

#include "hstmon/thesis_params.hpp"
#include "hstmon_ident/thesis_fit.hpp"

namespace hstmon::ident {

/// Inputs to store with the parameters: Psupl, Ps, Pbp of the first operating point and the
/// kp of the setting with the most samples (a replay of a log without a kp column uses it).
ThesisInputs<double> identified_inputs(const ThesisFitResult& fit);

/// One-line provenance: source logs, s², which parameters were held at the prior.
std::string identified_description(const ThesisFitResult& fit);

/// Text of the generated header (namespace hstmon::identified): templates
/// `thesis_params<T>()`, `thesis_inputs<T>()`, constants kThesisParamsF / kThesisParamsD,
/// and kKpPerSetting[] with the setting labels as comments.
std::string format_params_header(const ThesisFitResult& fit);

/// Writes the parameter file (JSON). @return error text, or nullopt on success
std::optional<std::string> write_identified_params(const std::string& path, const ThesisFitResult& fit);

/// Writes the generated header. @return error text, or nullopt on success
std::optional<std::string> write_params_header(const std::string& path, const ThesisFitResult& fit);

}  // namespace hstmon::ident
