#pragma once
/// @file signature_table.hpp
/// The constexpr fault-signature table for the firmware matcher
/// (lib/include/hstmon/generated/thesis_signatures.hpp): one row per parameter fault of
/// the catalogue (both directions where physical) plus one per sensor. Magnitude: the
/// nonlinear steady-state sign at the nominal point (what the matcher sees). Slope and
/// order: the qualitative TCG of Fig. 2.3. Direction: the noise-scaled steady-state
/// residual of a small fault, as a unit vector.

#include <string>
#include <vector>

#include "hstmon/fault_signature.hpp"

namespace hstmon::fdi {

/// Options of the table generator.
struct SignatureOptions {
  double sigma_pressure = 0.05e5;  ///< noise level of each pressure channel [Pa] (0.05 bar)
  double sigma_speed_rpm = 0.5;    ///< noise level of the speed channel [rpm]
  double direction_step = 0.05;    ///< relative fault size for the direction vector [-]
  int max_order = 4;               ///< highest derivative order the TCG looks at [-]
};

/// One generated row, with the reason for anything unusual.
struct SignatureRow {
  FaultSignature sig;  ///< sig.name points into `name`; refresh with sig.name = name.c_str() after copying
  std::string name;
  std::string note;  ///< where the TCG and the nonlinear model disagree, or empty
};

/// Builds the rows (parameter faults in catalogue order, then the four sensor faults).
std::vector<SignatureRow> build_signature_rows(const SignatureOptions& opt = SignatureOptions{});

/// The header text: deterministic for given rows and options.
std::string render_signature_header(const std::vector<SignatureRow>& rows, const SignatureOptions& opt);

/// Path of the committed header relative to the source root.
inline constexpr const char* kSignatureHeaderPath = "lib/include/hstmon/generated/thesis_signatures.hpp";

}  // namespace hstmon::fdi
