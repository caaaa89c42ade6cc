/// @file thesis_forward.cpp
#include "hstmon_fdi/thesis_forward.hpp"

#include <iterator>
#include <stdexcept>
#include <string>

#include "hstmon_fdi/thesis_tcg.hpp"

namespace hstmon::fdi {

namespace {

/// The thesis's four measurement nodes as a ForwardResult.
ForwardResult thesis_channels(const std::vector<ChannelPrediction>& v) {
  ForwardResult r;
  for (std::size_t c = 0; c < 4; ++c) r.channel[c] = v[c];
  return r;
}

std::vector<std::string> thesis_measurements() { return {std::begin(kMeasurementNodes), std::end(kMeasurementNodes)}; }

}  // namespace

ForwardResult forward_qualitative(const CausalGraph& g, const std::vector<ParamStep>& fault, int max_order) {
  return thesis_channels(forward_qualitative_at(g, fault, max_order, thesis_measurements()));
}

ForwardResult forward_weighted(const CausalGraph& g, const std::vector<ParamStep>& fault, int max_order) {
  return thesis_channels(forward_weighted_at(g, fault, max_order, thesis_measurements()));
}

std::array<double, 4> linear_steady_change(const CausalGraph& g, const std::vector<ParamStep>& fault) {
  if (integrated_nodes(g).size() != 4) {
    throw std::invalid_argument("linear_steady_change: the graph must have exactly 4 integrated nodes");
  }
  const std::vector<double> v = linear_steady_change_at(g, fault, thesis_measurements());
  return {v[0], v[1], v[2], v[3]};
}

}  // namespace hstmon::fdi
