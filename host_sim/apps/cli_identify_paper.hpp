#pragma once
// `hstmon identify --paper TABLE` and `--studies` (cli_identify_paper.cpp).
#include <nlohmann/json.hpp>

#include "cli_identify_report.hpp"
#include "hstmon_circuit/circuit_load.hpp"

namespace hstmon::cli::identify {

/// The paper rig's table (a.paper, a.cd, a.rho): pump B's flow–pressure curve and the DCV
/// and PRV port areas, into rep and js["paper"]; with a circuit beside its compensated pump
/// and its orifices named dcv/prv.
/// @param circuit  the circuit to compare with, or nullptr
/// @param worst    out: the largest |difference| of a pump-curve parameter from the circuit's [%]
/// @return kExitOk, or kExitBadInput after printing the table's error
int run_paper(const IdentifyArgs& a, const circuit_tools::LoadedCircuit* circuit, Report& rep, nlohmann::json& js,
              double& worst);

/// The paper's parameter studies (Figs. 7–9, Table I model, from rest) into rep (tables,
/// plots) and js["studies"].
void run_studies(Report& rep, nlohmann::json& js);

}  // namespace hstmon::cli::identify
