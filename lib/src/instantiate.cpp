// Instantiates every core template in float and double under the firmware flags
// (-fno-exceptions -fno-rtti, strict warnings), so type errors in either precision
// surface in every build, not only in the configuration a test happens to use.
#include "hstmon/hstmon.hpp"

namespace hstmon {
template class ThesisReducedModel<float>;
template class ThesisReducedModel<double>;
template class PaperModel<float>;
template class PaperModel<double>;
template class PumpCurve<float>;
template class PumpCurve<double>;
template class Observer<ThesisReducedModel<float>>;
template class Observer<ThesisReducedModel<double>>;
template class Observer<PaperModel<float>>;
template class Observer<PaperModel<double>>;
template ThesisState<float> thesis_derivative(const ThesisParams<float>&, const ThesisInputs<float>&,
                                              const ThesisState<float>&) noexcept;
template ThesisState<double> thesis_derivative(const ThesisParams<double>&, const ThesisInputs<double>&,
                                               const ThesisState<double>&) noexcept;
template class TwoSidedCusum<float>;
template class TwoSidedCusum<double>;
template class ResidualEvaluator<float>;
template class ResidualEvaluator<double>;
template class SensorCheck<float>;
template class SensorCheck<double>;
template class FaultMatcher<float>;
template class FaultMatcher<double>;
template class ModelMonitor<ThesisReducedModel<float>>;  // the firmware C API's monitor
template class ModelMonitor<ThesisReducedModel<double>>;
template Status thesis_model_bound(const ThesisReducedModel<float>&, const ThesisUncertainty<float>&,
                                   float (&)[kFdiChannels]) noexcept;
template Status thesis_model_bound(const ThesisReducedModel<double>&, const ThesisUncertainty<double>&,
                                   double (&)[kFdiChannels]) noexcept;
}  // namespace hstmon
