// Driver for scripts/count_stiff_ticks.sh: the observer on the circuit interpreter
// (Observer<HostCircuitModel>, the host replay's model) at a circuit's steady state, N ticks
// between CALLGRIND_START_INSTRUMENTATION and CALLGRIND_STOP_INSTRUMENTATION.
//
//   hstmon_count_stiff_ticks <circuit.json> <params.json> <steady|step|rk4|rk4_one> [ticks] [step_input]
//     steady  N ticks at the parameter file's inputs (the usual tick)
//     step    N ticks right after input `step_input` (default the last input) rises by
//             half: the work after an input change
//     rk4     as steady, with RK4 substeps on stiff ticks (Config::implicit_above = 0)
//     rk4_one as steady, with exactly one RK4 substep per tick (max_substeps = 1; health
//             then says substeps_clipped wherever the ρ bound asked for more): the cost of
//             a tick on a circuit that needs no more, such as closed_loop_hst_soft
//
// Prints the ticks, the implicit ticks and the steps they took, so the count can be read
// as instructions per tick. Exit 2 on bad usage or a file that does not load.

#include <valgrind/callgrind.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "hstmon/circuit/engine.hpp"
#include "hstmon/observer.hpp"
#include "hstmon_host/circuit_file.hpp"
#include "hstmon_host/circuit_values.hpp"

namespace {

using Model = hstmon::host::HostCircuitModel;
using Obs = hstmon::Observer<Model>;

// One out-of-line call per tick, as in count_ticks.cpp.
__attribute__((noinline)) void tick(Obs& o, const Model::Inputs& u, const Obs::Measurement& m) { o.step(u, m); }

}  // namespace

int main(int argc, char** argv) {
  const bool known = argc >= 4 && (std::strcmp(argv[3], "steady") == 0 || std::strcmp(argv[3], "step") == 0 ||
                                   std::strcmp(argv[3], "rk4") == 0 || std::strcmp(argv[3], "rk4_one") == 0);
  if (argc < 4 || argc > 6 || !known) {
    std::fprintf(stderr, "usage: %s <circuit.json> <params.json> <steady|step|rk4|rk4_one> [ticks] [step_input]\n", argv[0]);
    return 2;
  }
  const long n = argc >= 5 ? std::strtol(argv[4], nullptr, 10) : 10000;
  const bool step = std::strcmp(argv[3], "step") == 0;
  auto file = hstmon::host::read_circuit_file(argv[1]);
  if (!file.ok()) {
    std::fprintf(stderr, "%s\n", file.error->to_string().c_str());
    return 2;
  }
  auto values = hstmon::host::read_circuit_values(argv[2], *file.file);
  if (!values.ok()) {
    std::fprintf(stderr, "%s\n", values.error->to_string().c_str());
    return 2;
  }
  hstmon::host::CircuitFile& f = *file.file;
  const Model::Params& p = values.values->params;
  Model::Inputs u = values.values->inputs;
  const double tick_s = 1e-3;
  f.circuit.stiff_mask = hstmon::circuit::auto_stiff_mask<double>(f.circuit, p, u, tick_s);
  Obs o;
  Obs::Config cfg;
  cfg.tick = tick_s;
  if (std::strncmp(argv[3], "rk4", 3) == 0) cfg.implicit_above = 0;
  if (std::strcmp(argv[3], "rk4_one") == 0) cfg.max_substeps = 1;
  if (n <= 0 || o.configure(Model(f.circuit, p, u), cfg) != hstmon::Status::kOk ||
      o.reset_steady(u) != hstmon::Status::kOk) {
    std::fprintf(stderr, "no steady state, or ticks not positive\n");
    return 2;
  }
  Obs::Measurement m;
  m.y = o.model().outputs(o.state());
  m.valid = static_cast<std::uint8_t>((1u << o.model().n_outputs()) - 1u);
  for (int k = 0; k < 200; ++k) tick(o, u, m);  // settle onto the discrete fixed point
  if (step) {
    const int i = argc == 6 ? f.input_index(argv[5]) : static_cast<int>(f.inputs.size()) - 1;
    if (i < 0) {
      std::fprintf(stderr, "no input %s\n", argc == 6 ? argv[5] : "");
      return 2;
    }
    u.v[i] *= 1.5;
  }
  const std::uint64_t implicit_before = o.implicit_ticks();
  long steps = 0;
  int max_steps = 0;
  CALLGRIND_START_INSTRUMENTATION;
  for (long k = 0; k < n; ++k) {
    tick(o, u, m);
    steps += o.substeps();
    if (o.substeps() > max_steps) max_steps = o.substeps();
  }
  CALLGRIND_STOP_INSTRUMENTATION;
  std::printf("ticks %ld implicit %llu steps %ld max %d health %u\n", n,
              static_cast<unsigned long long>(o.implicit_ticks() - implicit_before), steps, max_steps, o.health());
  return 0;
}
