// A firmware team's host program against hstmon::core: the thesis observer started at the
// steady state of Table 2.2, fed its own estimate for one second, must stay there with zero
// residuals. Exit status 0 = the package works.
#include <cmath>
#include <cstdio>

#include "hstmon/hstmon.hpp"

int main() {
  using Model = hstmon::ThesisReducedModel<double>;
  hstmon::Observer<Model> obs;
  hstmon::Observer<Model>::Config cfg;
  cfg.tick = 1e-3;
  const hstmon::ThesisInputs<double> u;  // Table 2.2's operating point
  if (obs.configure(Model{}, cfg) != hstmon::Status::kOk || obs.reset_steady(u) != hstmon::Status::kOk) {
    std::puts("consumer: configure/reset_steady failed");
    return 1;
  }
  const auto y0 = obs.estimate();
  hstmon::Observer<Model>::Measurement m;
  m.valid = 0x0F;
  double worst = 0.0;
  for (int k = 0; k < 1000; ++k) {
    m.y = obs.estimate();
    if (obs.step(u, m) != 0) {
      std::puts("consumer: unhealthy tick");
      return 1;
    }
    for (int i = 0; i < 4; ++i) worst = std::fmax(worst, std::fabs(obs.residual()[i]));
  }
  std::printf("consumer: steady Ppp %.6g Pa, wm %.6g rad/s; %llu ticks, max |residual| %.3g\n", y0[2], y0[3],
              static_cast<unsigned long long>(obs.ticks()), worst);
  return (y0[2] > 0.0 && y0[3] > 0.0 && worst == 0.0) ? 0 : 1;
}
