#pragma once
/// @file envelope.hpp
/// Is the machine the model's kind of machine at all? At each steady input setting of a
/// log, the measured operating point (mean over the setting's second half) is compared
/// with the nominal model's, and with how far parameter uncertainty and every library
/// effect together could move the model: ±5 % on Dm, Dp, kf, Rf + Rbl and on the logged kp
/// and Psupl, and each effect at the largest size a working rig plausibly shows (docs/gap.md),
/// their steady shifts summed per channel and sign (worst case, as an LFT bound). Outside
/// that envelope no effect of the library can be the explanation.
#include <array>
#include <string>
#include <vector>

#include "hstmon_gap/effects.hpp"

namespace hstmon::gap {

/// One steady setting.
struct EnvelopeSegment {
  double t0 = 0, t1 = 0;                      ///< rows averaged [s]
  double Psupl = 0, kp = 0;
  std::array<double, kChannels> measured{}, model{};  ///< means (SI)
  std::array<double, kChannels> lo{}, hi{};           ///< envelope of model − nominal shifts (SI)
  std::array<double, kChannels> margin{};             ///< noise and rounding allowance (SI)
  bool outside = false;                       ///< two channels outside, or one beyond a sensor's plausible offset
  int worst_channel = -1;                     ///< channel furthest outside (in envelope widths)
  double excess = 0;                          ///< its distance outside / (envelope width + margin)
};

/// The envelope test over one or more logs.
struct Envelope {
  bool out = false;                           ///< most steady settings lie outside
  std::vector<EnvelopeSegment> segments;
  int outside = 0;
  std::string text;                           ///< one sentence on the worst setting
};

/// Steady settings of one log and where the measurements lie; `model_y` is the nominal
/// model's open-loop output at the log's rows, `thesis` the implementation it ran on.
void add_envelope_segments(Envelope& env, const ExtendedModel& nominal, const InputSeries& u,
                           const std::vector<std::array<double, kChannels>>& y,
                           const std::vector<std::array<double, kChannels>>& model_y,
                           const std::array<bool, kChannels>& present, const std::array<double, kChannels>& noise,
                           double settle, ThesisImpl thesis = ThesisImpl::kSpecialised);

/// Decides env.out from the segments (at least half outside) and writes env.text.
void finish_envelope(Envelope& env);

}  // namespace hstmon::gap
